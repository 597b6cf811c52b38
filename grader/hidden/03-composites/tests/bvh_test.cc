// Hidden tests of stage 03's bounding volume hierarchy (bvh.cc). Each TEST_CASE is one
// graded item; the tag [bvh] puts it in the rubric's "bvh" category. The children are
// probes (hidden_support.hh): objects your code has never seen, which compute their own
// hits in long double and count their own tests. The answer key is the brute force over
// the same probes: what a plain LIST of them returns.
#include "vl/catch.hh"

#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "bvh_scenes.hh"
#include "composite_checks.hh"

using vl::intersection;
using vl::point;
using vl::ray;
using vl::rtab_component;
using vl::rtab_composite;
using vl::vector;
using vl::stage03::make_bvh;
using namespace vl::stage03::hidden;

namespace {

/// N spheres of random sizes (overlapping) in the unit cube.
void varied_spheres(probe_set& set, rtab_composite& into, std::size_t n, unsigned seed) {
    dice random(seed);
    for (std::size_t k = 0; k < n; ++k)
        into.insert(set.add(std::make_unique<probe_sphere>(random.in_cube(), random.uniform(0.01, 0.2), true)));
}

/// Rays of every kind at the unit cube: from outside, from inside, along the axes (two
/// direction components exactly 0) and in the axis planes (one component 0).
std::vector<ray> mixed_rays(unsigned seed, int count) {
    dice random(seed);
    std::vector<ray> out;
    const point middle(0.5, 0.5, 0.5);
    static const vector axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (int k = 0; k < count; ++k) {
        switch (k % 4) {
            case 0: out.push_back(ray_through(middle + 2 * random.direction(), random.in_cube())); break;
            case 1: out.push_back(ray(random.in_cube(), random.direction())); break;
            case 2: out.push_back(ray(random.in_cube(-0.2, 1.2), axes[random.below(6)])); break;
            default: {
                vector d = random.direction();
                const int zero = random.below(3);
                (zero == 0 ? d.x : zero == 1 ? d.y : d.z) = 0;
                out.push_back(ray(random.in_cube(-0.2, 1.2), d));
            }
        }
    }
    return out;
}

/// Shoots `rays` at `bvh` and checks every answer against the brute force and the probes'
/// count against the framework's.
void check_rays(tally& t, const std::string& who, const rtab_composite& bvh, const probe_set& set,
                const std::vector<ray>& rays) {
    sweep(t, who, bvh, set, rays);
}

}  // namespace

// --- the nearest hit -----------------------------------------------------------------------

TEST_CASE("bvh: rays from outside - from inside and along the axes get the nearest hit a LIST of the same children gives", "[03][bvh][hits][essential]") {
    tally t("rays at BVHs of random spheres");
    const std::size_t sizes[] = {1, 2, 3, 5, 8, 17, 60, 250};
    const int leaf_sizes[] = {4, 1, 2, 3, 8, 4, 1, 4};
    for (std::size_t k = 0; k < std::size(sizes); ++k) {
        probe_set set;
        auto bvh = make_bvh(leaf_sizes[k]);
        varied_spheres(set, *bvh, sizes[k], 300 + static_cast<unsigned>(k));
        check_rays(t, std::to_string(sizes[k]) + " random spheres (leaf_size " + std::to_string(leaf_sizes[k]) + ")", *bvh,
                   set, mixed_rays(400 + static_cast<unsigned>(k), 240));
    }
    t.report();
}

TEST_CASE("bvh: capsules - solid boxes and flat rectangles whose boxes have no thickness are found like in a LIST", "[03][bvh][hits]") {
    tally t("rays at BVHs of mixed children");
    dice random(310);
    for (int round = 0; round < 3; ++round) {
        probe_set set;
        auto bvh = make_bvh(round == 1 ? 1 : 4);
        for (int k = 0; k < 40; ++k) {
            const point c = random.in_cube();
            switch (k % 4) {
                case 0: bvh->insert(set.add(std::make_unique<probe_capsule>(c, c + 0.3 * random.direction(), 0.02))); break;
                case 1: bvh->insert(set.add(std::make_unique<probe_cuboid>(c, c + vector(0.05, 0.1, 0.03)))); break;
                case 2: {
                    // A rectangle flat in z (its box has no thickness), many in one plane.
                    const double z = k % 8 == 2 ? 0.5 : c.z;
                    bvh->insert(set.add(std::make_unique<probe_flat>(2, z, c.x, c.y, c.x + 0.15, c.y + 0.1)));
                    break;
                }
                default: bvh->insert(set.add(std::make_unique<probe_flat>(k % 3, 0.25, c.x, c.y, c.x + 0.2, c.y + 0.2)));
            }
        }
        std::vector<ray> rays = mixed_rays(320 + static_cast<unsigned>(round), 200);
        // Rays lying in the plane z = 0.5 of the flat rectangles.
        for (int k = 0; k < 20; ++k) {
            vector d = random.direction();
            d.z = 0;
            rays.push_back(ray(point(random.uniform(0, 1), random.uniform(0, 1), 0.5), d));
        }
        check_rays(t, "40 mixed children (round " + std::to_string(round) + ")", *bvh, set, rays);
    }
    // Every child flat in the same plane: the BVH's own box has no thickness.
    probe_set set;
    auto bvh = make_bvh();
    for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 6; ++j)
            bvh->insert(set.add(std::make_unique<probe_flat>(1, 0.5, 0.2 * i, 0.2 * j, 0.2 * i + 0.15, 0.2 * j + 0.15)));
    check_rays(t, "36 rectangles all in the plane y = 0.5", *bvh, set, mixed_rays(330, 200));
    t.report();
}

