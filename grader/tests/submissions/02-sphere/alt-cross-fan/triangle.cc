// The triangle: the watertight test of frame.hh, t interpolated from the vertices'
// distances along the ray.
#include <algorithm>
#include <cmath>
#include <ostream>
#include <string>

#include "frame.hh"
#include "stage_02.hh"
#include "text.hh"
#include "vl/primitive_bases.hh"

namespace vl::stage02 {

namespace {

// Why a b c is not a triangle, or "".
class triangle final : public shapes::triangle_base {
public:
    triangle(const point& a, const point& b, const point& c) : triangle_base(a, b, c) {}

    vector normal(const point&) const override { return ((b_ - a_) % (c_ - a_)).unit(); }
    point min_point() const override {
        return {std::min({a_.x, b_.x, c_.x}), std::min({a_.y, b_.y, c_.y}), std::min({a_.z, b_.z, c_.z})};
    }
    point max_point() const override {
        return {std::max({a_.x, b_.x, c_.x}), std::max({a_.y, b_.y, c_.y}), std::max({a_.z, b_.z, c_.z})};
    }

    void write(std::ostream& s) const override {
        s << "TRIANGLE { a " << number{a_.x} << ' ' << number{a_.y} << ' ' << number{a_.z};
        s << " b " << number{b_.x} << ' ' << number{b_.y} << ' ' << number{b_.z};
        s << " c " << number{c_.x} << ' ' << number{c_.y} << ' ' << number{c_.z};
        write_surface(s);
        s << " }";
    }

private:
    intersection find_intersection(const ray& r) const override {
        const frame f(r);
        const auto t = crossing(f(a_), f(b_), f(c_));
        if (t && std::isfinite(*t) && *t > std::fabs(zero_t())) return intersection::at(*t, this);
        return intersection::none();
    }
};

}  // namespace

std::unique_ptr<primitive> make_triangle(const point& a, const point& b, const point& c) {
    shapes::triangle_base::check(a, b, c);
    return std::make_unique<triangle>(a, b, c);
}

}  // namespace vl::stage02
