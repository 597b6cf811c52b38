#pragma once
// Edge functions from the parts of the vertices that lie across the ray: each vertex,
// relative to the ray's origin, minus its component along the ray. The edge function of
// p q is the ray direction's triple product with those two parts; swapping p and q
// negates it exactly, so neighbours sharing an edge agree about it.

#include "vl/ray.hh"

namespace vl::stage02 {

/// A vertex seen from a ray: its part across the ray and its distance along it.
struct seen {
    vector across;
    double along = 0;
};

inline seen see(const ray& r, const point& p) {
    const vector q = p - r.origin();
    const double along = q * r.direction();
    return {q - along * r.direction(), along};
}

inline double edge_value(const ray& r, const seen& p, const seen& q) { return r.direction() * (p.across % q.across); }

}  // namespace vl::stage02
