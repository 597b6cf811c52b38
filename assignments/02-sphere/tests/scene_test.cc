// Public tests of reading and writing stage 02's objects in scene files, and of the
// public scenes' images. Run them with `ctest -L 02-sphere`.
#include <catch2/catch.hpp>
#include <filesystem>
#include <string>
#include <vector>

#include "image_compare.hh"
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

// Checks the message of the vl::file_error that reading `text` throws.
std::string read_error(const std::string& text) {
    try {
        read_object(text);
    } catch (const file_error& e) {
        return e.what();
    }
    return "(no error)";
}

}  // namespace

TEST_CASE("scene: each object reads its properties and writes them back", "[02][scene]") {
    const std::vector<std::string> scenes = {
        "SPHERE { center 1 -2 0.5 radius 1.25 color 1 0 0 kdr 0.7 }",
        "SPHERE { }",
        "PLANE { point 0 -1 0 normal (0, 2, 0.5) zero_t 1e-4 }",
        "TRIANGLE { a 0 0 0 b 1 0 0 c 0.1 0.9 0.3 ksr 0.5 }",
        "POLYGON { vertices (0, 0, 0) (2, 0, 0) (2, 1, 0.5) (0, 1, 0.5) color 0 0 1 }",
        "POLYGON { n 20 }",
    };
    for (const std::string& text : scenes) {
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
}

TEST_CASE("scene: SPHERE's center and radius are read", "[02][scene]") {
    const auto s = read_object("SPHERE { radius 2 center 0 0 -10 }");
    const intersection i = s->intersect(ray(point(0, 0, 0), vector(0, 0, -1)));
    REQUIRE(i.hit());
    CHECK(i.t == Approx(8));
    CHECK(s->min_point() == point(-2, -2, -12));
}

TEST_CASE("scene: a bad object is refused at its place in the file", "[02][scene]") {
    CHECK_THAT(read_error("SPHERE { radius -1 }"), Catch::Contains("test.ray_trace:1:17") && Catch::Contains("radius"));
    CHECK_THAT(read_error("PLANE { normal 0 0 0 }"), Catch::Contains("test.ray_trace:1:16") && Catch::Contains("normal"));
    CHECK_THAT(read_error("TRIANGLE { a 0 0 0 b 1 1 1 c 2 2 2 }"),
               Catch::Contains("test.ray_trace:1:") && Catch::Contains("line"));
    // The fourth vertex is 0.5 off the plane of the others: the error points at it.
    CHECK_THAT(read_error("POLYGON {\n  vertices (0, 0, 0) (1, 0, 0)\n           (1, 1, 0.5) (0, 1, 0)\n}"),
               Catch::Contains("test.ray_trace:3:") && Catch::Contains("planar"));
    CHECK_THAT(read_error("POLYGON { vertices (0, 0, 0) (1, 0, 0) (0.3, 0.3, 0) (0, 1, 0) }"),
               Catch::Contains("test.ray_trace:1:") && Catch::Contains("convex"));
    CHECK_THAT(read_error("POLYGON { vertices (0, 0, 0) (1, 0, 0) }"),
               Catch::Contains("test.ray_trace:1:") && Catch::Contains("at least 3"));
}

TEST_CASE("scene: each public scene renders like its reference image", "[02][scene][render]") {
    // The scenes and their PNGs are in ../scenes; tools/update-reference-images makes
    // the PNGs with the reference pieces.
    const std::filesystem::path scenes = std::filesystem::path(__FILE__).parent_path().parent_path() / "scenes";
    int rendered = 0;
    for (const auto& entry : std::filesystem::directory_iterator(scenes)) {
        if (entry.path().extension() != ".ray_trace") continue;
        const std::filesystem::path png = std::filesystem::path(entry.path()).replace_extension(".png");
        DYNAMIC_SECTION(entry.path().filename().string()) {
            REQUIRE(std::filesystem::exists(png));
            const image_difference d = compare_render(entry.path(), png);
            INFO(entry.path().filename().string() << ": " << d.summary);
            CHECK(renders_match(d));
        }
        ++rendered;
    }
    CHECK(rendered >= 4);
}
