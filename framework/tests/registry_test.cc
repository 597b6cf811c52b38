// Tests of the registry of scene type names.
#include <catch2/catch.hpp>

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
