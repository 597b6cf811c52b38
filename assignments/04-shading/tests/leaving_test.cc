// Public tests of rays that START INSIDE an object (stage_04.hh, steps 2 and 5): the
// normal negated when the object contains the ray's origin, refraction out of glass,
// total internal reflection, the critical angle, and Schlick's F from inside (with the
// cosine on the air side). Run them with `build/student/stage_04_public_test "[leaving]"`.
//
// The glass fills everything below y = 0 (glass_below in test_support.hh: ior 1.5, kst 1,
// its normal +y points out into the air, contains() is true for y < 0). The rays start
// inside it, below the surface, and hit the surface at the origin from beneath. There are
// no lights, ambient is (1, 1, 1) and the background is black; small emitters (kdr 1)
// wait where a ray should land. Each test looks at what the bounces add: your trace() of
// the ray minus your trace() of the same ray with the glass made dull (ksr = kst = 0),
// at depth 3 (every secondary ray ends after one bounce), against your tracer's own
// colour E of each emitter (a ray aimed straight at it).
//
// The critical angle of glass of ior 1.5: sin a_c = 1 / 1.5, a_c = 41.81 degrees.
#include "vl/catch.hh"

#include <cmath>
#include <numbers>

#include "test_support.hh"

using namespace vl;
using namespace vl::stage04::testing;

namespace {

/// The ray that starts inside the glass at y = -0.5 and hits its surface at the origin
/// `degrees` from the (inward) normal -y.
ray from_inside(double degrees) {
    const vector d = from_vertical(degrees);
    return ray(point(0, 0, 0) - (0.5 / d.y) * d, d);
}

/// An emitter of colour `c`, radius 0.4, at `at`.
struct patch {
    point at;
    color c;
};

/// Glass (`looks`) below y = 0, the emitters `patches`, and a red emitter ceiling at
/// y = 5 when `red_ceiling`.
test_scene glass_and(const surface& looks, std::initializer_list<patch> patches, bool red_ceiling = false) {
    test_scene t;
    t.s.ambient = color(1, 1, 1);
    t.add(glass_below(looks));
    for (const patch& p : patches) t.add(std::make_unique<test_sphere>(p.at, 0.4, emitter(p.c)));
    if (red_ceiling) t.add(floor_plane(emitter(color(1, 0, 0)), 5));
    return t;
}

/// Your colour of the emitter at `at`: the ray from the point 1 from the origin towards
/// it, aimed straight at it.
color emitter_colour(const test_scene& t, const point& at) {
    const vector towards = (at - point(0, 0, 0)).unit();
    return t.trace(ray(point(0, 0, 0) + towards, towards), 0);
}

const surface glass{.kst = 1, .ior = 1.5};

/// What the glass adds to from_inside(degrees) at depth 3, with the emitters `patches`.
color bounces(double degrees, std::initializer_list<patch> patches, bool red_ceiling = false) {
    const test_scene t = glass_and(glass, patches, red_ceiling), plain = glass_and(dull(glass), patches, red_ceiling);
    return bounce_part(t, plain, from_inside(degrees), 3);
}

/// Where the mirror ray of from_inside(degrees) goes, back down into the glass.
vector mirrored(double degrees) {
    const vector d = from_vertical(degrees);
    return vector(d.x, -d.y, 0);
}

}  // namespace

