// The sphere. The ray's distance from the centre is |f x d| (f from the centre to the
// origin): no difference of two large, nearly equal squares, so a small sphere far away
// keeps its digits. The root that does not cancel comes first, the other from c / it.
#include <cmath>
#include <ostream>

#include "stage_02.hh"
#include "text.hh"

namespace vl::stage02 {

namespace {

bool finite(const point& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

class sphere final : public primitive {
public:
    sphere(const point& center, double radius) : center_(center), radius_(radius) {}

    std::string type_name() const override { return "SPHERE"; }

    vector normal(const point& p) const override { return (p - center_).unit(); }
    bool contains(const point& p) const override { return (p - center_).length() < radius_; }
    point min_point() const override { return {center_.x - radius_, center_.y - radius_, center_.z - radius_}; }
    point max_point() const override { return {center_.x + radius_, center_.y + radius_, center_.z + radius_}; }

    void read(scene_reader& in) override {
        point center = center_;
        double radius = radius_;
        read_with_surface(in, {{"center", [&] {
                                    const source_location where = in.peek().where;
                                    center = in.read_point("center of SPHERE").homogenized();
                                    if (!finite(center)) in.fail(where, "center of SPHERE must be a finite point (w not 0)");
                                }},
                               {"radius", [&] { radius = in.read_positive("radius of SPHERE"); }}});
        center_ = center;
        radius_ = radius;
    }
    void write(std::ostream& s) const override {
        s << "SPHERE { center " << number{center_.x} << ' ' << number{center_.y} << ' ' << number{center_.z}
          << " radius " << number{radius_};
        write_surface(s);
        s << " }";
    }

private:
    intersection find_intersection(const ray& r) const override {
        const vector f = r.origin() - center_, d = r.direction();
        const vector cross = f % d;
        const double distance2 = cross * cross;  // squared distance of the ray's line from the centre
        const double rr = radius_ * radius_;
        if (distance2 > rr) return intersection::none();
        const double h = std::sqrt(rr - distance2);
        const double b = f * d;
        const double c = f * f - rr;
        const double q = b > 0 ? -b - h : -b + h;  // the root of larger magnitude
        if (q == 0) return intersection::none();
        const double other = c / q;
        const double first = q < other ? q : other, second = q < other ? other : q;
        const double eps = std::fabs(zero_t());
        if (first > eps) return intersection::at(first, this);
        if (second > eps) return intersection::at(second, this);
        return intersection::none();
    }

    point center_;
    double radius_;
};

}  // namespace

std::unique_ptr<primitive> make_sphere(const point& center, double radius) {
    const point c = center.homogenized();
    if (!finite(c) || !std::isfinite(radius) || !(radius > 0))
        throw usage_error("make_sphere: the center must be finite and the radius a finite number > 0");
    return std::make_unique<sphere>(c, radius);
}

}  // namespace vl::stage02
