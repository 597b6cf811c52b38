#pragma once
// Watertight ray/triangle intersection after Woop, Benthin and Wald, "Watertight
// Ray/Triangle Intersection", JCGT 2(1), 2013: the vertices are moved into a frame where
// the ray starts at the origin and runs along +z (a permutation of the axes and a shear),
// and the ray meets the triangle when its three 2D edge functions agree in sign.

#include <optional>

#include "vl/ray.hh"

namespace vl::stage02 {

/// A vertex in the ray's sheared frame.
struct sheared_vertex {
    double x = 0, y = 0, z = 0;
};

/// The ray's permutation and shear, computed once per ray.
class sheared_ray {
public:
    explicit sheared_ray(const ray& r);
    sheared_vertex operator()(const point& p) const;

private:
    point origin_;
    int kx_ = 0, ky_ = 1, kz_ = 2;
    double sx_ = 0, sy_ = 0, sz_ = 1;
};

/// The edge function of the edge from p to q: twice the signed area of (0, p, q).
/// Swapping p and q negates it exactly, so two triangles sharing that edge agree on it.
inline double edge_function(const sheared_vertex& p, const sheared_vertex& q) { return p.x * q.y - p.y * q.x; }

/// The distance to the triangle a b c along the ray, when the ray passes through it
/// (either side; an exact zero edge function counts as inside), or nothing.
std::optional<double> woop_distance(const sheared_vertex& a, const sheared_vertex& b, const sheared_vertex& c);

}  // namespace vl::stage02
