#pragma once
// The BVH tests' scenes (grader only): random spheres, clusters, needles, a row, and the
// rays shot at them, all seeded; and the per-ray cost of a sweep of rays.

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include "hidden_support.hh"

namespace vl::stage03::hidden {

/// The radius of N random spheres in the unit cube: 0.15 of their mean spacing.
inline double small_radius(std::size_t n) { return 0.15 / std::cbrt(static_cast<double>(n)); }

/// N spheres at random in the unit cube, each put into `into` and recorded in `set`.
inline void random_spheres(probe_set& set, rtab_composite& into, std::size_t n, unsigned seed) {
    dice random(seed);
    const double r = small_radius(n);
    for (std::size_t k = 0; k < n; ++k) into.insert(set.add(std::make_unique<probe_sphere>(random.in_cube(), r)));
}

/// Most spheres in eight tight clusters, the rest spread thin; returns the cluster centres.
inline std::vector<point> clustered_spheres(probe_set& set, rtab_composite& into, std::size_t n, unsigned seed) {
    dice random(seed);
    std::vector<point> centres;
    for (int k = 0; k < 8; ++k) centres.push_back(random.in_cube(0.15, 0.85));
    const double r = small_radius(n);
    for (std::size_t k = 0; k < n; ++k) {
        if (k % 10 == 9) {
            into.insert(set.add(std::make_unique<probe_sphere>(random.in_cube(), r)));
            continue;
        }
        const point& c = centres[k % 8];
        const vector offset = random.uniform(0, 0.05) * random.direction();
        into.insert(set.add(std::make_unique<probe_sphere>(c + offset, 0.3 * r)));
    }
    return centres;
}

/// N long thin capsules (length 0.15 to 0.3) at random places in random directions.
inline void random_needles(probe_set& set, rtab_composite& into, std::size_t n, unsigned seed) {
    dice random(seed);
    const double r = 0.3 * small_radius(n);
    for (std::size_t k = 0; k < n; ++k) {
        const point c = random.in_cube(0.1, 0.9);
        const vector half = random.uniform(0.075, 0.15) * random.direction();
        into.insert(set.add(std::make_unique<probe_capsule>(c - half, c + half, r)));
    }
}

/// N spheres in a row along z from 0 to 1 at x = y = 0.5.
inline void spheres_in_a_row(probe_set& set, rtab_composite& into, std::size_t n) {
    const double r = 0.3 / static_cast<double>(n);
    for (std::size_t k = 0; k < n; ++k)
        into.insert(set.add(std::make_unique<probe_sphere>(
            point(0.5, 0.5, (static_cast<double>(k) + 0.5) / static_cast<double>(n)), r)));
}

/// Rays from a sphere of radius 2.5 around the cube's centre through random points of it.
inline std::vector<ray> rays_through_cube(std::size_t count, unsigned seed) {
    dice random(seed);
    std::vector<ray> out;
    const point middle(0.5, 0.5, 0.5);
    for (std::size_t k = 0; k < count; ++k) out.push_back(ray_through(middle + 2.5 * random.direction(), random.in_cube()));
    return out;
}

/// A camera's rays: from (0.5, 0.5, 3) through a w x h grid over the cube's middle plane.
inline std::vector<ray> camera_rays(int w, int h) {
    std::vector<ray> out;
    const point eye(0.5, 0.5, 3);
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i)
            out.push_back(ray_through(eye, point((i + 0.5) / w, (j + 0.5) / h, 0.5)));
    return out;
}

/// Rays aimed at the clusters (within 0.06 of a centre) and rays at random.
inline std::vector<ray> rays_at_clusters(const std::vector<point>& centres, std::size_t count, unsigned seed) {
    dice random(seed);
    std::vector<ray> out;
    const point middle(0.5, 0.5, 0.5);
    for (std::size_t k = 0; k < count; ++k) {
        const point target = k % 4 == 3 ? random.in_cube()
                                        : centres[k % centres.size()] + random.uniform(0, 0.06) * random.direction();
        out.push_back(ray_through(middle + 2.5 * random.direction(), target));
    }
    return out;
}

/// What a sweep of rays cost, per ray.
struct sweep_cost {
    double primitive = 0, bounding = 0, total = 0;  ///< per ray
    std::size_t rays = 0;
    double hit_total = 0;    ///< box plus primitive tests per ray, over the rays that hit
    std::size_t hits = 0;    ///< the rays that hit
};

