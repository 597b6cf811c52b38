#pragma once
// Closest hits decided again in long double, where the reference's BVH and Embree (which
// works in float) name different primitives: each candidate's distance is recomputed, and
// a candidate hit or missed within float round-off ("grazing": the ray passes a sphere's
// rim, a triangle's edge, or a triangle's plane edge-on, or t is at zero_t) may go either
// way. Used by the oracle test (every difference must be the reference's right) and by
// embree_bench (which counts the differences of its large scenes by the same rule).
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "embree_scene.hh"

namespace vl::embree_bench {

using ld = long double;

/// The reference's zero_t: a hit must be beyond it.
inline constexpr ld exact_zero_t = rtab_component::default_zero_t;
inline constexpr ld float_eps = std::numeric_limits<float>::epsilon();

struct vec3 {
    ld x, y, z;
    vec3 operator-(const vec3& o) const { return {x - o.x, y - o.y, z - o.z}; }
    vec3 operator*(ld s) const { return {x * s, y * s, z * s}; }
    ld dot(const vec3& o) const { return x * o.x + y * o.y + z * o.z; }
    vec3 cross(const vec3& o) const { return {y * o.z - z * o.y, z * o.x - x * o.z, x * o.y - y * o.x}; }
    ld length() const { return std::sqrt(dot(*this)); }
};

/// A candidate's distance along the ray, recomputed in long double.
struct exact_hit {
    bool hit = false;      ///< long double says the ray hits it beyond zero_t
    ld t = 0;              ///< the nearest hit beyond zero_t (or where it passes closest)
    bool grazing = false;  ///< hit or missed within float round-off: either answer is right
};

struct exact_ray {
    vec3 o, d;  // d unit in long double
};

inline exact_ray exact(const ray_f& r) {
    const vec3 d{r.dx, r.dy, r.dz};
    return {{r.ox, r.oy, r.oz}, d * (1 / d.length())};
}

inline exact_hit exact_sphere(const exact_ray& r, const sphere_f& s) {
    const vec3 oc = r.o - vec3{s.x, s.y, s.z};
    const ld b = oc.dot(r.d);
    const vec3 nearest = oc - r.d * b;  // from the centre to the ray's nearest point
    const ld rr = ld(s.r) * s.r, h2 = rr - nearest.dot(nearest);
    exact_hit e;
    // A float discriminant (b^2 - c) loses about float_eps * |oc|^2 to cancellation.
    e.grazing = std::abs(h2) <= 16 * float_eps * (oc.dot(oc) + rr);
    if (h2 < 0) {
        e.t = -b;
        return e;
    }
    const ld h = std::sqrt(h2), t0 = -b - h, t1 = -b + h;
    if (t0 > exact_zero_t) e = {true, t0, e.grazing};
    else if (t1 > exact_zero_t) e = {true, t1, e.grazing};
    else e.t = t1;
    e.grazing = e.grazing || std::abs(t0 - exact_zero_t) <= exact_zero_t || std::abs(t1 - exact_zero_t) <= exact_zero_t;
    return e;
}

inline exact_hit exact_triangle(const exact_ray& r, const scene_data& s, const triangle_i& tri) {
    const auto vertex = [&](std::uint32_t k) { return vec3{s.vertices[k].x, s.vertices[k].y, s.vertices[k].z}; };
    const vec3 a = vertex(tri.a), e1 = vertex(tri.b) - a, e2 = vertex(tri.c) - a;
    const vec3 p = r.d.cross(e2);
    const ld det = e1.dot(p);
    exact_hit e;
    if (std::abs(det) <= 1e-4L * e1.length() * e2.length()) {  // the plane seen edge-on
        e.grazing = true;
        if (det == 0) return e;
    }
    const vec3 ao = r.o - a, q = ao.cross(e1);
    const ld u = ao.dot(p) / det, v = r.d.dot(q) / det, w = 1 - u - v;
    e.t = e2.dot(q) / det;
    const ld inside = std::min({u, v, w});  // < 0: outside an edge
    e.hit = inside >= 0 && e.t > exact_zero_t;
    e.grazing = e.grazing || std::abs(inside) <= 1e-4L || std::abs(e.t - exact_zero_t) <= exact_zero_t;
    return e;
}

inline exact_hit exact_candidate(const exact_ray& r, const scene_data& s, const primitive_id& id) {
    return id.kind == 0 ? exact_sphere(r, s.spheres[id.index]) : exact_triangle(r, s, s.triangles[id.index]);
}

inline bool same_t(ld a, ld b, ld relative) { return std::abs(a - b) <= relative * std::max<ld>(1e-3L, std::max(a, b)); }

enum class verdict { agree, reference_right, tie, grazing, reference_wrong };

/// Decides one ray on which the reference (`ref`) and Embree (`emb`) differ.
inline verdict decide(const exact_ray& r, const scene_data& s, const hit_record& ref, const hit_record& emb) {
    std::optional<exact_hit> p, q;  // the reference's candidate, Embree's
    if (ref.id.hit()) p = exact_candidate(r, s, ref.id);
    if (emb.id.hit()) q = exact_candidate(r, s, emb.id);
    bool grazing = false;
    // The reference's own answer: its primitive is hit there (or grazed).
    if (p) {
        if (!p->hit && !p->grazing) return verdict::reference_wrong;
        if (!same_t(ref.t, p->t, p->grazing ? 1e-5L : 1e-9L)) return verdict::reference_wrong;
        grazing = grazing || p->grazing;
    }
    // What Embree found instead.
    if (q && ref.id != emb.id) {
        if (q->hit && !q->grazing) {
            if (!p) return verdict::reference_wrong;                      // missed a plain hit
            if (q->t < p->t && !same_t(q->t, p->t, 1e-9L)) return verdict::reference_wrong;  // a nearer one
            if (same_t(q->t, p->t, 1e-9L)) return grazing ? verdict::grazing : verdict::tie;
        }
        grazing = grazing || q->grazing;
    }
    return grazing ? verdict::grazing : verdict::reference_right;
}

}  // namespace vl::embree_bench
