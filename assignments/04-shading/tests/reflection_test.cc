// Public tests of mirror reflection (stage_04.hh, step 5 with kst == 0): the mirror
// direction R = d - 2 (d.N) N, the weight ksr, the surface colour as a filter, and the
// depth limit. Run them with `build/student/stage_04_public_test "[reflection]"`.
//
// These scenes have no lights and ambient (1, 1, 1): an object with kdr 1 then sends
// back exactly its colour (an "emitter", see test_support.hh), and a mirror with kdr 0
// sends back only what it reflects. So the colour you get says where the reflected ray went.
#include <catch2/catch.hpp>

#include <cmath>

#include "test_support.hh"

using namespace vl;
using namespace vl::stage04::testing;

namespace {

/// A mirror floor y = 0 with `looks`, a green emitter at (2, 2, 0) where the ray from
/// (-2, 2, 0) to the origin is reflected, and a red one at (2, -2, 0) below the floor,
/// where the ray would go on if it were not reflected.
test_scene mirror_floor(const surface& looks) {
    test_scene t;
    t.s.ambient = color(1, 1, 1);
    t.add(floor_plane(looks));
    t.add(std::make_unique<test_sphere>(point(2, 2, 0), 0.5, emitter(color(0.2, 0.9, 0.4))));
    t.add(std::make_unique<test_sphere>(point(2, -2, 0), 0.5, emitter(color(1, 0, 0))));
    return t;
}

const ray at_the_mirror = ray_through(point(-2, 2, 0), point(0, 0, 0));  // 45 degrees onto the origin

}  // namespace

TEST_CASE("reflection: at depth 0 a mirror shows only its own local light", "[04][reflection]") {
    // The mirror floor (ksr 1, kdr 0.2, white) under ambient 1: its local light is
    // ambient * c * kdr = 0.2. At depth 0 nothing is reflected (step 5 runs only when
    // depth > 0), so the emitter in the mirror direction is not seen.
    const test_scene t = mirror_floor(surface{.kdr = 0.2, .ksr = 1});
    CHECK_COLOR(show(at_the_mirror) << " hits a mirror (ksr 1, kdr 0.2) at depth 0: no reflected ray is traced, only "
                                       "the ambient term 1 * 1 * 0.2",
                t.trace(at_the_mirror, 0), color(0.2, 0.2, 0.2), 1e-12);
}

TEST_CASE("reflection: one bounce off a plane mirror sees what lies in the mirror direction", "[04][reflection]") {
    // The ray from (-2, 2, 0) hits the floor at the origin with d = (1, -1, 0)/sqrt(2),
    // N = (0, 1, 0): R = d - 2 (d.N) N = (1, 1, 0)/sqrt(2), straight at the green emitter
    // (0.2, 0.9, 0.4) at (2, 2, 0). With ksr 0.8, kdr 0 and a white mirror:
    //   c * ksr * trace(R) = 0.8 * (0.2, 0.9, 0.4) = (0.16, 0.72, 0.32)
    // (Red would mean the ray went on through the floor to the emitter at (2, -2, 0).)
    const test_scene t = mirror_floor(surface{.ksr = 0.8});
    for (const int depth : {1, 4}) {
        CHECK_COLOR(show(at_the_mirror) << " at depth " << depth
                                        << " is reflected at the origin towards (1, 1, 0)/sqrt(2) and sees the green "
                                           "emitter at (2, 2, 0): ksr 0.8 times its colour (0.2, 0.9, 0.4)",
                    t.trace(at_the_mirror, depth), color(0.16, 0.72, 0.32), 1e-9);
    }
}

TEST_CASE("reflection: a coloured mirror filters what it reflects", "[04][reflection]") {
    // The mirror's colour c multiplies what comes back (step 5: c * w_r * trace(R)). An
    // orange mirror (1, 0.5, 0), ksr 1, kdr 0, sees a white emitter:
    //   (1, 0.5, 0) * 1 * (1, 1, 1) = (1, 0.5, 0)
    test_scene t;
    t.s.ambient = color(1, 1, 1);
    t.add(floor_plane(surface{.clr = color(1, 0.5, 0), .ksr = 1}));
    t.add(std::make_unique<test_sphere>(point(2, 2, 0), 0.5, emitter(color(1, 1, 1))));
    CHECK_COLOR(show(at_the_mirror) << " is reflected by an orange mirror (colour (1, 0.5, 0), ksr 1) towards a white "
                                       "emitter: the mirror's colour filters the reflection",
                t.trace(at_the_mirror, 1), color(1, 0.5, 0), 1e-9);
}

