// The sphere, in long double: half-b quadratic, the squared half chord from the part of
// the origin's offset across the ray, the stable root first and the other from c / q.
#include <cmath>
#include <limits>
#include <ostream>
#include <utility>

#include "stage_02.hh"
#include "vl/primitive_bases.hh"
#include "wide.hh"

namespace vl::stage02 {

namespace {

class sphere final : public shapes::sphere_base {
public:
    sphere(const point& center, double radius) : sphere_base(center, radius) {}

    vector normal(const point& p) const override { return (p - center_).unit(); }
    bool contains(const point& p) const override {
        const wide::vec f = wide::from(p) - wide::from(center_);
        return wide::dot(f, f) < static_cast<long double>(radius_) * radius_;
    }
    point min_point() const override { return center_ - vector(radius_, radius_, radius_); }
    point max_point() const override { return center_ + vector(radius_, radius_, radius_); }

    void write(std::ostream& s) const override {
        const auto old_flags = s.flags();
        const auto old_precision = s.precision(16);
        s << std::scientific << "SPHERE { center " << center_.x << ' ' << center_.y << ' ' << center_.z << " radius "
          << radius_;
        s.flags(old_flags);
        s.precision(old_precision);
        write_surface(s);
        s << " }";
    }

private:
    intersection find_intersection(const ray& r) const override {
        using wide::dot;
        const wide::vec f = wide::from(r.origin()) - wide::from(center_), d = wide::from(r.direction());
        const long double rr = static_cast<long double>(radius_) * radius_;
        const long double b = dot(f, d);
        const wide::vec across = f - b * d;
        const long double disc = rr - dot(across, across);
        if (disc < 0) return intersection::none();
        const long double q = -(b + std::copysign(std::sqrt(disc), b));
        if (q == 0) return intersection::none();
        const long double c = dot(f, f) - rr;
        double t0 = static_cast<double>(c / q), t1 = static_cast<double>(q);
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
