#include "shear.hh"

#include <cmath>
#include <utility>

namespace vl::stage02 {

namespace {

long double at(const long double (&v)[3], int k) { return v[k]; }

}  // namespace

shear::shear(const ray& r) : ox_(r.origin().x), oy_(r.origin().y), oz_(r.origin().z) {
    const long double d[3] = {r.direction().x, r.direction().y, r.direction().z};
    iz_ = 0;
    for (int k = 1; k < 3; ++k)
        if (std::fabs(d[k]) > std::fabs(d[iz_])) iz_ = k;
    ix_ = (iz_ + 1) % 3;
    iy_ = (iz_ + 2) % 3;
    if (d[iz_] < 0) std::swap(ix_, iy_);
    sx_ = at(d, ix_) / at(d, iz_);
    sy_ = at(d, iy_) / at(d, iz_);
    sz_ = 1 / at(d, iz_);
}

sheared shear::operator()(const point& p) const {
    const long double q[3] = {p.x - ox_, p.y - oy_, p.z - oz_};
    return {q[ix_] - sx_ * q[iz_], q[iy_] - sy_ * q[iz_], sz_ * q[iz_]};
}

std::optional<double> through_triangle(const sheared& a, const sheared& b, const sheared& c) {
    const long double u = edge_of(b, c), v = edge_of(c, a), w = edge_of(a, b);
    const bool negative = u < 0 || v < 0 || w < 0, positive = u > 0 || v > 0 || w > 0;
    if (negative && positive) return std::nullopt;
    const long double det = u + v + w;
    if (det == 0) return std::nullopt;
    return static_cast<double>((u * a.z + v * b.z + w * c.z) / det);
}

}  // namespace vl::stage02
