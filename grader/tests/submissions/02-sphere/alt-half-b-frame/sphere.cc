// The sphere: the quadratic t^2 + 2 b t + c = 0 in its half-b form, with the root that
// does not cancel computed first and the other one from the product of the roots.
#include <cmath>
#include <ostream>
#include <utility>

#include "numbers.hh"
#include "stage_02.hh"
#include "vl/primitive_bases.hh"

namespace vl::stage02 {

namespace {

class sphere final : public shapes::sphere_base {
public:
    sphere(const point& center, double radius) : sphere_base(center, radius) {}

    vector normal(const point& p) const override {
        const vector out = p - center_;
        return out / out.length();
    }
    bool contains(const point& p) const override { return (p - center_).length() < radius_; }
    point min_point() const override { return center_ - vector(radius_, radius_, radius_); }
    point max_point() const override { return center_ + vector(radius_, radius_, radius_); }

    void write(std::ostream& s) const override {
        s << "SPHERE { center ";
        write_number(s, center_.x);
        s << ' ';
        write_number(s, center_.y);
        s << ' ';
        write_number(s, center_.z);
        s << " radius ";
        write_number(s, radius_);
        write_surface(s);
        s << " }";
    }

private:
    intersection find_intersection(const ray& r) const override {
        const vector f = r.origin() - center_;
        const vector d = r.direction();
        const double b = f * d;  // half of the linear coefficient
        const double c = f * f - radius_ * radius_;
        // b^2 - c cancels when the sphere is small and far; the same number is
        // r^2 - |f - b d|^2, the squared half chord, which keeps its digits.
        const vector perpendicular = f - b * d;
        const double distance = perpendicular.length();
        const double disc = (radius_ - distance) * (radius_ + distance);
        if (disc < 0) return intersection::none();
        const double q = -(b + std::copysign(std::sqrt(disc), b));
        if (q == 0) return intersection::none();  // tangent at the origin
        double t0 = c / q, t1 = q;
        if (t0 > t1) std::swap(t0, t1);
        const double eps = std::fabs(zero_t());
        if (t0 > eps) return intersection::at(t0, this);
        if (t1 > eps) return intersection::at(t1, this);
        return intersection::none();
    }
};

}  // namespace

std::unique_ptr<primitive> make_sphere(const point& center, double radius) {
    shapes::sphere_base::check(center, radius);
    return std::make_unique<sphere>(center, radius);
}

}  // namespace vl::stage02
