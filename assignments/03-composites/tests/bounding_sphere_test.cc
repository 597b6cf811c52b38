// Public tests of the bounding sphere (stage_03.hh, bounding_sphere.cc). Run them with
// `build/student/stage_03_public_test "[boundsph]"`. The children are the tests' own
// spheres (tests/test_support.hh), which count how often they are intersected.
#include "vl/catch.hh"

#include <cmath>
#include <vector>

#include "stage_02.hh"
#include "test_support.hh"
#include "vl/object_list.hh"

using namespace vl;
using namespace vl::stage03;
using namespace vl::stage03::testing;

TEST_CASE("bounding sphere: gives the same nearest hit and leaf as a LIST of the same spheres",
          "[03][boundsph][essential]") {
    random_numbers random(21);
    auto bs = make_bounding_sphere();
    std::vector<test_sphere*> spheres;
    for (int k = 0; k < 30; ++k) spheres.push_back(add_sphere(*bs, random.in_box(-2, 2), random.uniform(0.1, 0.6), k));
    const auto list = list_of(spheres);
    // Rays from outside aimed into the cluster, and rays from anywhere in any direction
    // (many start inside the bounding sphere, some inside a child).
    std::vector<ray> rays = rays_into(random, 400, -2, 2);
    for (const ray& r : random_rays(random, 400, -4, 4)) rays.push_back(r);
    const std::string diff = differences_from_list(*bs, *list, rays);
    INFO(diff);
    CHECK(diff.empty());
}

TEST_CASE("bounding sphere: returns the nearest hit - not the first child's", "[03][boundsph]") {
    // Four spheres in a row along -z, inserted far ones first: the ray from the origin
    // along -z hits all four; the nearest (z = -2, radius 0.5) is entered at t = 1.5.
    auto bs = make_bounding_sphere();
    for (int k = 3; k >= 0; --k) add_sphere(*bs, point(0, 0, -2 - 2 * k), 0.5, k);
    const ray r(point(0, 0, 0), vector(0, 0, -1));
    const intersection i = bs->intersect(r);
    INFO(show(r) << " gave " << show(i));
    REQUIRE(hit_sphere(i) != nullptr);
    CHECK(hit_sphere(i)->id() == 0);
    CHECK(i.t == Approx(1.5).epsilon(1e-12));
}

TEST_CASE("bounding sphere: a ray that misses its sphere costs one bounding-volume test and no child test",
          "[03][boundsph][essential]") {
    auto bs = make_bounding_sphere();
    std::vector<test_sphere*> spheres;
    for (int k = 0; k < 5; ++k) spheres.push_back(add_sphere(*bs, point(k - 2.0, 0.3 * k, 0), 0.5, k));
    random_numbers random(22);
    for (int k = 0; k < 50; ++k) {
        // Rays that pass at least 6 units from the cluster (its sphere has radius < 3).
        const vector d = random.direction();
        const ray r(point(0, 0, 0) + 6.5 * perpendicular(d) - 20 * d, d);
        intersection i;
        const intersection_counts cost = cost_of([&] { i = bs->intersect(r); });
        INFO(show(r) << " passes 6.5 from the centre of the cluster; it cost " << show(cost) << " and gave "
                     << show(i));
        CHECK(i.is_miss());
        CHECK(cost.bounding_volume_tests == 1);
        CHECK(cost.primitive_tests == 0);
    }
    std::uint64_t child_tests = 0;
    for (const test_sphere* s : spheres) child_tests += s->calls();
    CHECK(child_tests == 0);
}

TEST_CASE("bounding sphere: a ray that enters the sphere and hits no child gets composite_only",
          "[03][boundsph][essential]") {
    // Two small spheres at x = -1 and x = 1: the ray down the z axis passes between them,
    // inside the bounding sphere (radius about 1.23 around the origin).
    auto bs = make_bounding_sphere();
    test_sphere* a = add_sphere(*bs, point(-1, 0, 0), 0.2, 1);
    test_sphere* b = add_sphere(*bs, point(1, 0, 0), 0.2, 2);
    const ray r(point(0, 0, 5), vector(0, 0, -1));
    intersection i;
    const intersection_counts cost = cost_of([&] { i = bs->intersect(r); });
    INFO(show(r) << " gave " << show(i) << " and cost " << show(cost));
    CHECK(i.is_composite_only());
    CHECK(i.object == bs.get());  // rule 2: the bounding sphere itself, t == 0
    CHECK(i.t == 0);
    CHECK(cost.bounding_volume_tests == 1);
    CHECK(a->calls() == 1);  // every child is tested once
    CHECK(b->calls() == 1);

    // A child's own composite_only is not a hit either: the answer is still this sphere's.
    auto outer = make_bounding_sphere();
    outer->insert(std::make_unique<test_shell>(point(0, 0, 0), 1));
    const intersection j = outer->intersect(r);
    INFO("a bounding sphere around a composite that answers composite_only gave " << show(j));
    CHECK(j.is_composite_only());
    CHECK(j.object == outer.get());
}