TEST_CASE("leaving: a light inside a sphere lights its inside", "[04][leaving]") {
    // A white sphere of radius 2 at the origin (kdr 0.7), a white light at (1, 0, 0), a
    // ray from (1.5, 0, 0) inside the sphere along +x. It hits the wall at (2, 0, 0),
    // where normal() is (1, 0, 0), pointing out. The ray starts inside (contains(origin)
    // is true), so N is negated: N = (-1, 0, 0), and L = (-1, 0, 0):
    //   kdr * N.L * (c * Lc) = 0.7 * 1 * (1, 1, 1) = (0.7, 0.7, 0.7)
    // With the normal not negated N.L = -1 and the wall would be black. (The sphere's
    // half x < 0 is left out, a bowl open towards -x, so that the shadow ray from the wall
    // through the light meets nothing even beyond the light, and the light is 1 from the
    // wall: this test looks at the normal alone.)
    test_scene t;
    t.add(std::make_unique<test_sphere>(point(0, 0, 0), 2, surface{.kdr = 0.7}, vector(-1, 0, 0)));
    t.light(color(1, 1, 1), point(1, 0, 0));
    const ray r(point(1.5, 0, 0), vector(1, 0, 0));
    CHECK_COLOR(show(r) << " starts inside the sphere and hits its wall at (2, 0, 0); the light is at (1, 0, 0) "
                           "inside too: negate the outward normal when the object contains the ray's origin, then "
                           "N.L = 1",
                t.trace(r, 0), color(0.7, 0.7, 0.7), 1e-9);
}

TEST_CASE("leaving: beyond the critical angle the light is totally internally reflected", "[04][leaving]") {
    // From inside at 60 degrees: eta = 1.5 / 1, cos_i = 0.5,
    //   k = 1 - eta^2 (1 - cos_i^2) = 1 - 2.25 * 0.75 = -0.6875 < 0
    // so F = 1 and nothing gets out: all of kst goes to the mirror ray, back down into the
    // glass to a green emitter 3 along it. The bounces add exactly that emitter's colour
    // E, and no red from the ceiling at y = 5 (light that got out). (A second green
    // emitter lies in the air, 3 along the ray's own straight line, so that this test does
    // not depend on which way the mirror ray goes: the [reflection] tests check that.)
    for (const double degrees : {45.0, 60.0, 80.0}) {
        const point back_in = point(0, 0, 0) + 3 * mirrored(degrees);
        const point straight_on = point(0, 0, 0) + 3 * from_vertical(degrees);
        const std::initializer_list<patch> greens{{back_in, color(0, 1, 0)}, {straight_on, color(0, 1, 0)}};
        const color e = emitter_colour(glass_and(glass, greens, true), back_in);
        REQUIRE_EMITTER_SEEN("the green emitter in the glass at " << show(back_in), e);
        CHECK_COLOR(show(from_inside(degrees))
                        << " starts inside glass of ior 1.5 and meets its surface " << num(degrees)
                        << " degrees from the normal, beyond the critical angle 41.81: k < 0, total internal "
                           "reflection, F = 1: all of it to the mirror ray (green "
                        << show(e) << "), none out (red)",
                    bounces(degrees, greens, true), e, 1e-9);
    }
}

TEST_CASE("leaving: at the critical angle all the light is reflected", "[04][leaving]") {
    // At sin a = 1 / 1.5 exactly, k = 1 - 2.25 (4/9) = 0 (up to round-off): cos_t = 0, the
    // transmitted ray would graze the surface, and F = R0 + (1 - R0) (1 - cos_t)^5 = 1
    // (the cosine on the air side, which is cos_t here). So again all of it goes to the
    // green emitters, as in the test beyond the critical angle. (With cos_i on the glass
    // side instead, F would be 0.041 and nearly all the light would leave, grazing.)
    const double critical = std::asin(1 / 1.5) * 180 / std::numbers::pi;
    const point back_in = point(0, 0, 0) + 3 * mirrored(critical);
    const point straight_on = point(0, 0, 0) + 3 * from_vertical(critical);
    const std::initializer_list<patch> greens{{back_in, color(0, 1, 0)}, {straight_on, color(0, 1, 0)}};
    const color e = emitter_colour(glass_and(glass, greens, true), back_in);
    REQUIRE_EMITTER_SEEN("the green emitter in the glass at " << show(back_in), e);
    CHECK_COLOR(show(from_inside(critical))
                    << " starts inside glass of ior 1.5 and meets its surface at the critical angle 41.81 degrees: "
                       "F = 1 (all to the mirror ray, green "
                    << show(e) << "), whether or not k comes out a hair above 0",
                bounces(critical, greens, true), e, 1e-6);
}

