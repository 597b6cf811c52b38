// Public tests of refraction for rays ENTERING glass from the air (stage_04.hh, step 5):
// Snell's direction, the Fresnel reflectance F at 0 and 90 degrees, and the weights
// w_r = ksr + kst F, w_t = kst (1 - F). Run them with
// `build/student/stage_04_public_test "[refraction]"`.
//
// The glass fills everything below the plane y = 0 (test_support.hh's glass_below: its
// normal +y points out into the air, contains() is true for y < 0). There are no lights
// and ambient is (1, 1, 1), so an emitter (kdr 1) sends back exactly its colour. Most
// tests make the reflected light red and the transmitted light green: the background is
// red (the reflected ray goes up into the empty sky), and a green emitter floor lies
// inside the glass at y = -1. Then trace() returns (w_r, w_t, 0) times the glass colour.
//
// Where F is checked, the expected value is between Schlick's approximation and the exact
// Fresnel equations (both are accepted), with a tolerance that covers both.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "test_support.hh"

using namespace vl;
using namespace vl::stage04::testing;

namespace {

/// Glass (`looks`) below y = 0, a red sky and a green emitter floor at y = -1 inside it.
test_scene red_sky_green_floor(const surface& looks) {
    test_scene t;
    t.s.ambient = color(1, 1, 1);
    t.s.background = color(1, 0, 0);
    t.add(glass_below(looks));
    t.add(floor_plane(emitter(color(0, 1, 0)), -1));
    return t;
}

/// The ray from the air that hits the glass at the origin `degrees` from the normal.
ray onto_glass(double degrees) {
    const vector d(std::sin(radians(degrees)), -std::cos(radians(degrees)), 0);
    return ray(point(0, 0, 0) - 5 * d, d);
}

}  // namespace

TEST_CASE("refraction: Schlick at normal incidence reflects R0 = 0.04 for ior 1.5", "[04][refraction]") {
    // Straight down onto glass of ior 1.5 (kst 1, ksr 0, white): cos_i = 1, so
    //   R0 = ((1 - 1.5) / (1 + 1.5))^2 = (-0.5 / 2.5)^2 = 0.04,  F = R0 + (1 - R0) (1 - 1)^5 = 0.04
    //   w_r = ksr + kst F = 0.04 (the red sky),  w_t = kst (1 - F) = 0.96 (the green floor)
    // (The exact Fresnel equations give 0.04 here too.)
    const test_scene t = red_sky_green_floor(surface{.kst = 1, .ior = 1.5});
    const ray r = onto_glass(0);
    CHECK_COLOR(show(r) << " hits glass of ior 1.5 head on: F = R0 = 0.04 of the light is reflected (red sky), 0.96 "
                           "transmitted (green floor inside)",
                t.trace(r, 1), color(0.04, 0.96, 0), 1e-9);
}

TEST_CASE("refraction: head on, ksr 0.3 and kst 0.5 reflect 0.32 and transmit 0.48", "[04][refraction]") {
    // Glass with ksr 0.3 and kst 0.5, head on (F = 0.04):
    //   w_r = 0.3 + 0.5 * 0.04 = 0.32 (red sky),  w_t = 0.5 * 0.96 = 0.48 (green floor)
    const test_scene t = red_sky_green_floor(surface{.ksr = 0.3, .kst = 0.5, .ior = 1.5});
    const ray r = onto_glass(0);
    CHECK_COLOR(show(r) << " hits glass with ksr 0.3, kst 0.5, ior 1.5 head on: w_r = ksr + kst F = 0.32 of the red "
                           "sky, w_t = kst (1 - F) = 0.48 of the green floor",
                t.trace(r, 1), color(0.32, 0.48, 0), 1e-9);
}

