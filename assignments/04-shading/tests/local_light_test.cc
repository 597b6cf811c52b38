// Public tests of the local light (stage_04.hh, steps 1 to 3 and 6): the background,
// ambient, diffuse (Lambert) and highlight (Blinn-Phong) terms, the surface colour as a
// filter, lights behind a surface, no clamping. Run them with
// `build/student/stage_04_public_test "[local]"`. Every test here traces at depth 0 and
// places its lights where no shadow can fall, so only the local light is seen.
#include "vl/catch.hh"

#include <cmath>

#include "test_support.hh"

using namespace vl;
using namespace vl::stage04::testing;

TEST_CASE("local light: a ray that hits nothing sees the scene's background", "[04][local]") {
    // One sphere at the origin; the rays below point away from it.
    test_scene t;
    t.s.background = color(0.2, 0.4, 0.6);
    t.add(std::make_unique<test_sphere>(point(0, 0, 0), 1, surface{.clr = color(1, 0, 0), .kdr = 1}));
    t.s.ambient = color(1, 1, 1);
    for (const ray& r : {ray(point(0, 0, 5), vector(0, 0, 1)), ray(point(0, 3, 0), vector(1, 0, 0))}) {
        for (const int depth : {0, 3}) {
            CHECK_COLOR(show(r) << " at depth " << depth
                                << " misses every object, so trace() must return scene.background (step 1)",
                        t.trace(r, depth), t.s.background, 0);
        }
    }
}

TEST_CASE("local light: a composite_only answer from the root is a miss and sees the background", "[04][local]") {
    // The root here is a list with a bound (a sphere of radius 3 at the origin), like a
    // BVH or BOUNDSPH: a ray that enters the bound but hits no child gets
    // composite_only(root), t == 0 (intersection rule 2). That is not a hit: hit() is
    // false, and there is no surface to shade.
    test_scene t;
    t.s.root = std::make_unique<bounded_root>(point(0, 0, 0), 3);
    t.s.background = color(0.2, 0.4, 0.6);
    t.s.ambient = color(1, 1, 1);
    t.add(std::make_unique<test_sphere>(point(0, 0, 0), 0.5, emitter(color(1, 0, 0))));
    const ray r(point(2, 0, 5), vector(0, 0, -1));  // passes 2 from the centre: inside the bound, beside the sphere
    REQUIRE(t.s.root->intersect(r).is_composite_only());
    CHECK_COLOR(show(r) << " enters the root's bound and hits nothing (the root answers composite_only, t == 0): "
                           "test hit.hit(), not hit.object != nullptr, and return the background",
                t.trace(r, 0), t.s.background, 0);
}

TEST_CASE("local light: ambient alone is ambient times colour times kdr", "[04][local]") {
    // No lights: ambient * c * kdr, channel by channel:
    //   (0.2, 0.4, 1) * (0.8, 0.5, 0.2) * 0.5 = (0.08, 0.1, 0.1)
    test_scene t;
    t.s.ambient = color(0.2, 0.4, 1);
    t.add(std::make_unique<test_sphere>(point(0, 0, 0), 1, surface{.clr = color(0.8, 0.5, 0.2), .kdr = 0.5}));
    const ray r(point(0, 0, 5), vector(0, 0, -1));
    CHECK_COLOR(show(r) << " hits the sphere (colour (0.8, 0.5, 0.2), kdr 0.5) at (0, 0, 1) with ambient (0.2, 0.4, "
                           "1) and no lights: ambient * clr * kdr",
                t.trace(r, 0), color(0.08, 0.1, 0.1), 1e-12);
}

TEST_CASE("local light: diffuse under a light straight above is kdr times the colours", "[04][local]") {
    // A scene file: a sphere of radius 1 at the origin, a light straight above it. The
    // ray down the y axis hits the top (0, 1, 0), where N = (0, 1, 0) and L = (0, 1, 0):
    //   kdr * max(0, N.L) * (c * Lc) = 0.75 * 1 * (0.8, 0.6, 0.4) * (1, 1, 0.5) = (0.6, 0.45, 0.15)
    // (no ambient, no highlight: ksr is 0).
    const scene s = read_scene_text(
        "tracer whitted  ambient 0 0 0\n"
        "light { color 1 1 0.5  position 0 10 0 }\n"
        "SPHERE { center 0 0 0  radius 1  color 0.8 0.6 0.4  kdr 0.75 }\n");
    const ray r(point(0, 5, 0), vector(0, -1, 0));
    CHECK_COLOR(show(r) << " hits the top of the sphere (0, 1, 0), right under the light at (0, 10, 0): N.L = 1, "
                           "so the colour is kdr * (clr * light colour)",
                trace_in(s, r, 0), color(0.6, 0.45, 0.15), 1e-12);
}

