#pragma once
/// \file
/// \brief The ray's own coordinate system, where the watertight triangle and polygon
/// tests happen (Woop, Benthin and Wald, "Watertight Ray/Triangle Intersection", JCGT
/// 2(1), 2013, section 3).
///
/// In ray space the ray starts at the origin and runs along +z, so "does the ray pass
/// through this polygon?" becomes "is the 2D origin inside the polygon's shadow on the
/// xy plane?", decided by the signs of one edge function per edge. Each vertex is
/// transformed once, the same way for every triangle or polygon that shares it, and the
/// edge function of the edge p -> q is exactly the negative of that of q -> p, so two
/// neighbours always agree on which side of their shared edge the ray passes: no gaps.

#include <cmath>
#include <utility>

#include "vl/ray.hh"

namespace vl::stage02 {

/// \brief A point in ray space: the ray starts at (0, 0, 0) and `z` is its distance along it.
struct ray_space_point {
    double x = 0, y = 0, z = 0;
};

/// \brief The translation, axis permutation and shear that take a ray to the +z axis.
class ray_space {
public:
    explicit ray_space(const ray& r) : origin_(r.origin()) {
        const vector& d = r.direction();
        const double dir[3] = {d.x, d.y, d.z};
        // The largest component becomes z, so the shear divides by the largest number
        // available; swapping x and y when it is negative keeps the winding (and so the
        // sign of the edge functions) the same for rays in opposite directions.
        kz_ = std::fabs(d.x) > std::fabs(d.y) ? (std::fabs(d.x) > std::fabs(d.z) ? 0 : 2)
                                              : (std::fabs(d.y) > std::fabs(d.z) ? 1 : 2);
        kx_ = (kz_ + 1) % 3;
        ky_ = (kx_ + 1) % 3;
        if (dir[kz_] < 0) std::swap(kx_, ky_);
        sx_ = dir[kx_] / dir[kz_];
        sy_ = dir[ky_] / dir[kz_];
        sz_ = 1 / dir[kz_];
    }

    /// `p` in ray space.
    ray_space_point operator()(const point& p) const {
        const vector v = p - origin_;
        const double c[3] = {v.x, v.y, v.z};
        return {c[kx_] - sx_ * c[kz_], c[ky_] - sy_ * c[kz_], sz_ * c[kz_]};
    }

private:
    point origin_;
    int kx_ = 0, ky_ = 1, kz_ = 2;
    double sx_ = 0, sy_ = 0, sz_ = 1;
};

/// Twice the signed area of the 2D triangle (origin, q, p) in ray space: > 0 when the
/// ray passes on one side of the edge p -> q, < 0 on the other, 0 exactly on it.
///
/// Rounding is monotonic, so the two rounded products can only tie, never swap order:
/// the difference has the exact sign unless it is 0. Then the products rounded to the
/// same double, and the sign is that of their rounding errors, which fma() gives exactly
/// (the paper falls back to double precision for float; for double, the exact errors
/// of the products do the same job).
inline double edge_function(const ray_space_point& p, const ray_space_point& q) {
    const double a = q.x * p.y, b = q.y * p.x;
    const double e = a - b;
    if (e != 0) return e;
    return std::fma(q.x, p.y, -a) - std::fma(q.y, p.x, -b);
}

}  // namespace vl::stage02