TEST_CASE("refraction: tinted glass filters the light it reflects and transmits", "[04][refraction]") {
    // The colour of the glass multiplies both rays (step 5: c * (w_r ... + w_t ...)).
    // Colour (0.5, 0.8, 1), kst 1, head on:
    //   (0.5, 0.8, 1) * (0.04 * red + 0.96 * green) = (0.02, 0.768, 0)
    const test_scene t = red_sky_green_floor(surface{.clr = color(0.5, 0.8, 1), .kst = 1, .ior = 1.5});
    const ray r = onto_glass(0);
    CHECK_COLOR(show(r) << " hits glass of colour (0.5, 0.8, 1) head on: the colour filters both the reflected 0.04 "
                           "(red) and the transmitted 0.96 (green)",
                t.trace(r, 1), color(0.02, 0.768, 0), 1e-9);
}

TEST_CASE("refraction: at grazing incidence from the air nearly all light is reflected", "[04][refraction]") {
    // 89.9 degrees from the normal, cos_i = 0.001745:
    //   Schlick: 0.04 + 0.96 (1 - 0.001745)^5 = 0.99165;  exact Fresnel: 0.98991
    // so F is about 0.99 (red sky) and 1 - F about 0.01 (green floor).
    const double cos_i = std::cos(radians(89.9));
    const double schlick_f = schlick(1, 1.5, cos_i), exact_f = fresnel_exact(1, 1.5, cos_i);
    const double f = (schlick_f + exact_f) / 2, tolerance = std::fabs(schlick_f - exact_f) / 2 + 0.002;
    const test_scene t = red_sky_green_floor(surface{.kst = 1, .ior = 1.5});
    const ray r = onto_glass(89.9);
    CHECK_COLOR(show(r) << " grazes glass of ior 1.5 at 89.9 degrees from the normal: F (red) is "
                        << num(schlick_f) << " by Schlick, " << num(exact_f) << " exactly; 1 - F is transmitted (green)",
                t.trace(r, 1), color(f, 1 - f, 0), tolerance);
}

TEST_CASE("refraction: a ray entering glass bends towards the normal by Snell's law", "[04][refraction]") {
    // 45 degrees onto glass of ior 1.5 at the origin: eta = 1 / 1.5, cos_i = cos 45,
    //   k = 1 - eta^2 (1 - cos_i^2) = 1 - 0.5 / 2.25 = 0.7778,  cos_t = sqrt(k) = 0.8819
    //   T = eta d + (eta cos_i - cos_t) N = (0.4714, -0.8819, 0): 28.1 degrees from -N
    // At depth 10 below the surface T is at x = 10 tan(28.1 degrees) = 5.345, where a green
    // emitter waits. A ray that does not bend goes on to x = 10 (a red emitter); eta the
    // wrong way up (1.5) gives k < 0, total reflection, into the black sky. Nothing
    // else is seen: the reflected F goes to the black sky.
    //   trace = kst (1 - F) green, F = 0.042 (Schlick) or 0.050 (exact) at 45 degrees.
    test_scene t;
    t.s.ambient = color(1, 1, 1);
    t.add(glass_below(surface{.kst = 1, .ior = 1.5}));
    const double sin_t = std::sin(radians(45)) / 1.5, cos_t = std::sqrt(1 - sin_t * sin_t);
    const double landing = 10 * sin_t / cos_t;
    t.add(std::make_unique<test_sphere>(point(landing, -10, 0), 0.5, emitter(color(0, 1, 0))));
    t.add(std::make_unique<test_sphere>(point(10, -10, 0), 0.5, emitter(color(1, 0, 0))));
    const double cos_i = std::cos(radians(45));
    const double schlick_f = schlick(1, 1.5, cos_i), exact_f = fresnel_exact(1, 1.5, cos_i);
    const double f = (schlick_f + exact_f) / 2, tolerance = std::fabs(schlick_f - exact_f) / 2 + 0.002;
    const ray r = onto_glass(45);
    CHECK_COLOR(show(r) << " enters glass of ior 1.5 at the origin, 45 degrees from the normal: T = eta d + (eta "
                           "cos_i - cos_t) N = (0.4714, -0.8819, 0) reaches the green emitter at ("
                        << num(landing) << ", -10, 0), with weight 1 - F; red means T did not bend",
                t.trace(r, 1), color(0, 1 - f, 0), tolerance);
}
