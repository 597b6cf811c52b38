// The sphere: t^2 + 2 b t + c = 0 with b = f . d, c = |f|^2 - r^2 (f from the centre to
// the ray's origin). The discriminant b^2 - c is r^2 - |f - b d|^2, whose subtraction
// f - b d is done with fused multiply-adds; the root -b - sign(b) sqrt(disc) has no
// cancellation, and the other is c divided by it.
#include <cmath>
#include <ostream>

#include "stage_02.hh"
#include "vl/primitive_bases.hh"
#include "write_number.hh"

namespace vl::stage02 {

namespace {

class sphere final : public shapes::sphere_base {
public:
    sphere(const point& center, double radius) : sphere_base(center, radius) {}

    vector normal(const point& p) const override { return (p - center_).unit(); }
    bool contains(const point& p) const override { return (p - center_).length() < radius_; }
    point min_point() const override { return center_ - vector(radius_, radius_, radius_); }
    point max_point() const override { return center_ + vector(radius_, radius_, radius_); }

    void write(std::ostream& s) const override {
        s << "SPHERE { center ";
        put(s, center_, " ");
        s << " radius ";
        put(s, radius_);
        write_surface(s);
        s << " }";
    }

private:
    intersection find_intersection(const ray& r) const override {
        const vector f = r.origin() - center_, d = r.direction();
        const double b = f * d;
        const vector l(std::fma(-b, d.x, f.x), std::fma(-b, d.y, f.y), std::fma(-b, d.z, f.z));
        const double disc = std::fma(radius_, radius_, -(l * l));
        if (disc < 0) return intersection::none();
        const double q = -b - std::copysign(std::sqrt(disc), b);
        if (q == 0) return intersection::none();
        const double c = std::fma(-radius_, radius_, f * f);
        const double t0 = std::fmin(q, c / q), t1 = std::fmax(q, c / q);
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
