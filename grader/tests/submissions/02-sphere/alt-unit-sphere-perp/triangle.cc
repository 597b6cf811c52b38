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
#include "vl/primitive_bases.hh"

namespace vl::stage02 {

namespace {

bool collinear(const point& a, const point& b, const point& c) {
    const vector ab = b - a, ac = c - a;
    return !((ab % ac).length() > 1e-12 * ab.length() * ac.length());
}

class triangle final : public shapes::triangle_base {
public:
    triangle(const point& a, const point& b, const point& c) : triangle_base(a, b, c) {}

    vector normal(const point&) const override { return ((b_ - a_) % (c_ - a_)).unit(); }
    point min_point() const override {
        return {std::min(a_.x, std::min(b_.x, c_.x)), std::min(a_.y, std::min(b_.y, c_.y)),
                std::min(a_.z, std::min(b_.z, c_.z))};
    }
    point max_point() const override {
        return {std::max(a_.x, std::max(b_.x, c_.x)), std::max(a_.y, std::max(b_.y, c_.y)),
                std::max(a_.z, std::max(b_.z, c_.z))};
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
};

}  // namespace

std::unique_ptr<primitive> make_triangle(const point& a, const point& b, const point& c) {
    shapes::triangle_base::check(a, b, c);
    return std::make_unique<triangle>(a, b, c);
}

}  // namespace vl::stage02