/// Shoots every ray at `bvh`, checks each answer against the brute force over `set` and
/// the probes' own count against the framework's, and returns the mean cost per ray.
inline sweep_cost sweep(tally& t, const std::string& scene, const rtab_composite& bvh, const probe_set& set,
                        const std::vector<ray>& rays) {
    sweep_cost out;
    std::uint64_t primitive = 0, bounding = 0, total = 0, hit_total = 0;
    for (const ray& r : rays) {
        intersection got;
        const cost c = measure([&] { got = bvh.intersect(r); });
        check_against_list(t, "BVH of " + scene, &bvh, set, r, got, std::nullopt);
        t.check(c.probe == c.counts.primitive_tests, [&] {
            return show(r) + " at the BVH of " + scene + ": the children counted " + std::to_string(c.probe) +
                   " intersection tests of their own, but vl::counts() saw " + std::to_string(c.counts.primitive_tests) +
                   " primitive tests (reach each child only through its intersect(), and leave the counters alone)";
        });
        primitive += c.counts.primitive_tests;
        bounding += c.counts.bounding_volume_tests;
        if (got.hit()) {
            ++out.hits;
            hit_total += c.counts.primitive_tests + c.counts.bounding_volume_tests;
        }
        total += c.counts.total_tests();
    }
    out.rays = rays.size();
    const double n = static_cast<double>(rays.size());
    out.primitive = static_cast<double>(primitive) / n;
    out.bounding = static_cast<double>(bounding) / n;
    out.total = static_cast<double>(total) / n;
    if (out.hits > 0) out.hit_total = static_cast<double>(hit_total) / static_cast<double>(out.hits);
    return out;
}

/// Checks the mean costs of a sweep: at most `prim_per_log` and `bv_per_log` times
/// log2(N) primitive and box tests per ray, and at most `factor` times the reference
/// BVH's measured mean of all tests per ray (`reference_total`).
inline void check_budget(const std::string& scene, std::size_t n, const sweep_cost& c, double prim_per_log,
                         double bv_per_log, double reference_total, double factor = 1.5) {
    // VL_MEASURE=1 in the environment prints every sweep's costs: how the reference's
    // numbers in bvh_test.cc were measured (run vl_grader_trusted_03 "[budget]").
    if (std::getenv("VL_MEASURE")) std::printf("MEASURE %s: prim %.6g bv %.6g total %.6g hit_total %.6g\n", scene.c_str(), c.primitive, c.bounding, c.total, c.hit_total);
    const double log_n = std::log2(static_cast<double>(n));
    const double prim_budget = prim_per_log * log_n, bv_budget = bv_per_log * log_n;
    const double total_budget = factor * reference_total;
    const std::string measured = "; yours made, per ray on average over " + std::to_string(c.rays) + " rays, " +
                                 num(c.primitive) + " primitive tests, " + num(c.bounding) + " box tests and " +
                                 num(c.total) + " tests in all (intersect() calls plus box tests)";
    VL_EXPECT(c.primitive <= prim_budget, "the BVH of " << scene << " (N = " << n << ") may make at most " << num(prim_per_log)
                                                        << " log2(N) = " << num(prim_budget)
                                                        << " primitive tests per ray" << measured);
    VL_EXPECT(c.bounding <= bv_budget, "the BVH of " << scene << " (N = " << n << ") may make at most " << num(bv_per_log)
                                                     << " log2(N) = " << num(bv_budget) << " box tests per ray" << measured);
    // Finding one of N children takes at least log2(N / 4) decisions, each a counted test:
    // a BVH that makes fewer per hit tests boxes it does not count.
    const double at_least = std::log2(static_cast<double>(n) / 4);
    VL_EXPECT(c.hits == 0 || c.hit_total >= at_least,
              "the BVH of " << scene << " (N = " << n << ") found its hits with " << num(c.hit_total)
                            << " box and primitive tests per ray on average over the " << c.hits
                            << " rays that hit; no tree of boxes can find one of N children with fewer than log2(N / 4) = "
                            << num(at_least) << " (count every box test: vl::hits_box() does, or call vl::count_bounding_volume_tests())");
    VL_EXPECT(c.total <= total_budget, "the BVH of " << scene << " (N = " << n << ") may make at most " << num(factor)
                                                     << " times the reference BVH's " << num(reference_total)
                                                     << " tests per ray, " << num(total_budget) << measured);
}

}  // namespace vl::stage03::hidden