TEST_CASE("bounding sphere: its sphere is around the children's boxes - not their centres", "[03][boundsph]") {
    // A big sphere (radius 3 at the origin) and a small one (radius 0.1 at x = 4). A
    // sphere around the two centres (centre x = 2, radius 2) would cut off the big
    // sphere's left half; the ray down -z at x = -2.5 must still hit it.
    auto bs = make_bounding_sphere();
    add_sphere(*bs, point(0, 0, 0), 3, 1);
    add_sphere(*bs, point(4, 0, 0), 0.1, 2);
    const ray r(point(-2.5, 0, 10), vector(0, 0, -1));
    const intersection i = bs->intersect(r);
    INFO(show(r) << " gave " << show(i));
    REQUIRE(hit_sphere(i) != nullptr);
    CHECK(hit_sphere(i)->id() == 1);
    CHECK(i.t == Approx(10 - std::sqrt(9 - 6.25)).epsilon(1e-12));
}

TEST_CASE("bounding sphere: its sphere is the smallest around the box of the children", "[03][boundsph]") {
    // The children's box is [-1, 3] x [-1, 1] x [-2, 2]: centre (1, 0, 0), half diagonal
    // R = sqrt(4^2 + 2^2 + 4^2) / 2 = 3. Rays that pass 1% outside that sphere must cost
    // one test and no child test; rays 1% inside it enter it (composite_only: they pass
    // far from the two small spheres in the box's corners).
    auto bs = make_bounding_sphere();
    add_sphere(*bs, point(-0.5, -0.5, -1.5), 0.5, 1);
    add_sphere(*bs, point(2.5, 0.5, 1.5), 0.5, 2);
    const point centre(1, 0, 0);
    const double radius = 3;
    // Directions along the y axis pass beside both spheres at the sides +-x of the centre.
    for (const double factor : {1.01, 0.99}) {
        for (const vector side : {vector(0, 0, 1), vector(0, 0, -1)}) {
            const ray r(centre + factor * radius * side - vector(0, 10, 0), vector(0, 1, 0));
            intersection i;
            const intersection_counts cost = cost_of([&] { i = bs->intersect(r); });
            INFO(show(r) << " passes " << factor << " R from the centre (1, 0, 0), R = 3; it gave " << show(i)
                         << " and cost " << show(cost));
            if (factor > 1) {
                CHECK(i.is_miss());
                CHECK(cost.primitive_tests == 0);
            } else {
                CHECK(i.is_composite_only());
                CHECK(cost.primitive_tests == 2);
            }
        }
    }
}

TEST_CASE("bounding sphere: min_point and max_point are the union of the children's boxes", "[03][boundsph]") {
    auto bs = make_bounding_sphere();
    add_sphere(*bs, point(1, 2, 3), 0.5);
    INFO("one sphere of radius 0.5 at (1, 2, 3): min_point " << show(bs->min_point()) << ", max_point "
                                                             << show(bs->max_point()));
    CHECK(bs->min_point() == point(0.5, 1.5, 2.5));
    CHECK(bs->max_point() == point(1.5, 2.5, 3.5));
    add_sphere(*bs, point(-2, 4, 0), 1);
    add_sphere(*bs, point(0, 0, 10), 0.25);
    INFO("after two more, radius 1 at (-2, 4, 0) and radius 0.25 at (0, 0, 10): min_point "
         << show(bs->min_point()) << ", max_point " << show(bs->max_point()));
    CHECK(bs->min_point() == point(-3, -0.25, -1));
    CHECK(bs->max_point() == point(1.5, 5, 10.25));
}