TEST_CASE("bvh: a hit inside a nested BVH or a LIST held by the BVH names the leaf that was hit", "[03][bvh][rules][essential]") {
    tally t("rays at BVHs that hold composites");
    probe_set set;
    dice random(340);
    auto outer = make_bvh();
    for (int g = 0; g < 4; ++g) {
        auto inner = make_bvh(g % 2 == 0 ? 2 : 4);
        auto list = std::make_unique<vl::object_list>();
        for (int k = 0; k < 6; ++k) {
            inner->insert(set.add(std::make_unique<probe_sphere>(random.in_cube(), random.uniform(0.02, 0.12))));
            list->insert(set.add(std::make_unique<probe_sphere>(random.in_cube(), random.uniform(0.02, 0.12))));
        }
        auto deeper = make_bvh(1);
        deeper->insert(set.add(std::make_unique<probe_sphere>(random.in_cube(), 0.05)));
        deeper->insert(set.add(std::make_unique<probe_cuboid>(point(0.1 * g, 0.8, 0.1), point(0.1 * g + 0.05, 0.9, 0.2))));
        inner->insert(std::move(deeper));
        outer->insert(std::move(inner));
        outer->insert(std::move(list));
    }
    outer->insert(set.add(std::make_unique<probe_sphere>(point(0.5, 0.5, 0.5), 0.08)));
    check_rays(t, "BVHs and LISTs of spheres", *outer, set, mixed_rays(341, 400));
    t.report();
}

// --- the three rules and the cost of a miss ---------------------------------------------------

TEST_CASE("bvh: a ray through the root box that hits nothing gets composite_only of the BVH - one beside it a miss for one box test", "[03][bvh][rules][essential]") {
    tally t("the rules for no hit");
    namer names;
    probe_set set;
    auto bvh = make_bvh();
    names.name(bvh.get(), "the BVH itself");
    bvh->insert(set.add(std::make_unique<probe_sphere>(point(0, 0, 0), 0.5)));
    bvh->insert(set.add(std::make_unique<probe_sphere>(point(4, 4, 4), 0.5)));
    bvh->insert(set.add(std::make_unique<probe_sphere>(point(4, 0, 0), 0.5)));
    // The root box runs from (-0.5, -0.5, -0.5) to (4.5, 4.5, 4.5).
    for (const ray& r : {ray(point(2, 2, -10), vector(0, 0, 1)), ray(point(2, -3, 2), vector(0.1, 1, 0.05)),
                         ray(point(2, 2, 2), vector(1, 1, -1)), ray(point(-0.4, 4.4, -5), vector(0, 0, 1))}) {
        intersection got;
        const cost c = measure([&] { got = bvh->intersect(r); });
        check_against_list(t, "BVH", bvh.get(), set, r, got, true);
        (void)c;
    }
    for (const ray& r : {ray(point(10, 10, -10), vector(0, 0, 1)), ray(point(-1, 2, 2), vector(-1, 0.2, 0.1)),
                         ray(point(2, 2, 6), vector(0, 0, 1)), ray(point(4.6, 4.6, -5), vector(0, 0, 1))}) {
        intersection got;
        const cost c = measure([&] { got = bvh->intersect(r); });
        check_against_list(t, "BVH", bvh.get(), set, r, got, false);
        t.check(c.counts.bounding_volume_tests == 1 && c.probe == 0 && c.counts.count() == 1, [&] {
            return show(r) + " misses the root box of the BVH: that should cost exactly one box test and no child test; "
                   "yours made " + std::to_string(c.counts.bounding_volume_tests) + " box tests and " +
                   std::to_string(c.counts.count() - 1) + " intersect() calls on children";
        });
    }
    // A child that answers composite_only of itself: the BVH answers composite_only of itself.
    auto with_hollow = make_bvh();
    names.name(with_hollow.get(), "the BVH itself");
    insert_hollow_child(names, *with_hollow);
    probe_set far;
    with_hollow->insert(far.add(std::make_unique<probe_sphere>(point(5, 5, 5), 0.5)));
    check_composite_only_of(t, names, *with_hollow, ray(point(0.5, 0.5, -3), vector(0, 0, 1)),
                            " enters only a child that answers composite_only of itself: the BVH should return "
                            "composite_only of the BVH");
    // A nested BVH entered for nothing.
    auto outer = make_bvh();
    names.name(outer.get(), "the outer BVH");
    auto inner = make_bvh();
    names.name(inner.get(), "the inner BVH (rule 2: the outer one names itself)");
    probe_set nested;
    inner->insert(nested.add(std::make_unique<probe_sphere>(point(0, 0, 0), 0.5)));
    inner->insert(nested.add(std::make_unique<probe_sphere>(point(2, 2, 0), 0.5)));
    outer->insert(std::move(inner));
    outer->insert(nested.add(std::make_unique<probe_sphere>(point(6, 0, 0), 0.5)));
    check_composite_only_of(t, names, *outer, ray(point(1, 1, -5), vector(0, 0, 1)),
                            " enters the box of a BVH inside a BVH but hits nothing: the outer BVH should return "
                            "composite_only of itself");
    // An empty BVH is missed.
    auto empty = make_bvh();
    const intersection g3 = empty->intersect(ray(point(0, 0, 5), vector(0, 0, -1)));
    t.check(g3.is_miss() && g3.t == 0, [&] { return "an empty BVH should be missed by every ray; yours returned " + show(g3, names); });
    t.report();
}

