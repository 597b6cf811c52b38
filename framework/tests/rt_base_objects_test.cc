// Tests of the ray, intersection rules, counters and the composite bases.
#include "vl/catch.hh"
#include <sstream>
#include <thread>

#include "support/probes.hh"
#include "vl/bounds.hh"
#include "vl/error.hh"
#include "vl/object_list.hh"

using namespace vl;
using vl::test::bounded_probe_list;
using vl::test::probe;

TEST_CASE("ray: the direction is stored as a unit vector", "[rt][ray]") {
    const ray r(point(1, 2, 3), vector(0, 0, -10));
    CHECK(r.direction() == vector(0, 0, -1));
    CHECK(r.origin() == point(1, 2, 3));
}

TEST_CASE("ray: t_point, t * r and r * t are the point at distance t", "[rt][ray]") {
    const ray r(point(1, 0, 0), vector(0, 3, 4));
    const point p = r.t_point(5);
    CHECK(p.x == Approx(1));
    CHECK(p.y == Approx(3));
    CHECK(p.z == Approx(4));
    CHECK((2.0 * r) == r.t_point(2));
    CHECK((r * 2.0) == r.t_point(2));
}

TEST_CASE("ray: a matrix moves the origin and turns the direction, which stays unit", "[rt][ray]") {
    const matrix m(2, 0, 0, 1,
                   0, 2, 0, 2,
                   0, 0, 2, 3,
                   0, 0, 0, 1);
    const ray r = m * ray(point(0, 0, 0), vector(1, 0, 0));
    CHECK(r.origin() == point(1, 2, 3));
    CHECK(r.direction() == vector(1, 0, 0));
}

TEST_CASE("ray: a zero direction is NaN, visibly undefined", "[rt][ray]") {
    const ray r(point(0, 0, 0), vector(0, 0, 0));
    CHECK(is_nan(r.direction()));
}

TEST_CASE("intersection: the three cases of the thesis's rules", "[rt][intersection]") {
    const probe leaf(1);
    const bounded_probe_list composite;
    CHECK(intersection::none().is_miss());
    CHECK_FALSE(intersection::none().hit());
    CHECK(intersection::at(2, &leaf).hit());
    CHECK_FALSE(intersection::at(2, &leaf).is_miss());
    CHECK(intersection::composite_only(&composite).is_composite_only());
    CHECK_FALSE(intersection::composite_only(&composite).hit());
    CHECK(intersection::composite_only(&composite).t == 0);
}

TEST_CASE("intersection: nearer_than prefers the smaller positive t and any hit over none", "[rt][intersection]") {
    const probe a(1), b(2);
    CHECK(intersection::at(1, &a).nearer_than(intersection::at(2, &b)));
    CHECK_FALSE(intersection::at(2, &b).nearer_than(intersection::at(1, &a)));
    CHECK(intersection::at(2, &b).nearer_than(intersection::none()));
    CHECK_FALSE(intersection::none().nearer_than(intersection::at(2, &b)));
}

TEST_CASE("rtab_component: the thesis's defaults", "[rt][component]") {
    probe p(1);
    const rtab_component& c = p;
    CHECK_FALSE(c.rtab_component::contains(point(0, 0, 0)));
    CHECK(is_nan(c.rtab_component::min_point()));
    CHECK(is_nan(c.rtab_component::max_point()));
    CHECK(is_nan(c.rtab_component::normal(point(0, 0, 0))));
    CHECK(c.rtab_component::zero_t() > 0);
    CHECK(c.rtab_component::zero_t() < 1e-3);
    // Surface physics: absent means "contributes nothing".
    CHECK(c.rtab_component::kdr() == 0);
    CHECK(c.rtab_component::ksr() == 0);
    CHECK(c.rtab_component::kdt() == 0);
    CHECK(c.rtab_component::kst() == 0);
    CHECK(c.rtab_component::ior() == 1);
    CHECK_FALSE(c.is_composite());
}

TEST_CASE("rtab_component: a leaf refuses insert and delete_all_children with a clear error", "[rt][component]") {
    probe p(1);
    CHECK_THROWS_WITH(p.insert(std::make_unique<probe>(2)), Catch::Contains("PROBE cannot hold other objects"));
    CHECK_THROWS_AS(p.delete_all_children(), usage_error);
    CHECK_THROWS_WITH(p.delete_all_children(), Catch::Contains("PROBE has no children"));
}