TEST_CASE("local light: diffuse falls off with the cosine between the normal and the light", "[04][local]") {
    // The floor y = 0 (kdr 1, white) and a white light at height 1. A point at distance
    // x from the foot of the light sees it at angle a from the normal, cos a = 1 / sqrt(1
    // + x^2): at x = sqrt(3), N.L = 1/2 (60 degrees); at x = 1, N.L = 1/sqrt(2) (45 degrees).
    test_scene t;
    t.add(floor_plane(surface{.kdr = 1}));
    t.light(color(1, 1, 1), point(0, 1, 0));
    for (const double x : {0.0, 1.0, std::sqrt(3.0), 3.0}) {
        const ray r(point(x, 2, 0), vector(0, -1, 0));  // straight down onto (x, 0, 0)
        const double cos_a = 1 / std::sqrt(1 + x * x);
        CHECK_COLOR(show(r) << " hits the floor at (" << num(x) << ", 0, 0); the light at (0, 1, 0) is at cos a = 1 / "
                               "sqrt(1 + x^2) = "
                            << num(cos_a) << " from the normal: kdr * N.L * white = N.L",
                    t.trace(r, 0), color(cos_a, cos_a, cos_a), 1e-12);
    }
}

TEST_CASE("local light: lights do not fade with distance", "[04][local]") {
    // The same light straight above the floor at height 1 and at height 1000 gives the
    // same diffuse light: N.L = 1, kdr 0.5, so (0.5, 0.5, 0.5) in both.
    for (const double height : {1.0, 1000.0}) {
        test_scene t;
        t.add(floor_plane(surface{.kdr = 0.5}));
        t.light(color(1, 1, 1), point(0, height, 0));
        const ray r(point(0, 0.5, 0), vector(0, -1, 0));
        CHECK_COLOR(show(r) << " hits the floor at the origin under a white light at height " << num(height)
                            << ": kdr * N.L = 0.5 whatever the distance (no 1/d^2)",
                    t.trace(r, 0), color(0.5, 0.5, 0.5), 1e-12);
    }
}

TEST_CASE("local light: the surface colour filters the light channel by channel", "[04][local]") {
    // A red surface (1, 0, 0), kdr 1, the light straight above. Colours multiply channel
    // by channel (vl::color's *, not a dot product):
    //   white light (1, 1, 1): (1, 0, 0) * (1, 1, 1) = (1, 0, 0)
    //   cyan light  (0, 1, 1): (1, 0, 0) * (0, 1, 1) = (0, 0, 0)  (a red surface reflects no cyan)
    //   (0.5, 0.25, 1) on colour (0.8, 0.6, 0.4): (0.4, 0.15, 0.4)
    struct example {
        color surface_colour, light_colour, want;
    };
    for (const example& e : {example{color(1, 0, 0), color(1, 1, 1), color(1, 0, 0)},
                             example{color(1, 0, 0), color(0, 1, 1), color(0, 0, 0)},
                             example{color(0.8, 0.6, 0.4), color(0.5, 0.25, 1), color(0.4, 0.15, 0.4)}}) {
        test_scene t;
        t.add(floor_plane(surface{.clr = e.surface_colour, .kdr = 1}));
        t.light(e.light_colour, point(0, 4, 0));
        const ray r(point(0, 1, 0), vector(0, -1, 0));
        CHECK_COLOR(show(r) << " hits a floor of colour " << show(e.surface_colour) << " (kdr 1) under a light of colour "
                            << show(e.light_colour) << " straight above: clr * light colour, channel by channel",
                    t.trace(r, 0), e.want, 1e-12);
    }
}

TEST_CASE("local light: a light behind the surface adds neither diffuse nor highlight", "[04][local]") {
    // The floor y = 0 faces up; the light is below it, at (4, -0.5, 0), so N.L < 0. The
    // eye at (-4, 1, 0) looks at the origin; the half vector H = (L - d).unit() still has
    // N.H = 0.98 here, so a highlight computed without the N.L test would shine. The
    // contract: a light with N.L <= 0 adds nothing. Only the ambient term remains:
    //   ambient * c * kdr = 0.2 * (1, 0.5, 0.25) * 0.5 = (0.1, 0.05, 0.025)
    test_scene t;
    t.s.ambient = color(0.2, 0.2, 0.2);
    t.add(floor_plane(surface{.clr = color(1, 0.5, 0.25), .kdr = 0.5, .ksr = 1, .n = 2}));
    t.light(color(1, 1, 1), point(4, -0.5, 0));
    const ray r = ray_through(point(-4, 1, 0), point(0, 0, 0));
    CHECK_COLOR(show(r) << " hits the floor (normal +y) at the origin; the only light is below the floor at (4, "
                           "-0.5, 0), behind the surface: ambient alone",
                t.trace(r, 0), color(0.1, 0.05, 0.025), 1e-12);
}

