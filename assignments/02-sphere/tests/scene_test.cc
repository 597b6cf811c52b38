// Public tests of reading and writing stage 02's objects in scene files. Run them with
// `ctest -L 02-sphere`.
#include "vl/catch.hh"
#include <string>
#include <vector>

#include "test_support.hh"

using namespace vl;
using namespace vl::stage02;
using namespace vl::stage02::testing;

namespace {

// The same object answers the same rays the same way.
void check_same_hits(const rtab_component& a, const rtab_component& b) {
    random_numbers random(7);
    for (int k = 0; k < 200; ++k) {
        const ray r(random.in_cube(4), random.direction());
        const intersection i = a.intersect(r), j = b.intersect(r);
        CHECK(i.hit() == j.hit());
        if (i.hit() && j.hit()) CHECK(i.t == j.t);
    }
}

// Reads `text`, writes the object, reads that back: the second object must write the
// same text, and have the same type, colour, zero_t and hits as the first.
void check_round_trip(const std::string& text) {
    CAPTURE(text);
    const auto first = read_object(text);
    const std::string out = written(*first);
    CAPTURE(out);
    const auto second = read_object(out);
    CHECK(written(*second) == out);
    CHECK(second->type_name() == first->type_name());
    CHECK(second->clr() == first->clr());
    CHECK(second->zero_t() == first->zero_t());
    check_same_hits(*first, *second);
}

}  // namespace

TEST_CASE("scene: SPHERE reads its properties and writes them back", "[02][scene][sphere]") {
    check_round_trip("SPHERE { center 1 -2 0.5 radius 1.25 color 1 0 0 kdr 0.7 }");
    check_round_trip("SPHERE { }");
}

TEST_CASE("scene: PLANE reads its properties and writes them back", "[02][scene][plane]") {
    check_round_trip("PLANE { point 0 -1 0 normal (0, 2, 0.5) zero_t 1e-4 }");
}

TEST_CASE("scene: TRIANGLE reads its properties and writes them back", "[02][scene][triangle]") {
    check_round_trip("TRIANGLE { a 0 0 0 b 1 0 0 c 0.1 0.9 0.3 ksr 0.5 }");
}

TEST_CASE("scene: POLYGON reads its properties and writes them back", "[02][scene][polygon]") {
    check_round_trip("POLYGON { vertices (0, 0, 0) (2, 0, 0) (2, 1, 0.5) (0, 1, 0.5) color 0 0 1 }");
    check_round_trip("POLYGON { n 20 }");
}

TEST_CASE("scene: SPHERE's center and radius are read", "[02][scene][sphere]") {
    const auto s = read_object("SPHERE { radius 2 center 0 0 -10 }");
    const intersection i = s->intersect(ray(point(0, 0, 0), vector(0, 0, -1)));
    REQUIRE(i.hit());
    CHECK(i.t == Approx(8));
    CHECK(s->min_point() == point(-2, -2, -12));
}

TEST_CASE("scene: a bad SPHERE is refused at its place in the file", "[02][scene][sphere]") {
    CHECK_THAT(read_error("SPHERE { radius -1 }"), Catch::Contains("test.ray_trace:1:17") && Catch::Contains("radius"));
}

TEST_CASE("scene: a bad PLANE is refused at its place in the file", "[02][scene][plane]") {
    CHECK_THAT(read_error("PLANE { normal 0 0 0 }"), Catch::Contains("test.ray_trace:1:16") && Catch::Contains("normal"));
}

TEST_CASE("scene: a bad TRIANGLE is refused at its place in the file", "[02][scene][triangle]") {
    CHECK_THAT(read_error("TRIANGLE { a 0 0 0 b 1 1 1 c 2 2 2 }"),
               Catch::Contains("test.ray_trace:1:") && Catch::Contains("line"));
}

TEST_CASE("scene: a bad POLYGON is refused at the vertex at fault", "[02][scene][polygon]") {
    // The third vertex is 0.5 off the plane of the others: the error points at it.
    CHECK_THAT(read_error("POLYGON {\n  vertices (0, 0, 0) (1, 0, 0)\n           (1, 1, 0.5) (0, 1, 0)\n}"),
               Catch::Contains("test.ray_trace:3:") && Catch::Contains("planar"));
    CHECK_THAT(read_error("POLYGON { vertices (0, 0, 0) (1, 0, 0) (0.3, 0.3, 0) (0, 1, 0) }"),
               Catch::Contains("test.ray_trace:1:") && Catch::Contains("convex"));
    CHECK_THAT(read_error("POLYGON { vertices (0, 0, 0) (1, 0, 0) }"),
               Catch::Contains("test.ray_trace:1:") && Catch::Contains("at least 3"));
}