TEST_CASE("rtab_composite: owns its children and deletes them on request", "[rt][composite]") {
    object_list list;
    CHECK(list.is_composite());
    list.insert(std::make_unique<probe>(3));
    list.insert(std::make_unique<probe>(1));
    CHECK(list.num_children() == 2);
    list.delete_all_children();
    CHECK(list.num_children() == 0);
    CHECK_THROWS_AS(list.insert(nullptr), usage_error);
}

TEST_CASE("rtab_composite: bounds are the union of the children's, unknown if any is unknown", "[rt][composite]") {
    object_list list;
    CHECK(is_nan(list.min_point()));
    list.insert(std::make_unique<probe>(3));
    list.insert(std::make_unique<probe>(5));
    CHECK(list.min_point() == point(-1, -1, -1));
    CHECK(list.max_point() == point(5, 1, 1));
    auto inner = std::make_unique<object_list>();  // empty: its box is unknown
    list.insert(std::move(inner));
    CHECK(is_nan(list.max_point()));
}

TEST_CASE("object_list: returns the nearest hit among its children", "[rt][composite]") {
    object_list list;
    list.insert(std::make_unique<probe>(3));
    list.insert(std::make_unique<probe>(1.5));
    list.insert(std::make_unique<probe>(0));  // a miss
    list.insert(std::make_unique<probe>(2));
    const intersection i = list.intersect(ray(point(0, 0, 0), vector(0, 0, 1)));
    REQUIRE(i.hit());
    CHECK(i.t == 1.5);
    CHECK(dynamic_cast<const probe*>(i.object)->t() == 1.5);
}

TEST_CASE("object_list: all children missing is a miss, not a composite hit", "[rt][composite]") {
    object_list list;
    list.insert(std::make_unique<probe>(0));
    CHECK(list.intersect(ray(point(0, 0, 0), vector(0, 0, 1))).is_miss());
}

TEST_CASE("object_list: a hit at or below zero_t is not a hit", "[rt][composite]") {
    object_list list;
    list.insert(std::make_unique<probe>(rtab_component::default_zero_t / 2));
    CHECK_FALSE(list.intersect(ray(point(0, 0, 0), vector(0, 0, 1))).hit());
}

TEST_CASE("counters: a composite of probes counts exactly what it calls", "[rt][counters]") {
    auto inner = std::make_unique<bounded_probe_list>();
    inner->insert(std::make_unique<probe>(0));  // miss
    inner->insert(std::make_unique<probe>(0));  // miss
    object_list root;
    root.insert(std::make_unique<probe>(4));
    root.insert(std::move(inner));  // entered, nothing hit: composite-only
    root.insert(std::make_unique<probe>(0));  // miss

    clear_counts();
    const intersection i = root.intersect(ray(point(0, 0, 0), vector(1, 0, 0)));
    CHECK(i.t == 4);
    const intersection_counts& c = counts();
    CHECK(c.composite_tests == 2);   // root and inner
    CHECK(c.primitive_tests == 4);   // 1 + 2 + 1 leaves
    CHECK(c.count() == 6);
    CHECK(c.misses == 3);            // the three missing leaves
    CHECK(c.null_count() == 3);
    CHECK(c.composite_only == 1);    // inner
    CHECK(c.t0_count() == 4);
    CHECK(c.bounding_volume_tests == 0);
}

TEST_CASE("counters: snapshots subtract to the cost of the work between them", "[rt][counters]") {
    object_list root;
    for (int k = 0; k < 5; ++k) root.insert(std::make_unique<probe>(1 + k));
    const intersection_counts before = counts();
    for (int k = 0; k < 10; ++k) root.intersect(ray(point(0, 0, 0), vector(0, 1, 0)));
    const intersection_counts cost = counts() - before;
    CHECK(cost.composite_tests == 10);
    CHECK(cost.primitive_tests == 50);
    CHECK(cost.misses == 0);
    CHECK((before + cost) == counts());
}

TEST_CASE("counters: each thread counts its own tests", "[rt][counters]") {
    object_list root;
    root.insert(std::make_unique<probe>(1));
    clear_counts();
    intersection_counts other;
    std::thread worker([&] {
        clear_counts();
        for (int k = 0; k < 7; ++k) root.intersect(ray(point(0, 0, 0), vector(0, 1, 0)));
        other = counts();
    });
    worker.join();
    CHECK(other.primitive_tests == 7);
    CHECK(counts().primitive_tests == 0);
}