TEST_CASE("local light: a plane seen from behind is lit only by a light on its front side", "[04][local]") {
    // "Nothing else flips N" (step 2): a plane has no inside, so its normal is never
    // negated, even when the eye is behind it. The floor faces +y; the eye is below it.
    // A light below (on the eye's side) adds nothing; a light above (the front side), at
    // (3, 4, 0), lights the origin with L = (0.6, 0.8, 0), N.L = 0.8:
    //   kdr * N.L * (c * Lc) = 0.5 * 0.8 * (1, 1, 1) = (0.4, 0.4, 0.4)
    // (The light is off the ray's line: straight above, L would equal d and the half
    // vector L - d would be the zero vector, which has no direction.)
    const ray r(point(0, -2, 0), vector(0, 1, 0));  // from below, up onto the origin
    {
        test_scene t;
        t.add(floor_plane(surface{.kdr = 0.5}));
        t.light(color(1, 1, 1), point(0, -5, 0));
        CHECK_COLOR(show(r) << " hits the floor (normal +y) from below; the light at (0, -5, 0) is on the back "
                               "side, N.L = -1: nothing (do not turn the normal towards the eye)",
                    t.trace(r, 0), BLACK, 1e-12);
    }
    {
        test_scene t;
        t.add(floor_plane(surface{.kdr = 0.5}));
        t.light(color(1, 1, 1), point(3, 4, 0));
        CHECK_COLOR(show(r) << " hits the floor (normal +y) from below; the light at (3, 4, 0) is on its front "
                               "side, N.L = 0.8: kdr * N.L * white",
                    t.trace(r, 0), color(0.4, 0.4, 0.4), 1e-12);
    }
}

TEST_CASE("local light: the highlight at the mirror angle is ksr times the colours", "[04][local]") {
    // The floor (kdr 0, ksr 0.7, n 50, colour (1, 0.5, 0.25)); light at (-3, 4, 0), eye at
    // (3, 4, 0), both 5 from the origin. L = (-3, 4, 0)/5, d = (-3, -4, 0)/5, so
    //   H = (L - d).unit() = (0, 8/5, 0).unit() = (0, 1, 0) = N,  N.H = 1,  1^50 = 1
    //   ksr * 1 * (c * Lc) = 0.7 * (1, 0.5, 0.25) = (0.7, 0.35, 0.175)
    test_scene t;
    t.add(floor_plane(surface{.clr = color(1, 0.5, 0.25), .ksr = 0.7, .n = 50}));
    t.light(color(1, 1, 1), point(-3, 4, 0));
    const ray r = ray_through(point(3, 4, 0), point(0, 0, 0));
    CHECK_COLOR(show(r) << " hits the floor at the origin, the light at (-3, 4, 0) being at the mirror angle: H = N, "
                           "so ksr * max(0, N.H)^n * (clr * light colour) = ksr * clr",
                t.trace(r, 0), color(0.7, 0.35, 0.175), 1e-9);
}

TEST_CASE("local light: the highlight uses Blinn's half vector H = (L - d).unit()", "[04][local]") {
    // The eye straight above the origin (d = (0, -1, 0)), the light at 60 degrees from
    // the normal: L = (sin 60, cos 60, 0). H lies halfway, at 30 degrees from N:
    //   N.H = cos 30 = sqrt(3)/2;  n = 4: (sqrt(3)/2)^4 = 9/16 = 0.5625;  n = 1: 0.8660...
    // (Phong's R.V would be cos 60 = 0.5, and 0.5^4 = 0.0625.) kdr 0: the highlight alone.
    for (const double exponent : {1.0, 4.0}) {
        test_scene t;
        t.add(floor_plane(surface{.ksr = 1, .n = exponent}));
        t.light(color(1, 1, 1), point(0, 0, 0) + 2 * from_vertical(60));
        const ray r(point(0, 3, 0), vector(0, -1, 0));
        const double want = std::pow(std::sqrt(3.0) / 2, exponent);
        CHECK_COLOR(show(r) << " hits the floor at the origin; the light is 60 degrees from the normal, so H is 30 "
                               "degrees from it: ksr * cos(30 degrees)^n with n = "
                            << num(exponent) << " (Phong's mirror vector would give 0.5^n)",
                    t.trace(r, 0), color(want, want, want), 1e-9);
    }
}

TEST_CASE("local light: trace does not clamp a sum above 1", "[04][local]") {
    // Ambient (0.5, 0.5, 0.5) and two white lights straight above a white floor with kdr
    // 1: 0.5 + 1 + 1 = 2.5 in every channel. The frame buffer clamps when it stores a
    // pixel; trace() returns the sum as it is (step 6).
    test_scene t;
    t.s.ambient = color(0.5, 0.5, 0.5);
    t.add(floor_plane(surface{.kdr = 1}));
    t.light(color(1, 1, 1), point(0, 3, 0));
    t.light(color(1, 1, 1), point(0, 6, 0));
    const ray r(point(0, 1, 0), vector(0, -1, 0));
    CHECK_COLOR(show(r) << " hits a white floor (kdr 1) under two white lights straight above, with ambient 0.5: "
                           "0.5 + 1 + 1, not clamped to 1",
                t.trace(r, 0), color(2.5, 2.5, 2.5), 1e-12);
}
