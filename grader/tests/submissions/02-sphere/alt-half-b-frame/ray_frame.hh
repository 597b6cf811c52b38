#pragma once
// An orthonormal frame around a ray: its origin at the ray's origin, its third axis the
// ray's direction (Duff et al., "Building an Orthonormal Basis, Revisited", JCGT 6(1),
// 2017). In it the ray is the positive z axis, and whether the ray passes through a flat
// object is a question about the signs of 2D edge functions at (0, 0).

#include "vl/ray.hh"

namespace vl::stage02 {

/// A point in a ray's frame.
struct frame_point {
    double x = 0, y = 0, z = 0;
};

class ray_frame {
public:
    explicit ray_frame(const ray& r);
    /// `p` in this frame: its offsets across the ray and its distance along it.
    frame_point operator()(const point& p) const {
        const vector q = p - origin_;
        return {q * u_, q * v_, q * w_};
    }

private:
    point origin_;
    vector u_, v_, w_;
};

/// Twice the signed area of the triangle (0, p, q) in the frame's xy plane. It is
/// exactly -edge(q, p), so two objects sharing the edge p q always agree on it.
inline double edge(const frame_point& p, const frame_point& q) { return p.x * q.y - p.y * q.x; }

}  // namespace vl::stage02