TEST_CASE("counters: count_bounding_volume_tests only adds, and refuses a count that would wrap", "[rt][counters]") {
    clear_counts();
    count_bounding_volume_tests(5);
    count_bounding_volume_tests(0);
    CHECK(counts().bounding_volume_tests == 5);
    // Taking tests away through unsigned wrap-around (adding 2^64 - 3) is refused, and
    // nothing is counted.
    CHECK_THROWS_WITH(count_bounding_volume_tests(std::uint64_t{0} - 3),
                      Catch::Contains("count_bounding_volume_tests(18446744073709551613)") &&
                          Catch::Contains("more tests than any ray makes"));
    CHECK(counts().bounding_volume_tests == 5);
    // Steps of at most 2^40 that would pass 2^64 are refused at the step that would wrap.
    const std::uint64_t step = std::uint64_t{1} << 40;
    count_bounding_volume_tests(step);  // the largest count one call may make
    CHECK(counts().bounding_volume_tests == 5 + step);
    std::uint64_t calls = 0;
    try {
        for (; calls < (std::uint64_t{1} << 25); ++calls) count_bounding_volume_tests(step);
        FAIL("2^25 steps of 2^40 passed 2^64 without a refusal");
    } catch (const usage_error& e) {
        CHECK_THAT(e.what(), Catch::Contains("past 2^64"));
    }
    // Before call k the count is 5 + (k + 1) 2^40; call 2^24 - 2 would make it 2^64 + 5.
    CHECK(calls == (std::uint64_t{1} << 24) - 2);
    CHECK(counts().bounding_volume_tests == 5 + ((std::uint64_t{1} << 24) - 1) * step);
    clear_counts();
}

TEST_CASE("bounds: a box test counts one bounding-volume test and finds the span", "[rt][bounds]") {
    clear_counts();
    ray_span span;
    CHECK(hits_box(ray(point(-5, 0.5, 0.5), vector(1, 0, 0)), point(0, 0, 0), point(1, 1, 1), 1e300, &span));
    CHECK(span.t_near == Approx(5));
    CHECK(span.t_far == Approx(6));
    CHECK_FALSE(hits_box(ray(point(-5, 2, 0.5), vector(1, 0, 0)), point(0, 0, 0), point(1, 1, 1)));
    CHECK_FALSE(hits_box(ray(point(5, 0.5, 0.5), vector(1, 0, 0)), point(0, 0, 0), point(1, 1, 1)));
    CHECK(counts().bounding_volume_tests == 3);
}

TEST_CASE("bounds: a ray starting inside a box hits it, and one in the plane of a face is handled", "[rt][bounds]") {
    CHECK(hits_box(ray(point(0.5, 0.5, 0.5), vector(0, 0, 1)), point(0, 0, 0), point(1, 1, 1)));
    // Parallel to the x slabs and lying in the plane x == 0: inside the closed slab.
    CHECK(hits_box(ray(point(0, 0.5, -3), vector(0, 0, 1)), point(0, 0, 0), point(1, 1, 1)));
    CHECK_FALSE(hits_box(ray(point(-1e-12, 0.5, -3), vector(0, 0, 1)), point(0, 0, 0), point(1, 1, 1)));
}

TEST_CASE("bounds: sphere test hits in front and misses beside or behind", "[rt][bounds]") {
    clear_counts();
    CHECK(hits_sphere(ray(point(0, 0, 10), vector(0, 0, -1)), point(0, 0, 0), 1));
    CHECK_FALSE(hits_sphere(ray(point(0, 2, 10), vector(0, 0, -1)), point(0, 0, 0), 1));
    CHECK_FALSE(hits_sphere(ray(point(0, 0, 10), vector(0, 0, 1)), point(0, 0, 0), 1));
    CHECK(hits_sphere(ray(point(0, 0, 0.5), vector(0, 0, 1)), point(0, 0, 0), 1));  // from inside
    CHECK(counts().bounding_volume_tests == 4);
}

TEST_CASE("rtab_component: << writes the object in the scene format", "[rt][component]") {
    object_list list;
    list.insert(std::make_unique<probe>(2));
    std::ostringstream out;
    out << list;
    CHECK(out.str().rfind("LIST {", 0) == 0);
    CHECK(out.str().find("PROBE") != std::string::npos);
}