TEST_CASE("reflection: a mirror's own local light and its reflection add up", "[04][reflection]") {
    // A white mirror with kdr 0.3 and ksr 0.5 under ambient 1, reflecting the emitter
    // (0.2, 0.9, 0.4):  ambient * c * kdr + c * ksr * (0.2, 0.9, 0.4)
    //   = (0.3, 0.3, 0.3) + (0.1, 0.45, 0.2) = (0.4, 0.75, 0.5)
    const test_scene t = mirror_floor(surface{.kdr = 0.3, .ksr = 0.5});
    CHECK_COLOR(show(at_the_mirror) << " hits a mirror with kdr 0.3 and ksr 0.5: its ambient term 0.3 plus 0.5 times "
                                       "the emitter it reflects",
                t.trace(at_the_mirror, 1), color(0.4, 0.75, 0.5), 1e-9);
}

TEST_CASE("reflection: the mirror direction on a sphere uses its normal at the hit", "[04][reflection]") {
    // A mirror sphere of radius 1 at the origin. The ray along +x at height sin 45 hits
    // it at P = (-cos 45, sin 45, 0), where N = P: d.N = -cos 45, so
    //   R = d - 2 (d.N) N = (1, 0, 0) + sqrt(2) (-1/sqrt(2), 1/sqrt(2), 0) = (0, 1, 0)
    // straight up, to the green emitter 3 above P. The red emitter at (3, 0.7, 0) is where the
    // ray would go without reflection, the blue one at (-4, 0.7, 0) where R = -d would go.
    test_scene t;
    t.s.ambient = color(1, 1, 1);
    const double s45 = std::sqrt(0.5);
    t.add(std::make_unique<test_sphere>(point(0, 0, 0), 1, surface{.ksr = 1}));
    t.add(std::make_unique<test_sphere>(point(-s45, s45 + 3, 0), 0.5, emitter(color(0, 1, 0))));
    t.add(std::make_unique<test_sphere>(point(3, s45, 0), 0.5, emitter(color(1, 0, 0))));
    t.add(std::make_unique<test_sphere>(point(-4, s45, 0), 0.5, emitter(color(0, 0, 1))));
    const ray r(point(-2.5, s45, 0), vector(1, 0, 0));
    CHECK_COLOR(show(r) << " hits the mirror sphere at (-0.7071, 0.7071, 0), 45 degrees from its normal, and must be "
                           "reflected straight up (R = d - 2 (d.N) N = (0, 1, 0)) to the green emitter",
                t.trace(r, 1), color(0, 1, 0), 1e-9);
}

TEST_CASE("reflection: two facing mirrors stop at the depth limit", "[04][reflection]") {
    // Mirrors x = -1 (facing +x) and x = 1 (facing -x), each white with kdr 0.25 and ksr
    // 0.5, under ambient 1. A ray along +x bounces between them; each hit adds its ambient
    // term 0.25 and half of what comes back from the next one. Depth k allows k bounces,
    // so k + 1 hits:
    //   trace(depth k) = 0.25 (1 + 0.5 + 0.5^2 + ... + 0.5^k) = 0.25 (2 - 0.5^k)
    //   depth 0: 0.25   1: 0.375   2: 0.4375   3: 0.46875   10: 0.499755859375
    test_scene t;
    t.s.ambient = color(1, 1, 1);
    const surface half_mirror{.kdr = 0.25, .ksr = 0.5};
    t.add(std::make_unique<test_plane>(point(-1, 0, 0), vector(1, 0, 0), half_mirror));
    t.add(std::make_unique<test_plane>(point(1, 0, 0), vector(-1, 0, 0), half_mirror));
    const ray r(point(0, 0, 0), vector(1, 0, 0));
    for (const int depth : {0, 1, 2, 3, 10}) {
        const double want = 0.25 * (2 - std::pow(0.5, depth));
        CHECK_COLOR(show(r) << " between two facing mirrors (kdr 0.25, ksr 0.5) at depth " << depth << ": " << depth
                            << " bounces, " << depth + 1 << " hits, 0.25 (2 - 0.5^" << depth << ")",
                    t.trace(r, depth), color(want, want, want), 1e-9);
    }
}