// --- budgets ----------------------------------------------------------------------------------
//
// Each budget is three limits on the mean cost per ray: primitive tests <= 3 log2(N), box
// tests <= 12 log2(N), and all tests (intersect() calls plus box tests) <= 1.5 times what
// the first reference BVH (a full SAH sweep over the sorted children on all three axes,
// leaf_size 4, a node's entry weighed as one child test) made on the very same scene and
// rays, measured once and written below, so that the budgets stay put when the reference
// changes. That reference made 0.8 to 1.9 primitive tests and 45 to 127 box tests per ray
// among the random spheres (5.2 to 7.6 log2(N) box tests: more than the contract's
// "about 6 log2(N)" at N = 10000 and 100000, hence 12 here). Today's reference (32 bins
// per axis, a node's entry weighed as its two box tests and a leaf as its blocks of four
// children, the binary tree collapsed into eight subtrees per node, a ball around each
// child of a leaf tested, and counted as a box test, before the child is called,
// VL_MEASURE below) makes 1.3 to 2.7 primitive and 50 to 147 box tests per ray among the
// random spheres, 1.12 to 1.17 times the totals written below (1.36 times along the row
// of spheres, where it tests the balls of a whole leaf). For comparison, a median split of the
// longest axis with leaves of 4 makes 1.0 to 1.3 times the reference's tests (up to 24
// primitive tests per ray), a 12-bin SAH about 1.0 times, a tree built by insertion
// (Goldsmith and Salmon) 1.1 to 1.45 times; a LIST makes N primitive tests per ray, a
// tree walked without skipping boxes beyond the best hit about N along the row of spheres.

namespace {
struct measured {
    double random_rays, camera_rays;  // the reference's mean tests per ray
};
// The reference BVH's mean tests per ray (random rays through the cube, then the 20 x 15
// camera's; for N = 100000, 100 random rays and a 10 x 10 camera).
constexpr measured reference_1000{53.7975, 46.7867};
constexpr measured reference_10000{95.3425, 80.2033};
constexpr measured reference_100000{129.29, 95.32};
constexpr double reference_clustered = 85.55;
constexpr double reference_needles = 165.215;
constexpr double reference_row = 22;

void random_sphere_budget(std::size_t n, const measured& reference, std::size_t random_count, int camera_w, int camera_h) {
    probe_set set;
    auto bvh = make_bvh();
    random_spheres(set, *bvh, n, 7);
    tally t("rays at " + std::to_string(n) + " random spheres");
    const std::string scene = std::to_string(n) + " random spheres of radius " + num(small_radius(n)) + " in the unit cube";
    const sweep_cost random_cost = sweep(t, scene, *bvh, set, rays_through_cube(random_count, 11));
    const sweep_cost camera_cost = sweep(t, scene + " seen by a camera", *bvh, set, camera_rays(camera_w, camera_h));
    t.report();
    check_budget(scene + " (rays through random points of the cube)", n, random_cost, 3, 12, reference.random_rays);
    check_budget(scene + " (a camera's rays)", n, camera_cost, 3, 12, reference.camera_rays);
}
}  // namespace

