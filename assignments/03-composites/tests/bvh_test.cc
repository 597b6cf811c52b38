// Public tests of the bounding volume hierarchy (stage_03.hh, bvh.cc). Run them with
// `build/student/stage_03_public_test "[bvh]"`. The children are the tests' own spheres
// (tests/test_support.hh); the answer key is a LIST of copies of them.
#include "vl/catch.hh"

#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>
#include <vector>

#include "stage_02.hh"
#include "test_support.hh"
#include "vl/object_list.hh"

using namespace vl;
using namespace vl::stage03;
using namespace vl::stage03::testing;

namespace {

/// `n` spheres of radius 0.01 to `max_radius` at random in the unit cube.
std::vector<test_sphere*> random_spheres(rtab_composite& bvh, random_numbers& random, int n, double max_radius) {
    std::vector<test_sphere*> spheres;
    for (int k = 0; k < n; ++k)
        spheres.push_back(add_sphere(bvh, random.in_box(0, 1), random.uniform(0.01, max_radius), k));
    return spheres;
}

/// A row of 64 spheres of radius 0.4 at x = 0, 1, ..., 63 on the x axis, inserted in a
/// shuffled order (so the order of insertion cannot help).
std::unique_ptr<rtab_composite> row_of_spheres(int leaf_size) {
    auto bvh = make_bvh(leaf_size);
    std::vector<int> xs(64);
    for (int k = 0; k < 64; ++k) xs[static_cast<std::size_t>(k)] = k;
    std::shuffle(xs.begin(), xs.end(), std::mt19937(5));
    for (const int x : xs) add_sphere(*bvh, point(x, 0, 0), 0.4, x);
    return bvh;
}

}  // namespace

TEST_CASE("bvh: gives the same nearest hits and leaves as a LIST of the same spheres", "[03][bvh][essential]") {
    for (const int leaf_size : {1, 4, 16}) {
        random_numbers random(61);
        auto bvh = make_bvh(leaf_size);
        const auto list = list_of(random_spheres(*bvh, random, 300, 0.08));
        std::vector<ray> rays = rays_into(random, 400, 0, 1);
        for (const ray& r : random_rays(random, 400, -0.5, 1.5)) rays.push_back(r);
        const std::string diff = differences_from_list(*bvh, *list, rays);
        INFO("300 random spheres in the unit cube, leaf_size " << leaf_size << ": " << diff);
        CHECK(diff.empty());
    }
}

TEST_CASE("bvh: a ray that misses the root box costs one box test and no child test", "[03][bvh][essential]") {
    random_numbers random(62);
    auto bvh = make_bvh();
    const std::vector<test_sphere*> spheres = random_spheres(*bvh, random, 200, 0.05);
    bvh->intersect(ray(point(0.5, 0.5, 5), vector(0, 0, -1)));  // the first ray builds the tree
    for (int k = 0; k < 50; ++k) {
        // Rays in the plane z = 1.5, above the root box (every sphere is below z = 1.05).
        const ray r(point(random.uniform(-2, 3), random.uniform(-2, 3), 1.5),
                    vector(random.uniform(-1, 1), random.uniform(-1, 1), 0));
        intersection i;
        const intersection_counts cost = cost_of([&] { i = bvh->intersect(r); });
        INFO(show(r) << " passes above every sphere; it gave " << show(i) << " and cost " << show(cost));
        CHECK(i.is_miss());
        CHECK(cost.bounding_volume_tests == 1);
        CHECK(cost.primitive_tests == 0);
    }
}

TEST_CASE("bvh: a ray that enters the root box and hits nothing gets composite_only", "[03][bvh]") {
    // Two spheres at (0, 0, 0) and (4, 0, 0): the ray down -z at x = 2 enters the root
    // box between them and hits neither.
    auto bvh = make_bvh(1);
    add_sphere(*bvh, point(0, 0, 0), 0.5, 1);
    add_sphere(*bvh, point(4, 0, 0), 0.5, 2);
    const ray r(point(2, 0, 5), vector(0, 0, -1));
    const intersection i = bvh->intersect(r);
    INFO(show(r) << " gave " << show(i));
    CHECK(i.is_composite_only());
    CHECK(i.object == bvh.get());
    // And a ray that hits one of them gets that sphere, not the BVH.
    const intersection j = bvh->intersect(ray(point(4, 0, 5), vector(0, 0, -1)));
    INFO("the ray down -z at x = 4 gave " << show(j));
    REQUIRE(hit_sphere(j) != nullptr);
    CHECK(hit_sphere(j)->id() == 2);
    CHECK(j.t == Approx(4.5).epsilon(1e-12));
}

