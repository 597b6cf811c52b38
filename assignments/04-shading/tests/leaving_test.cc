// Public tests of rays that START INSIDE an object (stage_04.hh, steps 2 and 5): the
// normal negated when the object contains the ray's origin, refraction out of glass,
// total internal reflection, the critical angle, and Schlick's F from inside (with the
// cosine on the air side). Run them with `build/student/stage_04_public_test "[leaving]"`.
//
// The glass fills everything below y = 0 (glass_below in test_support.hh: ior 1.5, its
// normal +y points out into the air, contains() is true for y < 0). The rays start inside
// it, below the surface, and hit the surface from beneath. With no lights and ambient
// (1, 1, 1), an emitter (kdr 1) sends back its colour: a green emitter floor at y = -1
// (inside the glass) receives the light reflected back into the glass, a red emitter
// ceiling at y = 1 (in the air) the light that gets out. trace() returns (1 - F, F, 0).
//
// The critical angle of glass of ior 1.5: sin a_c = 1 / 1.5, a_c = 41.81 degrees.
#include <catch2/catch.hpp>

#include <cmath>

#include "test_support.hh"

using namespace vl;
using namespace vl::stage04::testing;

namespace {

/// Glass (kst 1, ior 1.5) below y = 0, a green emitter floor at y = -1 inside it and a
/// red emitter ceiling at y = 1 above it.
test_scene green_floor_red_ceiling() {
    test_scene t;
    t.s.ambient = color(1, 1, 1);
    t.add(glass_below(surface{.kst = 1, .ior = 1.5}));
    t.add(floor_plane(emitter(color(0, 1, 0)), -1));
    t.add(floor_plane(emitter(color(1, 0, 0)), 1));
    return t;
}

/// The ray that starts inside the glass at y = -0.5 and hits its surface at the origin
/// `degrees` from the (inward) normal -y.
ray from_inside(double degrees) {
    const vector d = from_vertical(degrees);
    return ray(point(0, 0, 0) - (0.5 / d.y) * d, d);
}

}  // namespace

TEST_CASE("leaving: a light inside a sphere lights its inside", "[04][leaving]") {
    // A white sphere of radius 2 at the origin (kdr 0.7), a white light at its centre, a
    // ray from (0.5, 0, 0) inside the sphere along +x. It hits the wall at (2, 0, 0),
    // where normal() is (1, 0, 0), pointing out. The ray starts inside (contains(origin)
    // is true), so N is negated: N = (-1, 0, 0), and L = (-1, 0, 0):
    //   kdr * N.L * (c * Lc) = 0.7 * 1 * (1, 1, 1) = (0.7, 0.7, 0.7)
    // With the normal not negated N.L = -1 and the wall would be black. (The sphere's
    // half x < 0 is left out, a bowl open towards -x, so that the shadow ray from the wall
    // through the light meets nothing even beyond the light: this test looks at the
    // normal alone.)
    test_scene t;
    t.add(std::make_unique<test_sphere>(point(0, 0, 0), 2, surface{.kdr = 0.7}, vector(-1, 0, 0)));
    t.light(color(1, 1, 1), point(0, 0, 0));
    const ray r(point(0.5, 0, 0), vector(1, 0, 0));
    CHECK_COLOR(show(r) << " starts inside the sphere and hits its wall at (2, 0, 0); the light is at the centre: "
                           "negate the outward normal when the object contains the ray's origin, then N.L = 1",
                t.trace(r, 0), color(0.7, 0.7, 0.7), 1e-9);
}

TEST_CASE("leaving: beyond the critical angle the light is totally internally reflected", "[04][leaving]") {
    // From inside at 60 degrees: eta = 1.5 / 1, cos_i = 0.5,
    //   k = 1 - eta^2 (1 - cos_i^2) = 1 - 2.25 * 0.75 = -0.6875 < 0
    // so F = 1 and nothing gets out: all of kst goes to the reflected ray, back down into
    // the glass onto the green floor. No red at all.
    const test_scene t = green_floor_red_ceiling();
    for (const double degrees : {45.0, 60.0, 80.0}) {
        const ray r = from_inside(degrees);
        CHECK_COLOR(show(r) << " starts inside glass of ior 1.5 and meets its surface " << num(degrees)
                            << " degrees from the normal, beyond the critical angle 41.81: k < 0, total internal "
                               "reflection, F = 1, all green",
                    t.trace(r, 1), color(0, 1, 0), 1e-9);
    }
}

