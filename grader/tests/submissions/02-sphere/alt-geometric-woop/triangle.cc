// The triangle, watertight by Woop, Benthin and Wald (woop.hh).
#include <algorithm>
#include <cmath>
#include <limits>
#include <ostream>
#include <string>
#include <utility>

#include "stage_02.hh"
#include "vl/primitive_bases.hh"
#include "woop.hh"

namespace vl::stage02 {

namespace {

class triangle final : public shapes::triangle_base {
public:
    triangle(const point& a, const point& b, const point& c) : triangle_base(a, b, c) { geometry_changed(); }

    vector normal(const point&) const override { return normal_; }
    point min_point() const override {
        return {std::min({a_.x, b_.x, c_.x}), std::min({a_.y, b_.y, c_.y}), std::min({a_.z, b_.z, c_.z})};
    }
    point max_point() const override {
        return {std::max({a_.x, b_.x, c_.x}), std::max({a_.y, b_.y, c_.y}), std::max({a_.z, b_.z, c_.z})};
    }

    void write(std::ostream& s) const override {
        const auto old_precision = s.precision(std::numeric_limits<double>::max_digits10);
        s << "TRIANGLE {";
        for (const auto& [key, p] : {std::pair{"a", a_}, std::pair{"b", b_}, std::pair{"c", c_}})
            s << ' ' << key << ' ' << p.x << ' ' << p.y << ' ' << p.z;
        s.precision(old_precision);
        write_surface(s);
        s << " }";
    }

private:
    void geometry_changed() override {
        normal_ = ((b_ - a_) % (c_ - a_)).unit();
    }

    intersection find_intersection(const ray& r) const override {
        const sheared_ray shear(r);
        const std::optional<double> t = woop_distance(shear(a_), shear(b_), shear(c_));
        if (t && std::isfinite(*t) && *t > std::fabs(zero_t())) return intersection::at(*t, this);
        return intersection::none();
    }

    vector normal_;
};

}  // namespace

std::unique_ptr<primitive> make_triangle(const point& a, const point& b, const point& c) {
    shapes::triangle_base::check(a, b, c);
    return std::make_unique<triangle>(a, b, c);
}

}  // namespace vl::stage02
