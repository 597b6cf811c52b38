// Tests of the registry of scene type names.
#include "vl/catch.hh"

#include "support/probes.hh"
#include "vl/error.hh"
#include "vl/registry.hh"

using namespace vl;

TEST_CASE("registry: names are 1 to 10 upper-case letters, as in the thesis", "[rt][registry]") {
    CHECK(registry::valid_name("SPHERE"));
    CHECK(registry::valid_name("ABCDEFGHIJ"));
    CHECK_FALSE(registry::valid_name("ABCDEFGHIJK"));
    CHECK_FALSE(registry::valid_name(""));
    CHECK_FALSE(registry::valid_name("Sphere"));
    CHECK_FALSE(registry::valid_name("SPHERE2"));
    CHECK_FALSE(registry::valid_name("BIG_BOX"));
}

TEST_CASE("registry: creates a new object for each registered name", "[rt][registry]") {
    registry r;
    r.add("PROBE", [] { return std::make_unique<test::probe>(); });
    auto a = r.create("PROBE");
    auto b = r.create("PROBE");
    REQUIRE(a);
    REQUIRE(b);
    CHECK(a.get() != b.get());
    CHECK(a->type_name() == "PROBE");
    CHECK(r.create("NOSUCH") == nullptr);
    CHECK(r.contains("PROBE"));
    CHECK_FALSE(r.contains("NOSUCH"));
}

TEST_CASE("registry: refuses bad names, duplicates and empty factories", "[rt][registry]") {
    registry r;
    CHECK_THROWS_WITH(r.add("sphere", [] { return std::make_unique<test::probe>(); }),
                      Catch::Contains("1 to 10 upper-case letters"));
    CHECK_THROWS_AS(r.add("TOOLONGNAMEX", [] { return std::make_unique<test::probe>(); }), usage_error);
    r.add("PROBE", [] { return std::make_unique<test::probe>(); });
    CHECK_THROWS_WITH(r.add("PROBE", [] { return std::make_unique<test::probe>(); }),
                      Catch::Contains("already registered"));
    CHECK_THROWS_AS(r.add("EMPTY", nullptr), usage_error);
}

TEST_CASE("registry: the framework registers LIST and names come back sorted", "[rt][registry]") {
    registry r;
    r.add("PROBE", [] { return std::make_unique<test::probe>(); });
    register_framework(r);
    CHECK(r.names() == std::vector<std::string>{"LIST", "PROBE"});
    auto list = r.create("LIST");
    REQUIRE(list);
    CHECK(list->is_composite());
}

TEST_CASE("registry: tracers are made by name, and the framework brings flat and normals", "[rt][registry]") {
    registry r;
    register_framework(r);
    const scene s;
    CHECK(dynamic_cast<flat_tracer*>(r.make_tracer("flat", s).get()) != nullptr);
    CHECK(dynamic_cast<normals_tracer*>(r.make_tracer("normals", s).get()) != nullptr);
    // A tracer no piece of this build binds (the Hall/Whitted tracer comes with a stage):
    // the message lists those it has.
    CHECK_THROWS_WITH(r.make_tracer("whitted", s),
                      Catch::Contains("no tracer 'whitted' is registered in this build; it registers: flat, normals, sky"));
    CHECK_THROWS_AS(r.add_tracer("flat", [](const scene& sc) { return std::make_unique<flat_tracer>(sc); }), usage_error);
}

TEST_CASE("registry: without a stage's camera or sampler, asking for one says that none is registered", "[rt][registry]") {
    registry r;
    register_framework(r);
    CHECK_THROWS_WITH(r.make_camera(camera_settings{}, 4, 4), Catch::Contains("no camera is registered in this build") &&
                                                                  Catch::Contains("a stage's piece"));
    CHECK_THROWS_WITH(r.make_sampler("grid"),
                      Catch::Contains("no sampler 'grid' is registered in this build (it registers none)"));
    r.add_sampler("center", [] { return std::unique_ptr<sampler>(); });
    CHECK_THROWS_WITH(r.make_sampler("grid"), Catch::Contains("no sampler 'grid' is registered in this build; it registers: center"));
    CHECK_THROWS_AS(r.set_camera(nullptr), usage_error);
    CHECK_THROWS_AS(r.add_sampler("grid", nullptr), usage_error);
}

TEST_CASE("registry: lists its sample patterns and tracers and knows whether it has a camera", "[rt][registry]") {
    registry r;
    CHECK_FALSE(r.has_camera());
    CHECK(r.sampler_names().empty());
    register_framework(r);
    CHECK(r.tracer_names() == std::vector<std::string>{"flat", "normals", "sky"});
    r.add_sampler("zeta", [] { return std::unique_ptr<sampler>(); });
    r.add_sampler("alpha", [] { return std::unique_ptr<sampler>(); });
    CHECK(r.sampler_names() == std::vector<std::string>{"alpha", "zeta"});
    r.set_camera([](const camera_settings&, int, int) { return std::unique_ptr<camera>(); });
    CHECK(r.has_camera());
}