TEST_CASE("leaving: at the critical angle all the light is reflected", "[04][leaving]") {
    // At sin a = 1 / 1.5 exactly, k = 1 - 2.25 (4/9) = 0 (up to round-off): cos_t = 0, the
    // transmitted ray would graze the surface, and F = R0 + (1 - R0) (1 - cos_t)^5 = 1
    // (the cosine on the air side, which is cos_t here). So again all green. (With cos_i
    // on the glass side instead, F would be 0.041 and nearly all the light would leave.)
    const test_scene t = green_floor_red_ceiling();
    const double critical = std::asin(1 / 1.5) * 180 / std::numbers::pi;
    const ray r = from_inside(critical);
    CHECK_COLOR(show(r) << " starts inside glass of ior 1.5 and meets its surface at the critical angle 41.81 degrees: "
                           "F = 1 (all reflected, green), whether or not k comes out a hair above 0",
                t.trace(r, 1), color(0, 1, 0), 1e-6);
}

TEST_CASE("leaving: a ray leaving glass bends away from the normal by Snell's law", "[04][leaving]") {
    // From inside at 30 degrees: eta = 1.5, sin_t = 1.5 sin 30 = 0.75, cos_t = 0.6614,
    //   T = eta d + (eta cos_i - cos_t) N = (0.75, 0.6614, 0) with N = (0, -1, 0) negated,
    // 48.6 degrees from the vertical. At height 5, T is at x = 5 * 0.75 / 0.6614 = 5.67:
    // a green emitter there. A ray that does not bend reaches x = 5 tan 30 = 2.89 (red);
    // eta the wrong way up (1 / 1.5) reaches x = 1.77 (blue). The reflected part goes
    // down into the black below. F from inside at 30 degrees is 0.044 (Schlick, cosine on
    // the air side) or 0.055 (exact), so the green weight is 1 - F, about 0.95.
    test_scene t;
    t.s.ambient = color(1, 1, 1);
    t.add(glass_below(surface{.kst = 1, .ior = 1.5}));
    const double sin_t = 1.5 * std::sin(radians(30)), cos_t = std::sqrt(1 - sin_t * sin_t);
    const double landing = 5 * sin_t / cos_t;
    t.add(std::make_unique<test_sphere>(point(landing, 5, 0), 0.4, emitter(color(0, 1, 0))));
    t.add(std::make_unique<test_sphere>(point(5 * std::tan(radians(30)), 5, 0), 0.4, emitter(color(1, 0, 0))));
    t.add(std::make_unique<test_sphere>(point(1.768, 5, 0), 0.4, emitter(color(0, 0, 1))));
    const double cos_i = std::cos(radians(30));
    const double schlick_f = schlick(1.5, 1, cos_i), exact_f = fresnel_exact(1.5, 1, cos_i);
    const double f = (schlick_f + exact_f) / 2, tolerance = std::fabs(schlick_f - exact_f) / 2 + 0.002;
    const ray r = from_inside(30);
    CHECK_COLOR(show(r) << " leaves glass of ior 1.5 at the origin 30 degrees from the normal: T = (0.75, 0.6614, "
                           "0) reaches the green emitter at ("
                        << num(landing) << ", 5, 0) with weight 1 - F; red means no bending, blue eta upside down",
                t.trace(r, 1), color(0, 1 - f, 0), tolerance);
}

TEST_CASE("leaving: Schlick from inside takes the cosine on the air side", "[04][leaving]") {
    // From inside at 40 degrees, just below the critical angle: sin_t = 1.5 sin 40 =
    // 0.9642, cos_t = 0.2652. The cosine for Schlick is on the side of the lower index
    // (the air): cos_t.
    //   F = 0.04 + 0.96 (1 - 0.2652)^5 = 0.2456;  the exact equations give 0.2453
    // With cos_i = cos 40 = 0.766 instead, F would be 0.0407: far too little reflection.
    const double cos_i = std::cos(radians(40));
    const double schlick_f = schlick(1.5, 1, cos_i), exact_f = fresnel_exact(1.5, 1, cos_i);
    const double f = (schlick_f + exact_f) / 2, tolerance = std::fabs(schlick_f - exact_f) / 2 + 0.01;
    const test_scene t = green_floor_red_ceiling();
    const ray r = from_inside(40);
    CHECK_COLOR(show(r) << " starts inside glass of ior 1.5 and meets its surface 40 degrees from the normal: F "
                           "(green, reflected back in) is "
                        << num(schlick_f) << " by Schlick with cos_t, " << num(exact_f)
                        << " exactly; 1 - F gets out (red). F near 0.04 means Schlick was given cos_i",
                t.trace(r, 1), color(1 - f, f, 0), tolerance);
}