TEST_CASE("leaving: a ray leaving glass bends away from the normal by Snell's law", "[04][leaving]") {
    // From inside at 30 degrees: eta = 1.5, sin_t = 1.5 sin 30 = 0.75, cos_t = 0.6614,
    //   T = eta d + (eta cos_i - cos_t) N = (0.75, 0.6614, 0) with N = (0, -1, 0) negated,
    // 48.6 degrees from the vertical. At height 5, T is at x = 5 * 0.75 / 0.6614 = 5.67:
    // a green emitter there. Eta the wrong way up (1 / 1.5) reaches x = 1.77 (blue); a ray
    // that does not bend reaches x = 5 tan 30 = 2.89, where there is nothing (black). The
    // mirror ray goes down into the black below. F from inside at 30 degrees is 0.044
    // (Schlick, cosine on the air side) or 0.055 (exact), so the green weight is 1 - F,
    // about 0.95.
    const double sin_t = 1.5 * std::sin(radians(30)), cos_t = std::sqrt(1 - sin_t * sin_t);
    const point landing(5 * sin_t / cos_t, 5, 0);
    const std::initializer_list<patch> emitters{{landing, color(0, 1, 0)}, {point(1.768, 5, 0), color(0, 0, 1)}};
    const color e = emitter_colour(glass_and(glass, emitters), landing);
    REQUIRE_EMITTER_SEEN("the green emitter at " << show(landing), e);
    const double cos_i = std::cos(radians(30));
    const double schlick_f = schlick(1.5, 1, cos_i), exact_f = fresnel_exact(1.5, 1, cos_i);
    const double f = (schlick_f + exact_f) / 2, tolerance = std::fabs(schlick_f - exact_f) / 2 + 0.002;
    CHECK_COLOR(show(from_inside(30)) << " leaves glass of ior 1.5 at the origin 30 degrees from the normal: T = (0.75, "
                                         "0.6614, 0) reaches the green emitter "
                                      << show(e) << " at " << show(landing)
                                      << " with weight 1 - F; blue means eta upside down, black T elsewhere",
                bounces(30, emitters), (1 - f) * e, tolerance);
}

TEST_CASE("leaving: Schlick from inside takes the cosine on the air side", "[04][leaving]") {
    // From inside at 40 degrees, just below the critical angle: sin_t = 1.5 sin 40 =
    // 0.9642, cos_t = 0.2652. The cosine for Schlick is on the side of the lower index
    // (the air): cos_t.
    //   F = 0.04 + 0.96 (1 - 0.2652)^5 = 0.2456;  the exact equations give 0.2453
    // so 1 - F = 0.754 gets out, along T = (0.9642, 0.2652, 0), to a red emitter 5 along
    // it; the mirror ray goes down into the black. With cos_i = cos 40 = 0.766 instead, F
    // would be 0.0407 and 0.959 would get out: far too much.
    const double cos_i = std::cos(radians(40));
    const double schlick_f = schlick(1.5, 1, cos_i), exact_f = fresnel_exact(1.5, 1, cos_i);
    const double f = (schlick_f + exact_f) / 2, tolerance = std::fabs(schlick_f - exact_f) / 2 + 0.01;
    const double sin_t = 1.5 * std::sin(radians(40));
    const point out = point(0, 0, 0) + 5 * vector(sin_t, std::sqrt(1 - sin_t * sin_t), 0);
    const std::initializer_list<patch> red{{out, color(1, 0, 0)}};
    const color e = emitter_colour(glass_and(glass, red), out);
    REQUIRE_EMITTER_SEEN("the red emitter at " << show(out), e);
    CHECK_COLOR(show(from_inside(40)) << " starts inside glass of ior 1.5 and meets its surface 40 degrees from the "
                                         "normal: F is "
                                      << num(schlick_f) << " by Schlick with cos_t, " << num(exact_f)
                                      << " exactly; 1 - F of the red emitter " << show(e)
                                      << " gets out. Nearly all of it means Schlick was given cos_i",
                bounces(40, red), (1 - f) * e, tolerance);
}
