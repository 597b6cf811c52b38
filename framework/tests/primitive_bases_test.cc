// Tests of stage 02's shape bases: what they read and write, that a derived class's
// geometry_changed() sees every change, and the factories' checks with their messages.
#include "vl/catch.hh"

#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "support/probes.hh"
#include "vl/error.hh"
#include "vl/primitive_bases.hh"
#include "vl/registry.hh"

using namespace vl;

namespace {

/// A sphere that only counts the calls of its hook and keeps the radius it saw last. Like
/// the shapes of stage 02 it has no constructor of its own: make() makes it.
class counting_sphere final : public shapes::sphere_base {
public:
    int changes = 0;           ///< calls of geometry_changed()
    double seen_radius = 0;    ///< radius_ at the last call

private:
    void geometry_changed() override {
        ++changes;
        seen_radius = radius_;
    }
    intersection find_intersection(const ray&) const override { return intersection::none(); }
};

/// A polygon that keeps the number of vertices its hook saw last.
class counting_polygon final : public shapes::polygon_base {
public:
    counting_polygon() : polygon_base({point(0, 0, 0), point(1, 0, 0), point(0, 1, 0)}) { geometry_changed(); }
    std::size_t seen_vertices = 0;  ///< vertices_.size() at the last call

private:
    void geometry_changed() override { seen_vertices = vertices_.size(); }
    intersection find_intersection(const ray&) const override { return intersection::none(); }
};

/// Reads `text` (an object's block, from its `{`) into `object`.
void read_into(rtab_component& object, const std::string& text) {
    const registry types = test::probe_types();
    scene_reader in(types);
    in.open_text(text, "t");
    object.read(in);
}

std::string written(const rtab_component& object) {
    std::ostringstream out;
    object.write(out);
    return out.str();
}

}  // namespace

TEST_CASE("primitive bases: read() hands the derived class what it read, through geometry_changed()",
          "[primitive_bases]") {
    const auto s = shapes::sphere_base::make<counting_sphere>(point(0, 0, 0), 1);
    CHECK(s->changes == 1);
    read_into(*s, "{ center 1 2 3 radius 0.5 kdr 0.25 }");
    CHECK(s->changes == 2);
    CHECK(s->seen_radius == 0.5);
    CHECK(s->kdr() == 0.25);
    CHECK(s->type_name() == "SPHERE");
    CHECK(written(*s) == "SPHERE { center 1 2 3 radius 0.5 kdr 0.25 }");

    counting_polygon p;
    read_into(p, "{ vertices (0, 0, 0) (2, 0, 0) (2, 2, 0) (0, 2, 0) }");
    CHECK(p.seen_vertices == 4);
    CHECK(written(p) == "POLYGON { vertices (0, 0, 0) (2, 0, 0) (2, 2, 0) (0, 2, 0) }");
    CHECK_FALSE(p.contains(point(1, 1, 0)));
}

TEST_CASE("primitive bases: a scene's bad values fail where they are, the geometry unchanged",
          "[primitive_bases]") {
    const auto s = shapes::sphere_base::make<counting_sphere>(point(0, 0, 0), 1);
    CHECK_THROWS_AS(read_into(*s, "{ radius 0 }"), file_error);
    CHECK(s->changes == 1);
    CHECK(s->seen_radius == 1);
}

TEST_CASE("primitive bases: each factory check refuses with the factory's message", "[primitive_bases]") {
    const point o(0, 0, 0);
    CHECK_NOTHROW(shapes::sphere_base::check(o, 1));
    CHECK_THROWS_WITH(shapes::sphere_base::check(o, 0),
                      "make_sphere: the center must be finite and the radius a finite number > 0");
    CHECK_THROWS_AS(shapes::sphere_base::check(point(0, 0, 0, 0), 1), usage_error);
    CHECK_NOTHROW(shapes::plane_base::check(o, vector(0, 2, 0)));
    CHECK_THROWS_WITH(shapes::plane_base::check(o, vector(0, 0, 0)),
                      "make_plane: the point must be finite and the normal a finite, non-zero vector");
    CHECK_NOTHROW(shapes::triangle_base::check(o, point(1, 0, 0), point(0, 1, 0)));
    CHECK_THROWS_WITH(shapes::triangle_base::check(o, point(1, 0, 0), point(2, 0, 0)),
                      Catch::StartsWith("make_triangle: its vertices a, b and c are on one line"));
    CHECK_NOTHROW(shapes::polygon_base::check({o, point(1, 0, 0), point(0, 1, 0)}));
    CHECK_THROWS_WITH(shapes::polygon_base::check({o, point(1, 0, 0)}), Catch::StartsWith("make_polygon: "));
}

TEST_CASE("primitive bases: make() checks, sets the geometry and calls geometry_changed() once",
          "[primitive_bases]") {
    const std::unique_ptr<counting_sphere> s = shapes::sphere_base::make<counting_sphere>(point(1, 2, 3, 2), 0.5);
    CHECK(s->changes == 1);
    CHECK(s->seen_radius == 0.5);
    CHECK(written(*s) == "SPHERE { center 0.5 1 1.5 radius 0.5 }");
    CHECK_THROWS_WITH(shapes::sphere_base::make<counting_sphere>(point(0, 0, 0), 0),
                      "make_sphere: the center must be finite and the radius a finite number > 0");
}