TEST_CASE("bounding sphere: contains is true inside a child and false elsewhere", "[03][boundsph]") {
    auto bs = make_bounding_sphere();
    add_sphere(*bs, point(0, 0, 0), 1);
    add_sphere(*bs, point(3, 0, 0), 0.5);
    CHECK(bs->contains(point(0.5, 0.5, 0)));
    CHECK(bs->contains(point(3.2, 0, 0.1)));
    CHECK_FALSE(bs->contains(point(2, 0, 0)));  // between the children, inside the bound
    CHECK_FALSE(bs->contains(point(0, 5, 0)));
    // Both bounds grew as the spheres came in, and a ray now tests them.
    CHECK(bs->intersect(ray(point(3, 0, 5), vector(0, 0, -1))).t == Approx(4.5).epsilon(1e-12));
}

TEST_CASE("bounding sphere: refuses a PLANE - an empty LIST and a null pointer", "[03][boundsph]") {
    auto bs = make_bounding_sphere();
    add_sphere(*bs, point(0, 0, -5), 1, 1);

    const std::string plane =
        usage_error_of([&] { bs->insert(stage02::make_plane(point(0, -1, 0), vector(0, 1, 0))); });
    INFO("inserting a PLANE: " << plane);
    CHECK_THAT(plane, Catch::Contains("PLANE") && Catch::Contains("BOUNDSPH") && Catch::Contains("LIST"));
    const std::string empty = usage_error_of([&] { bs->insert(std::make_unique<object_list>()); });
    INFO("inserting an empty LIST: " << empty);
    CHECK(empty != "(no error)");
    CHECK(usage_error_of([&] { bs->insert(nullptr); }) != "(no error)");

    // The refusals changed nothing: one child, its box, its hit.
    CHECK(bs->num_children() == 1);
    CHECK(bs->min_point() == point(-1, -1, -6));
    CHECK(bs->intersect(ray(point(0, 0, 0), vector(0, 0, -1))).t == Approx(4).epsilon(1e-12));
}

TEST_CASE("bounding sphere: an empty one misses every ray and costs no bound test", "[03][boundsph][detail]") {
    auto bs = make_bounding_sphere();
    intersection i;
    const intersection_counts cost = cost_of([&] { i = bs->intersect(ray(point(0, 0, 0), vector(0, 0, -1))); });
    INFO("an empty BOUNDSPH gave " << show(i) << " and cost " << show(cost));
    CHECK(i.is_miss());
    CHECK(cost.bounding_volume_tests == 0);
    CHECK(is_nan(bs->min_point()));
    // After delete_all_children() it is empty again.
    add_sphere(*bs, point(0, 0, -3), 1);
    CHECK(bs->intersect(ray(point(0, 0, 0), vector(0, 0, -1))).hit());
    bs->delete_all_children();
    CHECK(bs->intersect(ray(point(0, 0, 0), vector(0, 0, -1))).is_miss());
}

TEST_CASE("scene: BOUNDSPH reads its children and writes them back", "[03][boundsph][scene]") {
    const std::string text =
        "BOUNDSPH { SPHERE { center 0 0 -4 radius 1 }  SPHERE { center 1.5 0.25 -6 radius 0.75 color 1 0 0 }"
        "  BOUNDSPH { SPHERE { center -2 1 -5 radius 0.5 } } }";
    const auto first = read_object(text);
    REQUIRE(first->type_name() == "BOUNDSPH");
    const std::string out = written(*first);
    INFO("read: " << text << "\nwritten: " << out);
    const auto second = read_object(out);
    CHECK(written(*second) == out);
    const intersection i = first->intersect(ray(point(0, 0, 0), vector(0, 0, -1)));
    CHECK(i.t == Approx(3).epsilon(1e-12));
    CHECK(first->min_point() == point(-2.5, -1, -6.75));
    const std::string diff = different_hits(*first, *second, 300, -3, 3);
    INFO(diff);
    CHECK(diff.empty());
}

TEST_CASE("scene: a PLANE inside BOUNDSPH is refused at the PLANE's place in the file", "[03][boundsph][scene]") {
    const std::string e = read_error("BOUNDSPH {\n  SPHERE { }\n  PLANE { }\n}");
    INFO(e);
    CHECK_THAT(e, Catch::Contains("test.ray_trace:3:3") && Catch::Contains("PLANE"));
}
