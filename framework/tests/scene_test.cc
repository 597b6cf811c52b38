// Tests of the scene model: defaults, every setting, lights, objects.
#include "vl/catch.hh"

#include "support/probes.hh"
#include "vl/registry.hh"
#include "vl/scene.hh"
#include "vl/tracer.hh"

using namespace vl;

namespace {
registry test_types() { return test::probe_types(); }
}  // namespace

TEST_CASE("scene: everything optional has a default", "[scene]") {
    const registry types = test_types();
    const scene s = parse_scene("PROBE { }", "min.ray_trace", types);
    CHECK(s.source == "min.ray_trace");
    CHECK(s.width == 320);
    CHECK(s.height == 240);
    CHECK(s.camera.eye == point(0, 0, 5));
    CHECK(s.camera.look_at == point(0, 0, 0));
    CHECK(s.camera.up == vector(0, 1, 0));
    CHECK(s.camera.fov_degrees == 45);
    CHECK(s.lights.empty());
    CHECK(s.samples_per_pixel == 1);
    CHECK(s.sampler == "center");
    CHECK(s.max_depth == 5);
    CHECK(s.tracer == "flat");
    CHECK(s.background == BLACK);
    REQUIRE(s.root->num_children() == 1);
    const auto& leaf = *s.root->children()[0];
    CHECK(leaf.type_name() == "PROBE");
    CHECK(leaf.clr() == WHITE);
    CHECK(leaf.kdr() == 0);
}

TEST_CASE("scene: every setting is read", "[scene]") {
    const registry types = test_types();
    const scene s = parse_scene(R"(
        # a full scene
        camera { eye 1 2 3  look_at 0 1 0  up 0 0 1  fov 60 }
        size 640 480
        samples 16
        sampler jittered
        depth 3
        tracer normals
        ambient 0.2 0.2 0.3
        background (0.1, 0.2, 0.3)
        light { color 1 1 0.9  position 10 10 10 }
        light { position -5 5 0 }
        PROBE { t 2  color 1 0 0  kdr 0.7  ksr 0.3  n 20  ior 1.5  kdt 0.1  kst 0.2  zero_t 1e-4 }
        LIST { PROBE { t 3 } PROBE { t 4 } }
    )", "full.ray_trace", types);
    CHECK(s.camera.eye == point(1, 2, 3));
    CHECK(s.camera.look_at == point(0, 1, 0));
    CHECK(s.camera.up == vector(0, 0, 1));
    CHECK(s.camera.fov_degrees == 60);
    CHECK(s.width == 640);
    CHECK(s.height == 480);
    CHECK(s.samples_per_pixel == 16);
    CHECK(s.sampler == "jittered");
    CHECK(s.max_depth == 3);
    CHECK(s.tracer == "normals");
    CHECK(s.ambient == color(0.2, 0.2, 0.3));
    CHECK(s.background == color(0.1, 0.2, 0.3));
    REQUIRE(s.lights.size() == 2);
    CHECK(s.lights[0] == color_point(color(1, 1, 0.9), point(10, 10, 10)));
    CHECK(s.lights[1].clr() == WHITE);
    REQUIRE(s.root->num_children() == 2);
    const auto& p = *s.root->children()[0];
    CHECK(p.clr() == color(1, 0, 0));
    CHECK(p.kdr() == 0.7);
    CHECK(p.ksr() == 0.3);
    CHECK(p.n() == 20);
    CHECK(p.ior() == 1.5);
    CHECK(p.kdt() == 0.1);
    CHECK(p.kst() == 0.2);
    CHECK(p.zero_t() == 1e-4);
    CHECK(s.root->children()[1]->is_composite());
}

TEST_CASE("scene: what a primitive writes, the reader reads back", "[scene]") {
    const registry types = test_types();
    const scene a = parse_scene("PROBE { t 2 color 0.25 0.5 1 kdr 0.75 ior 1.25 }", "a", types);
    std::ostringstream out;
    out << *a.root->children()[0];
    const scene b = parse_scene(out.str(), "b", types);
    const auto& p = *b.root->children()[0];
    CHECK(p.clr() == color(0.25, 0.5, 1));
    CHECK(p.kdr() == 0.75);
    CHECK(p.ior() == 1.25);
}

TEST_CASE("flat tracer: an object's colour where it is hit, the background elsewhere", "[scene][tracer]") {
    const registry types = test_types();
    const scene hit = parse_scene("background 0 0 1\nPROBE { t 2 color 1 0 0 }", "hit", types);
    const scene miss = parse_scene("background 0 0 1\nPROBE { t 0 }", "miss", types);
    const ray r(point(0, 0, 0), vector(0, 0, 1));
    CHECK(flat_tracer(hit).trace(r, 0) == color(1, 0, 0));
    CHECK(flat_tracer(miss).trace(r, 0) == color(0, 0, 1));
}

TEST_CASE("normals tracer: the normal mapped from -1..1 to 0..1", "[scene][tracer]") {
    const registry types = test_types();
    const scene s = parse_scene("PROBE { t 2 }", "n", types);  // the probe's normal is +z
    CHECK(normals_tracer(s).trace(ray(point(0, 0, 0), vector(0, 0, 1)), 0) == color(0.5, 0.5, 1));
}

TEST_CASE("scene: settings without objects are a scene (the sky tracer shows the camera)", "[scene]") {
    const registry types = test_types();
    const scene s = parse_scene("tracer sky\nsize 16 8\n", "sky.ray_trace", types);
    CHECK(s.root->num_children() == 0);
    CHECK(s.tracer == "sky");
}

TEST_CASE("scene: sampler and tracer names are the registry's, whatever they are", "[scene]") {
    registry types = test_types();
    const std::string text = "sampler stratified\ntracer whitted\nPROBE { }";
    // Not registered: the error says so and lists what this build has.
    CHECK_THROWS_WITH(parse_scene(text, "s.ray_trace", types),
                      Catch::StartsWith("s.ray_trace:1:9: sampler 'stratified' is not registered in this build; "
                                        "choose one of: center, jittered"));
    types.add_sampler("stratified", [] { return std::make_unique<test::probe_sampler>(); });
    CHECK_THROWS_WITH(parse_scene(text, "s.ray_trace", types),
                      Catch::StartsWith("s.ray_trace:2:8: tracer 'whitted' is not registered in this build; "
                                        "choose one of: flat, normals, sky"));
    // Once a piece binds them, the same scene reads.
    types.add_tracer("whitted", [](const scene& sc) { return std::make_unique<flat_tracer>(sc); });
    const scene s = parse_scene(text, "s.ray_trace", types);
    CHECK(s.sampler == "stratified");
    CHECK(s.tracer == "whitted");
    // With no sample pattern at all, the message says that none is registered.
    registry bare;
    register_framework(bare);
    CHECK_THROWS_WITH(parse_scene("sampler center\n", "s.ray_trace", bare),
                      Catch::StartsWith("s.ray_trace:1:9: sampler 'center' is not registered in this build; "
                                        "it registers none"));
}
