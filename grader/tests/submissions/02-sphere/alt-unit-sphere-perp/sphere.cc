// The sphere, solved in its own unit frame: the ray's origin is moved to the centre and
// scaled by 1 / radius, so the sphere becomes |p| = 1 and t scales back by the radius.
#include <cmath>
#include <ostream>

#include "format.hh"
#include "stage_02.hh"
#include "vl/primitive_bases.hh"

namespace vl::stage02 {

namespace {

class sphere final : public shapes::sphere_base {
public:
    sphere(const point& center, double radius) : sphere_base(center, radius) {}

    vector normal(const point& p) const override { return (p - center_).unit(); }
    bool contains(const point& p) const override {
        const vector f = p - center_;
        return std::sqrt(f * f) < radius_;
    }
    point min_point() const override { return center_ + vector(-radius_, -radius_, -radius_); }
    point max_point() const override { return center_ + vector(radius_, radius_, radius_); }

    void write(std::ostream& s) const override {
        s << "SPHERE { center " << exact(center_.x) << ' ' << exact(center_.y) << ' ' << exact(center_.z)
          << " radius " << exact(radius_);
        write_surface(s);
        s << " }";
    }

private:
    intersection find_intersection(const ray& r) const override {
        const vector d = r.direction();
        const vector o = (r.origin() - center_) / radius_;  // the origin in the unit sphere's frame
        const double along = -(o * d);                       // to the point nearest the centre
        const vector nearest = o + along * d;
        const double h2 = 1 - nearest * nearest;             // squared half chord
        if (h2 < 0) return intersection::none();
        const double h = std::sqrt(h2);
        const double c = o * o - 1;
        // The root on the side of `along` is a sum of like signs; the other is c over it.
        const double big = along >= 0 ? along + h : along - h;
        if (big == 0) return intersection::none();
        const double small = c / big;
        const double s0 = std::fmin(small, big), s1 = std::fmax(small, big);
        const double eps = std::fabs(zero_t());
        if (radius_ * s0 > eps) return intersection::at(radius_ * s0, this);
        if (radius_ * s1 > eps) return intersection::at(radius_ * s1, this);
        return intersection::none();
    }
};

}  // namespace

std::unique_ptr<primitive> make_sphere(const point& center, double radius) {
    shapes::sphere_base::check(center, radius);
    return std::make_unique<sphere>(center, radius);
}

}  // namespace vl::stage02
