// The triangle, watertight by Woop, Benthin and Wald in long double (shear.hh).
#include <algorithm>
#include <cmath>
#include <limits>
#include <ostream>
#include <string>
#include <utility>

#include "stage_02.hh"
#include "shear.hh"

namespace vl::stage02 {

namespace {

bool finite(const point& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

std::string triangle_problem(const point& a, const point& b, const point& c) {
    if (!finite(a) || !finite(b) || !finite(c)) return "every vertex must be a finite point (w not 0)";
    const vector ab = b - a, ac = c - a;
    if (!((ab % ac).length() > 1e-12 * ab.length() * ac.length()))
        return "its vertices a, b and c are on one line (or two coincide): it has no area";
    return "";
}

class triangle final : public primitive {
public:
    triangle(const point& a, const point& b, const point& c) { set_geometry(a, b, c); }

    std::string type_name() const override { return "TRIANGLE"; }

    vector normal(const point&) const override { return normal_; }
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
        if (const std::string problem = triangle_problem(a, b, c); !problem.empty())
            in.fail(where, "this TRIANGLE is not a triangle: " + problem);
        set_geometry(a, b, c);
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
    void set_geometry(const point& a, const point& b, const point& c) {
        a_ = a.homogenized();
        b_ = b.homogenized();
        c_ = c.homogenized();
        normal_ = ((b_ - a_) % (c_ - a_)).unit();
    }

    intersection find_intersection(const ray& r) const override {
        const shear to_ray(r);
        const std::optional<double> t = through_triangle(to_ray(a_), to_ray(b_), to_ray(c_));
        if (t && std::isfinite(*t) && *t > std::fabs(zero_t())) return intersection::at(*t, this);
        return intersection::none();
    }

    point a_, b_, c_;
    vector normal_;
};

}  // namespace

std::unique_ptr<primitive> make_triangle(const point& a, const point& b, const point& c) {
    if (const std::string problem = triangle_problem(a.homogenized(), b.homogenized(), c.homogenized()); !problem.empty())
        throw usage_error("make_triangle: " + problem);
    return std::make_unique<triangle>(a, b, c);
}

}  // namespace vl::stage02