TEST_CASE("bvh: 1000 random small spheres cost about log2(N) tests per ray - like the reference BVH", "[03][bvh][budget][essential]") {
    random_sphere_budget(1000, reference_1000, 400, 20, 15);
}

TEST_CASE("bvh: 10000 random small spheres cost about log2(N) tests per ray - like the reference BVH", "[03][bvh][budget][essential]") {
    random_sphere_budget(10000, reference_10000, 400, 20, 15);
}

TEST_CASE("bvh: 100000 random small spheres cost about log2(N) tests per ray - like the reference BVH", "[03][bvh][budget][essential]") {
    random_sphere_budget(100000, reference_100000, 100, 10, 10);
}

TEST_CASE("bvh: spheres in tight clusters with a few spread thin cost no more than with the reference BVH", "[03][bvh][budget]") {
    probe_set set;
    auto bvh = make_bvh();
    const std::vector<point> centres = clustered_spheres(set, *bvh, 10000, 5);
    tally t("rays at clustered spheres");
    const std::string scene = "10000 spheres, nine in ten of them in eight tight clusters";
    const sweep_cost c = sweep(t, scene, *bvh, set, rays_at_clusters(centres, 400, 3));
    t.report();
    check_budget(scene, 10000, c, 3, 12, reference_clustered);
}

TEST_CASE("bvh: long thin capsules in random directions cost no more than with the reference BVH", "[03][bvh][budget]") {
    probe_set set;
    auto bvh = make_bvh();
    random_needles(set, *bvh, 3000, 9);
    tally t("rays at needles");
    const std::string scene = "3000 needles (capsules 0.15 to 0.3 long) in random directions";
    const sweep_cost c = sweep(t, scene, *bvh, set, rays_through_cube(400, 13));
    t.report();
    // Needles overlap many boxes: the reference makes 26.7 primitive and 137.5 box tests
    // per ray here, so the formulas are wider; the reference's multiple is the same.
    check_budget(scene, 3000, c, 12, 20, reference_needles);
}

TEST_CASE("bvh: along a row of spheres only the first is tested: near-first - and boxes beyond the best hit are skipped", "[03][bvh][budget][essential]") {
    probe_set set;
    auto bvh = make_bvh();
    spheres_in_a_row(set, *bvh, 1000);
    std::vector<ray> rays;
    dice random(3);
    for (int k = 0; k < 100; ++k) {
        const double dx = random.uniform(-1e-4, 1e-4), dy = random.uniform(-1e-4, 1e-4);
        rays.push_back(ray(point(0.5 + dx, 0.5 + dy, -1), vector(0, 0, 1)));
        rays.push_back(ray(point(0.5 + dx, 0.5 + dy, 2), vector(0, 0, -1)));
    }
    tally t("rays along the row");
    const std::string scene = "1000 spheres in a row along z, rays along the row from either end";
    const sweep_cost c = sweep(t, scene, *bvh, set, rays);
    t.report();
    check_budget(scene, 1000, c, 1, 4, reference_row);
}

// --- the work behind the counts -----------------------------------------------------------------

// The budgets count tests; this checks that the counted tests are the work (see
// bvh_time_growth() in bvh_scenes.hh; every budget above checks it too).
TEST_CASE("bvh: the time a ray takes grows with log2(N) as its counted tests do - not with N", "[03][bvh][budget]") {
    const time_growth& g = bvh_time_growth();
    if (std::getenv("VL_MEASURE"))
        std::printf("MEASURE time per ray: %.3g us at 1000, %.3g us at 64000, growth %.3g; tests %.4g, %.4g; "
                    "other threads %.3g s, this one %.3g s\n",
                    1e6 * g.small.seconds, 1e6 * g.large.seconds, g.growth(), g.small.tests, g.large.tests, g.elsewhere,
                    g.small.here + g.large.here);
    vl::grading::margin("a ray took " + vl::grading::about(g.growth()) + " times as long at 64000 random spheres as at 1000 " +
                    "(at most " + vl::grading::about(most_time_growth) + "; a tree's grows a few times, a list's 64 or more)");
    VL_EXPECT(g.ok(), g.words());
}

// --- leaf_size, rebuilding, threads ------------------------------------------------------------

