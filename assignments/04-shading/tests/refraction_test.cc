// Public tests of refraction for rays ENTERING glass from the air (stage_04.hh, step 5):
// Snell's direction, the Fresnel reflectance F near 0 and at 90 degrees, the weight
// w_t = kst (1 - F) and the glass colour as a filter. Run them with
// `build/student/stage_04_public_test "[refraction]"`.
//
// The glass fills everything below the plane y = 0 (test_support.hh's glass_below: its
// normal +y points out into the air, contains() is true for y < 0). There are no lights,
// ambient is (1, 1, 1) and the background is black. A white emitter (kdr 1) lies inside
// the glass, 20 along Snell's transmitted direction T from the point hit, and nothing
// else: the reflected ray goes up into the black sky. So what the bounces add is
//   c * w_t * E,  w_t = kst (1 - F)
// with E the emitter's colour as your tracer shows it (a ray aimed straight at it) and c
// the glass colour: the tests read F from the light that gets in. (The mirror's weight
// w_r = ksr + kst F is a [reflection] test.) "What the bounces add" is your trace() of the
// ray minus your trace() of the same ray with the glass made dull (ksr = kst = 0); the
// rays are traced at depth 3, and every secondary ray ends after one bounce.
//
// Where F is checked, the expected value is between Schlick's approximation and the exact
// Fresnel equations (both are accepted), with a tolerance that covers both.
#include "vl/catch.hh"

#include <algorithm>
#include <cmath>

#include "test_support.hh"

using namespace vl;
using namespace vl::stage04::testing;

namespace {

/// The ray from the air that hits the glass at the origin `degrees` from the normal.
ray onto_glass(double degrees) {
    const vector d(std::sin(radians(degrees)), -std::cos(radians(degrees)), 0);
    return ray(point(0, 0, 0) - 5 * d, d);
}

/// Snell's transmitted direction into glass of ior 1.5 for onto_glass(degrees): sin t =
/// sin i / 1.5, T = (sin t, -cos t, 0).
vector snell_into_glass(double degrees) {
    const double sin_t = std::sin(radians(degrees)) / 1.5;
    return vector(sin_t, -std::sqrt(1 - sin_t * sin_t), 0);
}

/// Glass (`looks`) below y = 0 and a white emitter of radius 0.4 at 20 T inside it.
test_scene into_glass(const surface& looks, const vector& transmitted) {
    test_scene t;
    t.s.ambient = color(1, 1, 1);
    t.add(glass_below(looks));
    t.add(std::make_unique<test_sphere>(point(0, 0, 0) + 20 * transmitted, 0.4, emitter(color(1, 1, 1))));
    return t;
}

/// What the glass transmits of onto_glass(degrees) at depth 3, and your colour of the
/// emitter (the ray from 10 T along T, inside the glass, straight at it).
struct transmitted_light {
    color added, emitter;
};
transmitted_light transmitted(const surface& glass, double degrees) {
    const vector tr = snell_into_glass(degrees);
    const test_scene t = into_glass(glass, tr), plain = into_glass(dull(glass), tr);
    return {bounce_part(t, plain, onto_glass(degrees), 3), t.trace(ray(point(0, 0, 0) + 10 * tr, tr), 0)};
}

/// The expected F at `degrees` from the air onto ior 1.5: the middle of Schlick's and the
/// exact value; `spread` is half their difference.
struct fresnel {
    double schlick, exact, middle, spread;
};
fresnel entering_f(double degrees) {
    const double cos_i = std::cos(radians(degrees));
    const double s = schlick(1, 1.5, cos_i), e = fresnel_exact(1, 1.5, cos_i);
    return {s, e, (s + e) / 2, std::fabs(s - e) / 2};
}

}  // namespace

TEST_CASE("refraction: near normal incidence Schlick reflects R0 = 0.04 for ior 1.5", "[04][refraction]") {
    // 10 degrees onto glass of ior 1.5 (kst 1, ksr 0, white): cos_i = 0.9848, so
    //   R0 = ((1 - 1.5) / (1 + 1.5))^2 = (-0.5 / 2.5)^2 = 0.04
    //   F = R0 + (1 - R0) (1 - 0.9848)^5 = 0.04 + 8e-10   (the exact equations: 0.040015)
    //   w_t = kst (1 - F) = 0.96 of the emitter E
    // (Not straight down: there a mirror ray turned the wrong way would go straight on
    // into the emitter too, and this test would see it.)
    const fresnel f = entering_f(10);
    const transmitted_light got = transmitted(surface{.kst = 1, .ior = 1.5}, 10);
    REQUIRE_EMITTER_SEEN("the white emitter inside the glass", got.emitter);
    CHECK_COLOR(show(onto_glass(10)) << " hits glass of ior 1.5 10 degrees from the normal: F = R0 = 0.04 is reflected, so "
                                  "0.96 of the emitter "
                               << show(got.emitter) << " gets in along T",
                got.added, (1 - f.middle) * got.emitter, f.spread + 1e-6);
}

