// Public tests of shadows (stage_04.hh, step 4): a light counts only when the shadow ray
// from the point to the light hits nothing before the light. Run them with
// `build/student/stage_04_public_test "[shadow]"`.
//
// Each test compares your tracer with itself: the point in shadow must get what it gets
// when the scene has no light at all (the ambient term), and a point the blocker does
// not hide must get what it gets when the blocker is removed. So these tests fail only
// for a shadow bug, whatever your diffuse term does.
#include "vl/catch.hh"

#include <cmath>

#include "test_support.hh"

using namespace vl;
using namespace vl::stage04::testing;

namespace {

/// A white floor (kdr 1) under ambient 0.1 and a white light at `light` (none when
/// `lit` is false), with a sphere of `radius` at `blocker` (none when radius is 0) that
/// has the surface `looks`.
test_scene floor_scene(bool lit, const point& light, const point& blocker, double radius,
                       const surface& looks = {.kdr = 1}) {
    test_scene t;
    t.s.ambient = color(0.1, 0.1, 0.1);
    t.add(floor_plane(surface{.kdr = 1}));
    if (radius > 0) t.add(std::make_unique<test_sphere>(blocker, radius, looks));
    if (lit) t.light(color(1, 1, 1), light);
    return t;
}

}  // namespace

TEST_CASE("shadow: a sphere between the point and the light leaves the ambient term alone", "[04][shadow]") {
    // The light at (0, 10, 0); a sphere of radius 1 at (0, 5, 0) hides it from the
    // origin. The point (0, 0, 0) is in shadow: it gets only ambient * c * kdr = 0.1,
    // what it gets with no light at all. The point (4, 0, 0) sees the light beside the
    // sphere (its shadow ray passes 1.86 from the sphere's centre).
    const point light(0, 10, 0), blocker(0, 5, 0);
    const test_scene blocked = floor_scene(true, light, blocker, 1);
    const ray in_shadow(point(0, 1, 0.5), vector(0, -1, 0) + vector(0, 0, -0.5));  // onto the origin, beside the sphere
    const color unlit = floor_scene(false, light, blocker, 1).trace(in_shadow, 0);
    CHECK_COLOR(show(in_shadow) << " hits the floor at the origin, which the sphere at (0, 5, 0) hides from the light "
                                   "at (0, 10, 0): it must get what it gets with no light at all (ambient 0.1 * kdr 1)",
                blocked.trace(in_shadow, 0), unlit, 1e-12);

    const ray lit(point(4, 1, 0.5), vector(0, -1, -0.5));  // onto (4, 0, 0)
    const color open = floor_scene(true, light, blocker, 0).trace(lit, 0);
    CHECK_COLOR(show(lit) << " hits the floor at (4, 0, 0), whose shadow ray to the light passes beside the sphere: "
                             "it must get what it gets without the sphere",
                blocked.trace(lit, 0), open, 1e-12);
}

TEST_CASE("shadow: a sphere on the line to the light but beyond it casts no shadow", "[04][shadow]") {
    // The light at (0, 2, 0), a sphere of radius 1 at (0, 5, 0): on the line from the
    // origin through the light, but 3 beyond it. The shadow ray from the origin hits the
    // sphere at t = 4, farther than the light (t = 2): the light is seen.
    const point light(0, 2, 0), beyond(0, 5, 0);
    const ray r(point(0, 1, 0.5), vector(0, -1, -0.5));  // onto the origin
    const color open = floor_scene(true, light, beyond, 0).trace(r, 0);
    CHECK_COLOR(show(r) << " hits the floor at the origin; the sphere at (0, 5, 0) lies beyond the light at (0, 2, 0), "
                           "so the shadow ray reaches the light first (count a hit only when its t is less than the "
                           "distance to the light): the same as without the sphere",
                floor_scene(true, light, beyond, 1).trace(r, 0), open, 1e-12);
}

TEST_CASE("shadow: of two lights only the blocked one is lost", "[04][shadow]") {
    // Lights at (-3, 4, 0) and (3, 4, 0); a small sphere at (-1.5, 2, 0), halfway to the
    // left light, blocks that light only. The origin must get what it gets with the
    // right light alone.
    const ray r(point(0, 1, 0.5), vector(0, -1, -0.5));
    test_scene both;
    both.s.ambient = color(0.1, 0.1, 0.1);
    both.add(floor_plane(surface{.kdr = 1}));
    both.add(std::make_unique<test_sphere>(point(-1.5, 2, 0), 0.5, surface{.kdr = 1}));
    both.light(color(1, 1, 1), point(-3, 4, 0));
    both.light(color(0.5, 0.5, 1), point(3, 4, 0));
    test_scene right_only;
    right_only.s.ambient = color(0.1, 0.1, 0.1);
    right_only.add(floor_plane(surface{.kdr = 1}));
    right_only.light(color(0.5, 0.5, 1), point(3, 4, 0));
    CHECK_COLOR(show(r) << " hits the floor at the origin; of the lights at (-3, 4, 0) and (3, 4, 0) the sphere at "
                           "(-1.5, 2, 0) hides the left one: each light has its own shadow ray, so the result is what "
                           "the right light alone gives",
                both.trace(r, 0), right_only.trace(r, 0), 1e-12);
}

TEST_CASE("shadow: a transparent object blocks the light too", "[04][shadow]") {
    // Every object blocks, transparent or not (step 4): a glass sphere (kst 1, ior 1.5,
    // kdr 0) between the light and the origin leaves the ambient term alone.
    const point light(0, 10, 0), blocker(0, 5, 0);
    const surface glass{.kst = 1, .ior = 1.5};
    const ray r(point(0, 1, 0.5), vector(0, -1, -0.5));
    const color unlit = floor_scene(false, light, blocker, 1, glass).trace(r, 0);
    CHECK_COLOR(show(r) << " hits the floor at the origin under a glass sphere (kst 1) that lies between it and the "
                           "light: a shadow all the same, the ambient term alone",
                floor_scene(true, light, blocker, 1, glass).trace(r, 0), unlit, 1e-12);
}

TEST_CASE("shadow: a composite's bound that the shadow ray enters without a hit does not block", "[04][shadow]") {
    // The root is a list with a bound of radius 3 at (0, 5, 0) (like a BVH): the shadow
    // ray from the origin to the light at (0, 10, 0) goes through the bound but hits no
    // child, and the root answers composite_only (t == 0, hit() false). That is no
    // blocker: the light is seen, as in the same scene with a plain list.
    const ray r(point(0, 1, 0.5), vector(0, -1, -0.5));
    auto build = [](bool bounded) {
        test_scene t;
        if (bounded) t.s.root = std::make_unique<bounded_root>(point(0, 5, 0), 3);
        t.s.ambient = color(0.1, 0.1, 0.1);
        t.add(floor_plane(surface{.kdr = 1}));
        t.add(std::make_unique<test_sphere>(point(2.5, 5, 0), 0.25, surface{.kdr = 1}));  // inside the bound, aside
        t.light(color(1, 1, 1), point(0, 10, 0));
        return t;
    };
    const test_scene bounded = build(true), plain = build(false);
    const ray shadow(point(0, 1e-6, 0), vector(0, 1, 0));
    REQUIRE(bounded.s.root->intersect(shadow).is_composite_only());
    CHECK_COLOR(show(r) << " hits the floor at the origin; its shadow ray up to the light at (0, 10, 0) gets "
                           "composite_only from the root (t == 0: no hit, hit() is false), which must not count as a "
                           "blocker: the same as with a plain list",
                bounded.trace(r, 0), plain.trace(r, 0), 1e-12);
}