TEST_CASE("bvh: with leaf_size K a ray that hits one isolated child tests at most K children", "[03][bvh][leaf_size]") {
    // The spheres are 0.4 apart, so each ray, 0.01 beside a centre, enters that sphere's
    // box only, and passes 0.39 from its neighbours: outside them, inside the ball around
    // each one's box (0.25 sqrt(3) = 0.43). So a leaf that held more than K children would
    // show, even in a BVH that tests such a ball before it calls a child.
    tally t("rays at one child of a row");
    for (const int k : {1, 2, 3, 8}) {
        for (const bool from_file : {false, true}) {
            std::unique_ptr<rtab_component> bvh;
            if (from_file) {
                std::string text = "BVH { leaf_size " + std::to_string(k);
                for (int i = 0; i < 64; ++i) text += " PROBE { center " + num(0.4 * i) + " 0 0 radius 0.25 }";
                bvh = read_one(text + " }");
            } else {
                auto made = make_bvh(k);
                for (int i = 0; i < 64; ++i) made->insert(std::make_unique<probe_sphere>(point(0.4 * i, 0, 0), 0.25));
                bvh = std::move(made);
            }
            for (int i = 0; i < 64; i += 3) {
                const ray r(point(0.4 * i + 0.01, 5, 0.02), vector(0, -1, 0));
                intersection got;
                const cost c = measure([&] { got = bvh->intersect(r); });
                const double want = 5 - std::sqrt(0.0625 - 0.0001 - 0.0004);
                const bool hit = got.hit() && std::fabs(got.t - want) < 1e-9;
                t.check(hit && c.probe <= static_cast<std::uint64_t>(k), [&] {
                    return show(r) + " hits only the sphere around (" + num(0.4 * i) + ", 0, 0) of a row of 64 spheres "
                           "of radius 0.25 spaced 0.4 apart along x, in a BVH " + (from_file ? "read with" : "made with") +
                           " leaf_size " + std::to_string(k) + ": it should hit at t = " + num(want) + " and test at most " +
                           std::to_string(k) + " children (a leaf holds at most leaf_size); yours " +
                           (hit ? "hit" : "did not hit") + " and tested " + std::to_string(c.probe);
                });
            }
        }
    }
    t.report();
}

TEST_CASE("bvh: with leaf_size K - N children in one place make a tree of at least N / K leaves - each of whose boxes a ray through them tests", "[03][bvh][leaf_size]") {
    // N identical spheres: a ray through them enters every box. A tree whose leaves hold at
    // most K children has at least L = ceil(N / K) leaves, and a near-first walk tests the
    // root box and, when L > 1, the box of every leaf: at least 1 + L box tests, whatever
    // the tree's shape (a binary tree tests both children's boxes at each of its L - 1
    // inner nodes, 1 + 2 (L - 1); the reference's tree of eight subtrees per node, fewer).
    tally t("box tests through identical children");
    for (const int k : {1, 2, 3, 4, 8}) {
        for (const int n : {8, 12}) {
            for (const bool from_file : {false, true}) {
                std::unique_ptr<rtab_component> bvh;
                if (from_file) {
                    std::string text = "BVH { leaf_size " + std::to_string(k);
                    for (int i = 0; i < n; ++i) text += " PROBE { center 0 0 0 radius 1 }";
                    bvh = read_one(text + " }");
                } else {
                    auto made = make_bvh(k);
                    for (int i = 0; i < n; ++i) made->insert(std::make_unique<probe_sphere>(point(0, 0, 0), 1));
                    bvh = std::move(made);
                }
                const ray r(point(0.1, 0.2, 5), vector(0, 0, -1));
                intersection got;
                const cost c = measure([&] { got = bvh->intersect(r); });
                const std::uint64_t leaves = static_cast<std::uint64_t>((n + k - 1) / k);
                const std::uint64_t at_least = leaves > 1 ? 1 + leaves : 1;
                t.check(got.hit() && c.counts.bounding_volume_tests >= at_least &&
                            c.probe == static_cast<std::uint64_t>(n) && c.counts.primitive_tests == c.probe, [&] {
                    return show(r) + " passes through " + std::to_string(n) + " identical unit spheres at the origin in a BVH " +
                           (from_file ? "read with" : "made with") + " leaf_size " + std::to_string(k) + ": its tree has at least " +
                           std::to_string(leaves) + " leaves, so the ray should make at least " + std::to_string(at_least) +
                           " box tests and test each sphere once (" + std::to_string(n) + "); yours " +
                           (got.hit() ? "hit" : "did not hit") + " after " + std::to_string(c.counts.bounding_volume_tests) +
                           " box tests and " + std::to_string(c.probe) + " sphere tests";
                });
            }
        }
    }
    t.report();
}