TEST_CASE("refraction: near head on - glass with ksr 0.3 and kst 0.5 transmits kst (1 - F) = 0.48", "[04][refraction]") {
    // Glass with ksr 0.3 and kst 0.5, 10 degrees from the normal (F = 0.04):
    //   w_t = kst (1 - F) = 0.5 * 0.96 = 0.48 of the emitter. (ksr adds to the mirror ray
    //   only, which goes up into the black sky.)
    const fresnel f = entering_f(10);
    const transmitted_light got = transmitted(surface{.ksr = 0.3, .kst = 0.5, .ior = 1.5}, 10);
    REQUIRE_EMITTER_SEEN("the white emitter inside the glass", got.emitter);
    CHECK_COLOR(show(onto_glass(10)) << " hits glass with ksr 0.3, kst 0.5, ior 1.5 10 degrees from the normal: w_t = kst (1 "
                                  "- F) = 0.48 of the emitter "
                               << show(got.emitter) << " gets in (ksr does not)",
                got.added, 0.5 * (1 - f.middle) * got.emitter, 0.5 * f.spread + 1e-6);
}

TEST_CASE("refraction: tinted glass filters the light it transmits", "[04][refraction]") {
    // The colour of the glass multiplies the transmitted light (step 5: c * (w_r ... +
    // w_t ...)). Colour (0.5, 0.8, 1), kst 1, 10 degrees from the normal, a white emitter:
    //   (0.5, 0.8, 1) * 0.96 * (1, 1, 1) = (0.48, 0.768, 0.96)
    const fresnel f = entering_f(10);
    const color tint(0.5, 0.8, 1);
    const transmitted_light got = transmitted(surface{.clr = tint, .kst = 1, .ior = 1.5}, 10);
    REQUIRE_EMITTER_SEEN("the white emitter inside the glass", got.emitter);
    CHECK_COLOR(show(onto_glass(10)) << " enters glass of colour (0.5, 0.8, 1): the colour filters the 0.96 of the emitter "
                               << show(got.emitter) << " that gets in",
                got.added, (1 - f.middle) * (tint * got.emitter), f.spread + 1e-6);
}

TEST_CASE("refraction: at grazing incidence from the air nearly all light is reflected", "[04][refraction]") {
    // 89.9 degrees from the normal, cos_i = 0.001745:
    //   Schlick: 0.04 + 0.96 (1 - 0.001745)^5 = 0.99165;  exact Fresnel: 0.98991
    // so F is about 0.99 (reflected, up into the black sky) and only 1 - F, about 0.009,
    // gets in to the emitter. (With no Fresnel term, all of kst would get in.)
    const fresnel f = entering_f(89.9);
    const transmitted_light got = transmitted(surface{.kst = 1, .ior = 1.5}, 89.9);
    REQUIRE_EMITTER_SEEN("the white emitter inside the glass", got.emitter);
    CHECK_COLOR(show(onto_glass(89.9)) << " grazes glass of ior 1.5 at 89.9 degrees from the normal: F is "
                                 << num(f.schlick) << " by Schlick, " << num(f.exact)
                                 << " exactly; only 1 - F of the emitter " << show(got.emitter) << " gets in",
                got.added, (1 - f.middle) * got.emitter, f.spread + 0.002);
}

TEST_CASE("refraction: a ray entering glass bends towards the normal by Snell's law", "[04][refraction]") {
    // 45 degrees onto glass of ior 1.5 at the origin: eta = 1 / 1.5, cos_i = cos 45,
    //   k = 1 - eta^2 (1 - cos_i^2) = 1 - 0.5 / 2.25 = 0.7778,  cos_t = sqrt(k) = 0.8819
    //   T = eta d + (eta cos_i - cos_t) N = (0.4714, -0.8819, 0): 28.1 degrees from -N
    // The emitter waits at 20 T = (9.43, -17.64, 0). A ray that does not bend goes on to
    // (14.1, -14.1, 0) at that distance, and eta the wrong way up (1.5) gives k < 0, total
    // reflection: both see only black. The bounces add kst (1 - F) E, F = 0.042 (Schlick)
    // or 0.050 (exact) at 45 degrees.
    const fresnel f = entering_f(45);
    const transmitted_light got = transmitted(surface{.kst = 1, .ior = 1.5}, 45);
    REQUIRE_EMITTER_SEEN("the white emitter inside the glass", got.emitter);
    CHECK_COLOR(show(onto_glass(45)) << " enters glass of ior 1.5 at the origin, 45 degrees from the normal: T = eta d + (eta "
                                  "cos_i - cos_t) N = (0.4714, -0.8819, 0) reaches the emitter at "
                               << show(point(0, 0, 0) + 20 * snell_into_glass(45)) << " with weight 1 - F; black "
                                  "means T went elsewhere",
                got.added, (1 - f.middle) * got.emitter, f.spread + 0.002);
}