TEST_CASE("bvh: on 512 random spheres a ray costs at most 3 log2 N sphere tests and 12 log2 N box tests",
          "[03][bvh][essential]") {
    // The budget of the contract for N small spheres at random in the unit cube, averaged
    // over rays from outside through the cube. A LIST tests all 512 on every ray.
    const int n = 512;
    random_numbers random(63);
    auto bvh = make_bvh();
    random_spheres(*bvh, random, n, 0.02);
    const std::vector<ray> rays = rays_into(random, 2000, 0, 1);
    bvh->intersect(rays.front());  // the first ray builds the tree
    const intersection_counts cost = cost_of([&] {
        for (const ray& r : rays) bvh->intersect(r);
    });
    const double per_ray_primitive = static_cast<double>(cost.primitive_tests) / static_cast<double>(rays.size());
    const double per_ray_box = static_cast<double>(cost.bounding_volume_tests) / static_cast<double>(rays.size());
    const double log2n = std::log2(n);
    INFO("per ray: " << per_ray_primitive << " sphere tests (budget 3 log2 N = " << 3 * log2n << "), " << per_ray_box
                     << " box tests (budget 12 log2 N = " << 12 * log2n << ")");
    CHECK(per_ray_primitive <= 3 * log2n);
    CHECK(per_ray_box <= 12 * log2n);
}

TEST_CASE("bvh: walks near-first and stops at the first hit along a row of spheres", "[03][bvh][essential]") {
    // 64 spheres in a row; a ray along the row hits the first one. Visiting the nearer
    // child first and skipping boxes that start beyond the hit costs a few tests; visiting
    // both children always, or the far one first, costs dozens.
    for (const int leaf_size : {1, 4}) {
        const auto bvh = row_of_spheres(leaf_size);
        struct along {
            ray r;
            int first_id;
            double t;
        };
        const along rays[] = {{ray(point(-5, 0, 0), vector(1, 0, 0)), 0, 4.6},
                              {ray(point(70, 0, 0), vector(-1, 0, 0)), 63, 6.6},
                              {ray(point(31.5, 0, 0), vector(1, 0, 0)), 32, 0.1},
                              {ray(point(31.5, 0, 0), vector(-1, 0, 0)), 31, 0.1}};
        for (const along& a : rays) {
            intersection i;
            const intersection_counts cost = cost_of([&] { i = bvh->intersect(a.r); });
            INFO("64 spheres of radius 0.4 at x = 0 ... 63, leaf_size " << leaf_size << ": " << show(a.r) << " gave "
                                                                        << show(i) << " and cost " << show(cost));
            REQUIRE(hit_sphere(i) != nullptr);
            CHECK(hit_sphere(i)->id() == a.first_id);
            CHECK(i.t == Approx(a.t).epsilon(1e-9));
            CHECK(cost.primitive_tests <= 8);
            CHECK(cost.bounding_volume_tests <= 36);  // 6 log2 64
        }
    }
}

TEST_CASE("bvh: min_point - max_point and contains cover every child", "[03][bvh]") {
    auto bvh = make_bvh(2);
    add_sphere(*bvh, point(1, 2, 3), 0.5);
    add_sphere(*bvh, point(-2, 4, 0), 1);
    add_sphere(*bvh, point(0, 0, 10), 0.25);
    INFO("min_point " << show(bvh->min_point()) << ", max_point " << show(bvh->max_point()));
    CHECK(bvh->min_point() == point(-3, -0.25, -1));
    CHECK(bvh->max_point() == point(1.5, 5, 10.25));
    CHECK(bvh->contains(point(-2, 4.5, 0)));
    CHECK(bvh->contains(point(0, 0, 10.1)));
    CHECK_FALSE(bvh->contains(point(0, 0, 5)));
    CHECK(bvh->intersect(ray(point(0, 0, 0), vector(0, 0, 1))).t == Approx(9.75).epsilon(1e-12));
}

TEST_CASE("bvh: refuses a PLANE - an empty LIST - a null pointer and a bad leaf_size", "[03][bvh][detail]") {
    auto bvh = make_bvh();
    add_sphere(*bvh, point(0, 0, -5), 1, 1);
    const std::string plane =
        usage_error_of([&] { bvh->insert(stage02::make_plane(point(0, -1, 0), vector(0, 1, 0))); });
    INFO("inserting a PLANE: " << plane);
    CHECK_THAT(plane, Catch::Contains("PLANE") && Catch::Contains("LIST"));
    CHECK(usage_error_of([&] { bvh->insert(std::make_unique<object_list>()); }) != "(no error)");
    CHECK(usage_error_of([&] { bvh->insert(nullptr); }) != "(no error)");
    CHECK(bvh->num_children() == 1);
    CHECK(bvh->intersect(ray(point(0, 0, 0), vector(0, 0, -1))).t == Approx(4).epsilon(1e-12));
    CHECK_THROWS_AS(make_bvh(0), usage_error);
    CHECK_THROWS_AS(make_bvh(65), usage_error);
}