TEST_CASE("bvh: insert() after a ray rebuilds the tree - and delete_all_children() empties it", "[03][bvh][rebuild][essential]") {
    tally t("a BVH changed between rays");
    namer names;
    auto bvh = make_bvh();
    auto a = std::make_unique<probe_sphere>(point(0, 0, -5), 1);
    const rtab_component* pa = a.get();
    names.name(pa, "the sphere around (0, 0, -5) of radius 1");
    bvh->insert(std::move(a));
    const ray r(point(0, 0, 0), vector(0, 0, -1));
    auto expect = [&](const std::string& when, const intersection& got, const rtab_component* object, double want) {
        t.check(object ? (got.object == object && std::fabs(got.t - want) < 1e-12) : got.is_miss(), [&] {
            return when + ": " + show(r) + " should " +
                   (object ? "hit " + names(object) + " at t = " + num(want) : std::string("miss")) +
                   "; yours returned " + show(got, names);
        });
    };
    expect("with one sphere", bvh->intersect(r), pa, 4);
    auto b = std::make_unique<probe_sphere>(point(0, 0, -2.5), 0.5);
    const rtab_component* pb = b.get();
    names.name(pb, "the sphere around (0, 0, -2.5) of radius 0.5");
    bvh->insert(std::move(b));
    expect("after inserting a nearer sphere", bvh->intersect(r), pb, 2);
    auto c = std::make_unique<probe_sphere>(point(30, 0, 0), 1);
    const rtab_component* pc = c.get();
    names.name(pc, "the sphere around (30, 0, 0) of radius 1");
    bvh->insert(std::move(c));
    const ray sideways(point(0, 0, 0), vector(1, 0, 0));
    const intersection side = bvh->intersect(sideways);
    t.check(side.object == pc && std::fabs(side.t - 29) < 1e-12, [&] {
        return "after inserting a sphere far outside the old box, " + show(sideways) + " should hit " + names(pc) +
               " at t = 29; yours returned " + show(side, names);
    });
    const point hi = bvh->max_point();
    t.check(hi.x == 31 && hi.y == 1 && hi.z == 1, [&] {
        return "after that insert, max_point() should be (31, 1, 1); yours is " + show(hi);
    });
    bvh->delete_all_children();
    expect("after delete_all_children()", bvh->intersect(r), nullptr, 0);
    t.check(unknown(bvh->min_point()) && unknown(bvh->max_point()), [&] {
        return "after delete_all_children() the box should be unknown (NaN_point); yours runs from " + show(bvh->min_point()) +
               " to " + show(bvh->max_point());
    });
    auto d = std::make_unique<probe_sphere>(point(0, 0, -8), 1);
    const rtab_component* pd = d.get();
    names.name(pd, "the sphere around (0, 0, -8) of radius 1");
    bvh->insert(std::move(d));
    expect("after deleting and inserting again", bvh->intersect(r), pd, 7);
    t.report();
}

TEST_CASE("bvh: four threads that intersect their first rays at the same time all get the nearest hits", "[03][bvh][threads]") {
    tally t("rays from four threads at once");
    for (int round = 0; round < 3; ++round) {
        probe_set set;
        auto bvh = make_bvh();
        random_spheres(set, *bvh, 3000, 500 + static_cast<unsigned>(round));
        const std::vector<ray> rays = rays_through_cube(400, 600 + static_cast<unsigned>(round));
        std::vector<intersection> got(rays.size());
        std::vector<int> mismatched(4, 0);
        std::vector<std::string> thrown(4);
        std::atomic<int> ready{0};
        std::vector<std::thread> threads;
        for (int k = 0; k < 4; ++k)
            threads.emplace_back([&, k] {
                ready.fetch_add(1);
                while (ready.load() < 4) std::this_thread::yield();
                try {
                    for (std::size_t i = static_cast<std::size_t>(k); i < rays.size(); i += 4) {
                        const cost c = measure([&] { got[i] = bvh->intersect(rays[i]); });
                        if (c.probe != c.counts.primitive_tests) ++mismatched[static_cast<std::size_t>(k)];
                    }
                } catch (const std::exception& e) {
                    thrown[static_cast<std::size_t>(k)] = e.what();
                } catch (...) {
                    thrown[static_cast<std::size_t>(k)] = "something that is not a std::exception";
                }
            });
        for (std::thread& th : threads) th.join();
        bool any_thrown = false;
        for (int k = 0; k < 4; ++k) {
            const std::string& what = thrown[static_cast<std::size_t>(k)];
            any_thrown = any_thrown || !what.empty();
            t.check(what.empty(), [&] { return "thread " + std::to_string(k) + ": intersect() threw " + what; });
        }
        if (any_thrown) continue;
        for (std::size_t i = 0; i < rays.size(); ++i)
            check_against_list(t, "BVH intersected by four threads at once", bvh.get(), set, rays[i], got[i], std::nullopt);
        for (int k = 0; k < 4; ++k)
            t.check(mismatched[static_cast<std::size_t>(k)] == 0, [&] {
                return "thread " + std::to_string(k) + ": on " + std::to_string(mismatched[static_cast<std::size_t>(k)]) +
                       " rays the children counted other numbers of tests than vl::counts() saw on that thread";
            });
    }
    t.report();
}

