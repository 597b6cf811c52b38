// Reference: the sphere (see assignments/02-sphere/stage_02.hh).
#include <cmath>
#include <ostream>

#include "stage_02.hh"

namespace vl::stage02 {

namespace {

class sphere final : public primitive {
public:
    sphere(const point& center, double radius) : center_(center), radius_(radius) {}

    std::string type_name() const override { return "SPHERE"; }
    vector normal(const point& p) const override { return (p - center_).unit(); }
    bool contains(const point& p) const override { return (p - center_).length() < radius_; }
    point min_point() const override { return center_ - vector(radius_, radius_, radius_); }
    point max_point() const override { return center_ + vector(radius_, radius_, radius_); }

    void read(scene_reader& in) override {
        read_with_surface(in, {{"center", [&] { center_ = in.read_point("center of SPHERE"); }},
                               {"radius", [&] { radius_ = in.read_positive("radius of SPHERE"); }}});
    }
    void write(std::ostream& s) const override {
        s << "SPHERE { center " << center_ << " radius " << radius_;
        write_surface(s);
        s << " }";
    }

private:
    // Robust ray-sphere intersection (Haines, Guenther and Akenine-Moeller, "Precision
    // Improvements for Ray/Sphere Intersection", Ray Tracing Gems ch. 7): the discriminant
    // from the squared distance of the centre to the line, which does not cancel
    // catastrophically for a small sphere far away, and the roots from
    // q = -(b + sign(b) sqrt(disc)), which avoids subtracting nearly equal numbers.
    intersection find_intersection(const ray& r) const override {
        const vector f = r.origin() - center_;
        const vector d = r.direction();  // unit, so a = 1
        const double b = f * d;          // half of the usual b
        const vector l = f - b * d;      // from the centre to the nearest point of the line
        const double disc = radius_ * radius_ - l * l;
        if (disc < 0) return intersection::none();
        const double c = f * f - radius_ * radius_;
        const double q = -(b + std::copysign(std::sqrt(disc), b));
        double t0 = c / q, t1 = q;
        if (t0 > t1) std::swap(t0, t1);
        const double eps = std::fabs(zero_t());
        if (t0 > eps) return intersection::at(t0, this);
        if (t1 > eps) return intersection::at(t1, this);
        return intersection::none();
    }

    point center_;
    double radius_;
};

}  // namespace

std::unique_ptr<primitive> make_sphere(const point& center, double radius) {
    return std::make_unique<sphere>(center, radius);
}

void register_stage_02(registry& r) {
    r.add("SPHERE", [] { return make_sphere(point(0, 0, 0), 1); });
}

}  // namespace vl::stage02
