// The triangle, watertight: three edge functions of the vertices' parts across the ray
// (across.hh) must not disagree in sign; t is interpolated from the vertices' distances
// along the ray with the edge functions as (unnormalised) barycentric coordinates.
#include <algorithm>
#include <cmath>
#include <ostream>
#include <string>

#include "across.hh"
#include "format.hh"
#include "stage_02.hh"

namespace vl::stage02 {

namespace {

bool finite(const point& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

bool collinear(const point& a, const point& b, const point& c) {
    const vector ab = b - a, ac = c - a;
    return !((ab % ac).length() > 1e-12 * ab.length() * ac.length());
}

class triangle final : public primitive {
public:
    triangle(const point& a, const point& b, const point& c) : a_(a.homogenized()), b_(b.homogenized()), c_(c.homogenized()) {}

    std::string type_name() const override { return "TRIANGLE"; }

    vector normal(const point&) const override { return ((b_ - a_) % (c_ - a_)).unit(); }
    bool contains(const point&) const override { return false; }
    point min_point() const override {
        return {std::min(a_.x, std::min(b_.x, c_.x)), std::min(a_.y, std::min(b_.y, c_.y)),
                std::min(a_.z, std::min(b_.z, c_.z))};
    }
    point max_point() const override {
        return {std::max(a_.x, std::max(b_.x, c_.x)), std::max(a_.y, std::max(b_.y, c_.y)),
                std::max(a_.z, std::max(b_.z, c_.z))};
    }

    void read(scene_reader& in) override {
        const source_location where = in.peek().where;
        point a = a_, b = b_, c = c_;
        read_with_surface(in, {{"a", [&] { a = in.read_point("vertex a of TRIANGLE").homogenized(); }},
                               {"b", [&] { b = in.read_point("vertex b of TRIANGLE").homogenized(); }},
                               {"c", [&] { c = in.read_point("vertex c of TRIANGLE").homogenized(); }}});
        if (!finite(a) || !finite(b) || !finite(c)) in.fail(where, "this TRIANGLE has a vertex that is not a finite point");
        if (collinear(a, b, c)) in.fail(where, "this TRIANGLE is not a triangle: its vertices are on one line");
        a_ = a, b_ = b, c_ = c;
    }
    void write(std::ostream& s) const override {
        s << "TRIANGLE { a " << exact(a_.x) << ' ' << exact(a_.y) << ' ' << exact(a_.z) << " b " << exact(b_.x) << ' '
          << exact(b_.y) << ' ' << exact(b_.z) << " c " << exact(c_.x) << ' ' << exact(c_.y) << ' ' << exact(c_.z);
        write_surface(s);
        s << " }";
    }

private:
    intersection find_intersection(const ray& r) const override {
        const seen a = see(r, a_), b = see(r, b_), c = see(r, c_);
        const double wa = edge_value(r, b, c), wb = edge_value(r, c, a), wc = edge_value(r, a, b);
        if ((wa < 0 || wb < 0 || wc < 0) && (wa > 0 || wb > 0 || wc > 0)) return intersection::none();
        const double sum = wa + wb + wc;
        if (sum == 0) return intersection::none();  // in the triangle's plane
        const double t = (wa * a.along + wb * b.along + wc * c.along) / sum;
        if (std::isfinite(t) && t > std::fabs(zero_t())) return intersection::at(t, this);
        return intersection::none();
    }

    point a_, b_, c_;
};

}  // namespace

std::unique_ptr<primitive> make_triangle(const point& a, const point& b, const point& c) {
    const point p = a.homogenized(), q = b.homogenized(), s = c.homogenized();
    if (!finite(p) || !finite(q) || !finite(s)) throw usage_error("make_triangle: every vertex must be a finite point");
    if (collinear(p, q, s)) throw usage_error("make_triangle: the vertices are on one line (or two coincide)");
    return std::make_unique<triangle>(p, q, s);
}

}  // namespace vl::stage02