// --- box, contains, refusals -------------------------------------------------------------------

TEST_CASE("bvh: min_point() and max_point() are the union of the children's boxes - and contains() asks the children", "[03][bvh][bounds]") {
    tally t("the BVH's box");
    dice random(350);
    probe_set set;
    auto bvh = make_bvh();
    box_union children;
    for (int k = 0; k < 50; ++k) {
        const point c = random.in_cube(-3, 2);
        const double r = random.uniform(0.01, 0.7);
        auto p = k % 2 == 0 ? std::unique_ptr<probe>(std::make_unique<probe_sphere>(c, r))
                            : std::unique_ptr<probe>(std::make_unique<probe_cuboid>(c, c + vector(r, 2 * r, 0.5 * r)));
        children.add(*p);
        bvh->insert(std::move(p));
        if (k == 0 || k == 7 || k == 49)
            check_box_is(t, *bvh, children, "the BVH of the first " + std::to_string(k + 1) + " children");
    }
    const auto empty = make_bvh();
    t.check(unknown(empty->min_point()) && unknown(empty->max_point()), [&] {
        return "an empty BVH's box should be unknown (NaN_point); yours runs from " + show(empty->min_point()) + " to " +
               show(empty->max_point());
    });
    auto small = make_bvh();
    check_contains_of_two_spheres(t, *small, "BVH");
    t.report();
}

TEST_CASE("bvh: insert() refuses a child whose box is unknown and a null pointer - and make_bvh() a leaf_size outside 1 to 64", "[03][bvh][refusals][detail]") {
    tally t("refusals");
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    auto bvh = make_bvh();
    probe_set set;
    bvh->insert(set.add(std::make_unique<probe_sphere>(point(0, 0, -5), 1)));
    check_insert_refuses(t, *bvh, "BVH", {
        {"a PLANE", [] { return vl::stage02::make_plane(point(0, 0, 0), vector(0, 1, 0)); }},
        {"an empty LIST", [] { return std::make_unique<vl::object_list>(); }},
        {"an object whose min_point() is NaN_point",
         [] { return std::make_unique<probe_boxless>(vl::NaN_point, point(1, 1, 1)); }},
        {"an object whose box has a NaN coordinate",
         [nan] { return std::make_unique<probe_boxless>(point(0, 0, 0), point(1, nan, 1)); }},
        {"an object whose box is infinite", [inf] { return std::make_unique<probe_boxless>(point(-inf, 0, 0), point(1, 1, 1)); }},
        {"a null pointer", [] { return std::unique_ptr<rtab_component>(); }},
    }, [&](const bad_child& b, const std::string& message) {
        if (b.what == "a PLANE")
            t.check(message.find("PLANE") != std::string::npos && message.find("BVH") != std::string::npos &&
                        message.find("LIST") != std::string::npos,
                    [&] {
                        return "the refusal of a PLANE should name both types (BVH, PLANE) and say to put it beside the BVH in "
                               "a LIST; yours says: " + message;
                    });
    });
    for (const int k : {0, -1, 65, 1000}) {
        std::string message;
        t.check(throws_usage_error([&] { make_bvh(k); }, message),
                [&] { return "make_bvh(" + std::to_string(k) + ") should throw vl::usage_error; " + message; });
    }
    // After the refusals the BVH still holds its one sphere and finds it.
    const ray r(point(0, 0, 0), vector(0, 0, -1));
    const intersection got = bvh->intersect(r);
    check_against_list(t, "BVH after the refusals", bvh.get(), set, r, got, std::nullopt);
    for (const int k : {1, 64}) {
        auto ok = make_bvh(k);
        ok->insert(std::make_unique<probe_sphere>(point(0, 0, -5), 1));
        t.check(ok->intersect(r).hit(), [&] { return "a BVH made with leaf_size " + std::to_string(k) + " should work"; });
    }
    t.report();
}

// --- scene files ------------------------------------------------------------------------------

