// The triangle: the watertight test of frame.hh, t interpolated from the vertices'
// distances along the ray.
#include <algorithm>
#include <cmath>
#include <ostream>
#include <string>

#include "frame.hh"
#include "stage_02.hh"
#include "text.hh"

namespace vl::stage02 {

namespace {

bool finite(const point& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

// Why a b c is not a triangle, or "".
std::string problem_with(const point& a, const point& b, const point& c) {
    if (!finite(a) || !finite(b) || !finite(c)) return "every vertex must be a finite point (w not 0)";
    const vector ab = b - a, ac = c - a;
    if (!((ab % ac).length() > 1e-12 * ab.length() * ac.length())) return "its vertices are on one line: it has no area";
    return "";
}

class triangle final : public primitive {
public:
    triangle(const point& a, const point& b, const point& c) : a_(a), b_(b), c_(c) {}

    std::string type_name() const override { return "TRIANGLE"; }

    vector normal(const point&) const override { return ((b_ - a_) % (c_ - a_)).unit(); }
    bool contains(const point&) const override { return false; }
    point min_point() const override {
        return {std::min({a_.x, b_.x, c_.x}), std::min({a_.y, b_.y, c_.y}), std::min({a_.z, b_.z, c_.z})};
    }
    point max_point() const override {
        return {std::max({a_.x, b_.x, c_.x}), std::max({a_.y, b_.y, c_.y}), std::max({a_.z, b_.z, c_.z})};
    }

    void read(scene_reader& in) override {
        const source_location where = in.peek().where;
        point a = a_, b = b_, c = c_;
        read_with_surface(in, {{"a", [&] { a = in.read_point("vertex a of TRIANGLE").homogenized(); }},
                               {"b", [&] { b = in.read_point("vertex b of TRIANGLE").homogenized(); }},
                               {"c", [&] { c = in.read_point("vertex c of TRIANGLE").homogenized(); }}});
        if (const std::string problem = problem_with(a, b, c); !problem.empty())
            in.fail(where, "this TRIANGLE is not a triangle: " + problem);
        a_ = a, b_ = b, c_ = c;
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

    point a_, b_, c_;
};

}  // namespace

std::unique_ptr<primitive> make_triangle(const point& a, const point& b, const point& c) {
    const point p = a.homogenized(), q = b.homogenized(), s = c.homogenized();
    if (const std::string problem = problem_with(p, q, s); !problem.empty()) throw usage_error("make_triangle: " + problem);
    return std::make_unique<triangle>(p, q, s);
}

}  // namespace vl::stage02
