// The reference's BVH against Embree as an oracle: 10 000 random spheres, 3 000 random
// triangles and a 800-triangle mesh patch (shared edges), 100 000 random rays. Every
// closest hit of the reference (stage02 primitives in a stage03::make_bvh, through the
// counted intersect()) must be Embree's: the same primitive, t within 1e-5 relative.
// Where they differ (Embree works in floats), both candidates' distances are computed
// again in long double, and the reference must be right by that check: it hits the
// candidate whose long-double t is nearest (ties, such as a shared mesh edge, go either
// way), its t is that primitive's, and it misses a candidate only when long double
// misses it too. A candidate hit or missed within float round-off ("grazing": the ray
// passes the sphere's rim, a triangle's edge, or a triangle's plane edge-on, or t is at
// zero_t) may go either way. The counts of each outcome are printed.
#include "vl/catch.hh"

#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <vector>

#include "embree_scene.hh"
#include "exact_hits.hh"

using namespace vl::embree_bench;

namespace {

constexpr double zero_t = vl::rtab_component::default_zero_t;

scene_data oracle_scene() {
    rng g(2026);
    scene_data s;
    for (int i = 0; i < 10000; ++i) {
        const double x = g.uniform(), y = g.uniform(), z = g.uniform(), r = g.uniform(0.005, 0.02);
        s.spheres.push_back({float(x), float(y), float(z), float(r)});
    }
    // Random triangles: a centre in the cube, vertices within 0.05 of it, not thin.
    while (s.triangles.size() < 3000) {
        const double cx = g.uniform(), cy = g.uniform(), cz = g.uniform();
        vertex_f v[3];
        for (vertex_f& p : v)
            p = {float(cx + g.uniform(-0.05, 0.05)), float(cy + g.uniform(-0.05, 0.05)), float(cz + g.uniform(-0.05, 0.05))};
        const vec3 a{v[0].x, v[0].y, v[0].z}, e1 = vec3{v[1].x, v[1].y, v[1].z} - a, e2 = vec3{v[2].x, v[2].y, v[2].z} - a;
        if (e1.cross(e2).length() < 0.2L * e1.length() * e2.length()) continue;
        const auto base = std::uint32_t(s.vertices.size());
        s.vertices.insert(s.vertices.end(), v, v + 3);
        s.triangles.push_back({base, base + 1, base + 2});
    }
    // A bumpy 20 x 20 patch of two triangles per cell sharing edges and vertices.
    const auto base = std::uint32_t(s.vertices.size());
    const int n = 20;
    for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= n; ++j)
            s.vertices.push_back({float(0.1 + 0.8 * i / n), float(0.5 + 0.03 * g.uniform(-1, 1)), float(0.1 + 0.8 * j / n)});
    const auto at = [&](int i, int j) { return base + std::uint32_t(i * (n + 1) + j); };
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
            s.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
            s.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
        }
    }
    return s;
}

}  // namespace

TEST_CASE("oracle: the reference BVH's closest hits are Embree's, or right by long double where they differ", "[embree]") {
    const scene_data s = oracle_scene();
    const std::vector<ray_f> rays = random_rays(100000, -0.5, 1.5, 7);

    const reference_scene ref(s);
    embree_scene emb(s);
    emb.commit();
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);

    std::size_t counts[5] = {};
    std::size_t hits = 0;
    for (std::size_t i = 0; i < rays.size(); ++i) {
        const hit_record a = ref.record(ref.bvh().intersect(to_vl_ray(rays[i])));
        RTCRayHit h = embree_scene::ray_hit(rays[i], float(zero_t));
        emb.intersect(context, h);
        const hit_record b = emb.record(h);
        hits += a.id.hit();
        const bool agree = a.id.hit() == b.id.hit() &&
                           (!a.id.hit() || (a.id == b.id && same_t(a.t, b.t, 1e-5L)));
        const verdict v = agree ? verdict::agree : decide(exact(rays[i]), s, a, b);
        ++counts[int(v)];
        if (v == verdict::reference_wrong && counts[int(v)] <= 20) {
            UNSCOPED_INFO("ray " << i << ": reference kind " << a.id.kind << " #" << a.id.index << " t " << a.t
                                 << ", Embree kind " << b.id.kind << " #" << b.id.index << " t " << b.t);
        }
    }
    std::printf("embree oracle: %zu rays, %zu reference hits; agree %zu; differ: reference right %zu, "
                "tie %zu, grazing (either right) %zu, reference wrong %zu\n",
                rays.size(), hits, counts[0], counts[1], counts[2], counts[3], counts[4]);
    CHECK(counts[int(verdict::reference_wrong)] == 0);
    // Embree is a useful oracle only when it mostly agrees (the mapping of ids is right).
    CHECK(counts[int(verdict::agree)] >= rays.size() * 99 / 100);
    CHECK(hits >= rays.size() / 10);
}