TEST_CASE("bvh: BVH { leaf_size K ... } is read from a scene file - and write() gives it back with every child in insertion order", "[03][bvh][scene_io]") {
    tally t("BVH in scene files");
    dice random(360);
    std::string text = "BVH { leaf_size 3\n";
    for (int k = 0; k < 30; ++k) {
        const point c = random.in_cube();
        text += "  PROBE { center " + num(c.x) + " " + num(c.y) + " " + num(c.z) + " radius " + num(random.uniform(0.02, 0.15)) +
                " id " + std::to_string(k) + " }\n";
    }
    text += "}";
    check_read_write_read(
        t, text, "BVH", 30,
        [&](const rtab_composite& bvh, const probe_set& set, int pass) {
            sweep(t, pass == 0 ? "a BVH read from a scene file" : "a BVH read back from what write() wrote", bvh, set,
                  mixed_rays(361, 200));
            return true;
        },
        [&](const std::string& written) {
            const std::vector<double> leaf = numbers_after(written, "leaf_size", 1);
            t.check(written.rfind("BVH", 0) == 0 && leaf.size() == 1 && leaf[0] == 3, [&] {
                return "write() of a BVH read with leaf_size 3 should start with \"BVH { leaf_size 3\"; yours wrote \"" +
                       written.substr(0, 200) + "\"";
            });
            std::size_t at = 0;
            for (int k = 0; k < 30; ++k) {
                const std::string id = " id " + std::to_string(k) + " ";
                const std::size_t found = written.find(id, at);
                if (!t.check(found != std::string::npos, [&] {
                        return "write() of a BVH should write every child in insertion order; child " + std::to_string(k) +
                               " is missing or out of order in \"" + written.substr(0, 300) + "...\"";
                    }))
                    break;
                at = found;
            }
        });
    t.report();
}

TEST_CASE("bvh: a bad BVH in a scene file is refused at the place of the fault", "[03][bvh][scene_io][detail]") {
    tally t("bad BVH blocks");
    check_refused(t, {{"BVH { leaf_size 0 SPHERE { } }", "hidden.ray_trace:1:17"},
                      {"BVH { leaf_size 65 }", "hidden.ray_trace:1:17"},
                      {"BVH { leaf_size 2.5 }", "hidden.ray_trace:1:17"},
                      {"BVH {\n  SPHERE { }\n  PLANE { }\n}", "hidden.ray_trace:3:3"},
                      {"BVH {\n  SPHERE { }\n  LIST { } }", "hidden.ray_trace:3:3"}});
    // A good one is read, with the default leaf_size 4.
    const auto good = read_one("BVH { SPHERE { center 0 0 -5 } SPHERE { center 3 0 -5 } }");
    const intersection got = good->intersect(ray(point(3, 0, 0), vector(0, 0, -1)));
    t.check(got.hit() && std::fabs(got.t - 4) < 1e-9, [&] {
        return "BVH { SPHERE { center 0 0 -5 } SPHERE { center 3 0 -5 } }: the ray from (3, 0, 0) towards (0, 0, -1) should "
               "hit at t = 4; yours returned t = " + num(got.t);
    });
    const std::vector<double> leaf = numbers_after(text_of(*good), "leaf_size", 1);
    t.check(leaf.size() == 1 && leaf[0] == 4, [&] {
        return "a BVH read without leaf_size should write leaf_size 4 (the default); yours wrote \"" +
               text_of(*good).substr(0, 100) + "\"";
    });
    t.report();
}

// --- many children with the same centre --------------------------------------------------------

TEST_CASE("bvh: many children with the same centre still make a tree and give the nearest hit", "[03][bvh][degenerate][essential]") {
    tally t("children with the same centre");
    probe_set set;
    auto bvh = make_bvh(2);
    for (int k = 0; k < 1500; ++k) bvh->insert(set.add(std::make_unique<probe_sphere>(point(0.5, 0.5, 0.5), 0.2)));
    for (int k = 0; k < 300; ++k)
        bvh->insert(set.add(std::make_unique<probe_sphere>(point(0.25, 0.25, 0.25), 0.001 + 0.0005 * k)));
    for (int k = 0; k < 300; ++k)
        bvh->insert(set.add(std::make_unique<probe_cuboid>(point(0.7, 0.1, 0.1), point(0.9, 0.2, 0.3))));
    check_rays(t, "2100 children at three centres", *bvh, set, mixed_rays(370, 120));
    // A BVH of leaf_size 1 over identical spheres only.
    probe_set same;
    auto ones = make_bvh(1);
    for (int k = 0; k < 500; ++k) ones->insert(same.add(std::make_unique<probe_sphere>(point(0, 0, 0), 1)));
    check_rays(t, "500 identical unit spheres (leaf_size 1)", *ones, same,
               {ray(point(0, 0, 5), vector(0, 0, -1)), ray(point(0.5, 0.5, 0), vector(1, 0, 0)), ray(point(3, 3, 3), vector(1, 1, 1))});
    t.report();
}