TEST_CASE("bvh: many children with the same centre still give a tree", "[03][bvh]") {
    // 100 spheres around one centre, radii 0.1 to 1.09, and 50 copies of one sphere: the
    // centres cannot be split, so the children must be split by count.
    auto bvh = make_bvh(1);
    for (int k = 0; k < 100; ++k) add_sphere(*bvh, point(1, 1, 1), 0.1 + 0.01 * k, k);
    for (int k = 0; k < 50; ++k) add_sphere(*bvh, point(5, 1, 1), 0.5, 100 + k);
    const intersection i = bvh->intersect(ray(point(1, 1, 5), vector(0, 0, -1)));
    INFO("the ray down -z onto the concentric spheres gave " << show(i));
    REQUIRE(hit_sphere(i) != nullptr);
    CHECK(hit_sphere(i)->id() == 99);  // the biggest, radius 1.09
    CHECK(i.t == Approx(4 - 1.09).epsilon(1e-12));
    const intersection j = bvh->intersect(ray(point(5, 1, 5), vector(0, 0, -1)));
    INFO("the ray down -z onto the 50 copies gave " << show(j));
    REQUIRE(hit_sphere(j) != nullptr);
    CHECK(j.t == Approx(3.5).epsilon(1e-12));
}

TEST_CASE("bvh: inserting or deleting after the first ray rebuilds the tree", "[03][bvh]") {
    auto bvh = make_bvh();
    const ray r(point(0, 0, 0), vector(0, 0, -1));
    add_sphere(*bvh, point(0, 0, -10), 1, 1);
    CHECK(bvh->intersect(r).t == Approx(9).epsilon(1e-12));
    add_sphere(*bvh, point(0, 0, -4), 1, 2);  // nearer, and outside the first tree's box
    const intersection i = bvh->intersect(r);
    INFO("after inserting a nearer sphere: " << show(i));
    REQUIRE(hit_sphere(i) != nullptr);
    CHECK(hit_sphere(i)->id() == 2);
    CHECK(i.t == Approx(3).epsilon(1e-12));
    CHECK(bvh->min_point() == point(-1, -1, -11));
    CHECK(bvh->max_point() == point(1, 1, -3));
    bvh->delete_all_children();
    CHECK(bvh->intersect(r).is_miss());
    CHECK(is_nan(bvh->min_point()));
}

TEST_CASE("scene: BVH reads leaf_size and its children and writes them back", "[03][bvh][scene]") {
    std::string text = "BVH { leaf_size 2\n";
    for (int k = 0; k < 12; ++k)
        text += "  SPHERE { center " + std::to_string(k % 4) + " " + std::to_string(k / 4) + " -5  radius 0.3 }\n";
    text += "}";
    const auto first = read_object(text);
    const std::string out = written(*first);
    INFO("read:\n" << text << "\nwritten:\n" << out);
    // Its first words, however it spaces them: BVH { leaf_size 2
    std::istringstream words(out);
    std::string w[4];
    words >> w[0] >> w[1] >> w[2] >> w[3];
    CHECK((w[0] == "BVH" && w[1] == "{" && w[2] == "leaf_size" && w[3] == "2"));
    const auto second = read_object(out);
    CHECK(written(*second) == out);
    CHECK(first->intersect(ray(point(3, 2, 0), vector(0, 0, -1))).t == Approx(4.7).epsilon(1e-12));
    CHECK(first->min_point() == point(-0.3, -0.3, -5.3));
    const std::string diff = different_hits(*first, *second, 300, -1, 4);
    INFO(diff);
    CHECK(diff.empty());
}

TEST_CASE("scene: a PLANE or a bad leaf_size in a BVH is refused at its place", "[03][bvh][scene][detail]") {
    const std::string plane = read_error("BVH {\n  SPHERE { }\n  PLANE { }\n}");
    INFO(plane);
    CHECK_THAT(plane, Catch::Contains("test.ray_trace:3:3") && Catch::Contains("PLANE"));
    CHECK_THAT(read_error("BVH { leaf_size 0 SPHERE { } }"), Catch::Contains("test.ray_trace:1:17"));
    // A good one is read and hit.
    CHECK(read_object("BVH { SPHERE { center 0 0 -3 } }")->intersect(ray()).t == Approx(2).epsilon(1e-12));
}
