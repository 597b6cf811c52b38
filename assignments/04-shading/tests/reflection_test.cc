// Public tests of mirror reflection (stage_04.hh, step 5): the mirror direction
// R = d - 2 (d.N) N, the weight ksr (and ksr + kst F on glass), the surface colour as a
// filter, and the depth limit. Run them with
// `build/student/stage_04_public_test "[reflection]"`.
//
// These scenes have no lights and ambient (1, 1, 1): an object with kdr 1 then sends
// back exactly its colour (an "emitter", see test_support.hh), so the colour you get says
// where the reflected ray went. Each test looks only at what the reflection adds: your
// trace() of the ray with the mirror minus your trace() of the same ray with the mirror
// made dull (ksr 0), and it reads each emitter's colour from your own tracer (a ray aimed
// straight at it). So these tests depend on your reflection alone, not on your ambient
// term.
#include "vl/catch.hh"

#include <cmath>

#include "test_support.hh"

using namespace vl;
using namespace vl::stage04::testing;

namespace {

const point green_at(2, 2, 0);  // where the ray below is reflected to
const color green(0.2, 0.9, 0.4);

/// A mirror floor y = 0 with `looks`, a green emitter at (2, 2, 0) where the ray from
/// (-2, 2, 0) to the origin is reflected, and a red one at (2, -2, 0) below the floor,
/// where the ray would go on if it were not reflected.
test_scene mirror_floor(const surface& looks, const color& emitted = green) {
    test_scene t;
    t.s.ambient = color(1, 1, 1);
    t.add(floor_plane(looks));
    t.add(std::make_unique<test_sphere>(green_at, 0.5, emitter(emitted)));
    t.add(std::make_unique<test_sphere>(point(2, -2, 0), 0.5, emitter(color(1, 0, 0))));
    return t;
}

const ray at_the_mirror = ray_through(point(-2, 2, 0), point(0, 0, 0));  // 45 degrees onto the origin

/// Your colour of the emitter at `center`: the ray from 2 beside it along x, aimed at it.
color emitter_colour(const test_scene& t, const point& center) {
    return t.trace(ray_through(center - vector(2, 0, 0), center), 0);
}

}  // namespace

TEST_CASE("reflection: at depth 0 a mirror shows only its own local light", "[04][reflection]") {
    // The mirror floor (ksr 1, kdr 0.2, white) under ambient 1. At depth 0 nothing is
    // reflected (step 5 runs only when depth > 0), so the green emitter in the mirror
    // direction is not seen: the mirror gives exactly what the same floor with ksr 0
    // gives (its local light, ambient * c * kdr = 0.2), and the bounce part is 0.
    const surface mirror{.kdr = 0.2, .ksr = 1};
    const test_scene t = mirror_floor(mirror), plain = mirror_floor(dull(mirror));
    REQUIRE_EMITTER_SEEN("the green emitter at (2, 2, 0)", emitter_colour(t, green_at));
    CHECK_COLOR(show(at_the_mirror) << " hits a mirror (ksr 1, kdr 0.2) at depth 0: no reflected ray is traced, so "
                                       "the reflection adds nothing to what the floor with ksr 0 gives",
                bounce_part(t, plain, at_the_mirror, 0), BLACK, 1e-12);
}

TEST_CASE("reflection: one bounce off a plane mirror sees what lies in the mirror direction", "[04][reflection]") {
    // The ray from (-2, 2, 0) hits the floor at the origin with d = (1, -1, 0)/sqrt(2),
    // N = (0, 1, 0): R = d - 2 (d.N) N = (1, 1, 0)/sqrt(2), straight at the green emitter
    // E = (0.2, 0.9, 0.4) at (2, 2, 0). With ksr 0.8 and a white mirror the reflection adds
    //   c * ksr * trace(R) = 0.8 * E = (0.16, 0.72, 0.32)
    // (Red would mean the ray went on through the floor to the emitter at (2, -2, 0).)
    const surface mirror{.ksr = 0.8};
    const test_scene t = mirror_floor(mirror), plain = mirror_floor(dull(mirror));
    const color e = emitter_colour(t, green_at);
    REQUIRE_EMITTER_SEEN("the green emitter at (2, 2, 0)", e);
    for (const int depth : {1, 4}) {
        CHECK_COLOR(show(at_the_mirror) << " at depth " << depth
                                        << " is reflected at the origin towards (1, 1, 0)/sqrt(2) and sees the green "
                                           "emitter at (2, 2, 0): the reflection adds ksr 0.8 times its colour "
                                        << show(e),
                    bounce_part(t, plain, at_the_mirror, depth), 0.8 * e, 1e-9);
    }
}

TEST_CASE("reflection: a coloured mirror filters what it reflects", "[04][reflection]") {
    // The mirror's colour c multiplies what comes back (step 5: c * w_r * trace(R)). An
    // orange mirror (1, 0.5, 0), ksr 1, kdr 0, sees a white emitter E = (1, 1, 1):
    //   (1, 0.5, 0) * 1 * E = (1, 0.5, 0)
    const surface mirror{.clr = color(1, 0.5, 0), .ksr = 1};
    const test_scene t = mirror_floor(mirror, color(1, 1, 1)), plain = mirror_floor(dull(mirror), color(1, 1, 1));
    const color e = emitter_colour(t, green_at);
    REQUIRE_EMITTER_SEEN("the white emitter at (2, 2, 0)", e);
    CHECK_COLOR(show(at_the_mirror) << " is reflected by an orange mirror (colour (1, 0.5, 0), ksr 1) towards a white "
                                       "emitter "
                                    << show(e) << ": the mirror's colour filters the reflection",
                bounce_part(t, plain, at_the_mirror, 1), color(1, 0.5, 0) * e, 1e-9);
}

TEST_CASE("reflection: a mirror's own local light and its reflection add up", "[04][reflection]") {
    // A white mirror with kdr 0.3 and ksr 0.5 under ambient 1, reflecting the emitter
    // E = (0.2, 0.9, 0.4): its local light (what the same floor with ksr 0 gives, ambient
    // * c * kdr = 0.3) plus c * ksr * E = (0.1, 0.45, 0.2), together (0.4, 0.75, 0.5).
    const surface mirror{.kdr = 0.3, .ksr = 0.5};
    const test_scene t = mirror_floor(mirror), plain = mirror_floor(dull(mirror));
    const color e = emitter_colour(t, green_at), local = plain.trace(at_the_mirror, 1);
    REQUIRE_EMITTER_SEEN("the green emitter at (2, 2, 0)", e);
    CHECK_COLOR(show(at_the_mirror) << " hits a mirror with kdr 0.3 and ksr 0.5: its local light " << show(local)
                                    << " (the same floor with ksr 0) plus 0.5 times the emitter it reflects "
                                    << show(e),
                t.trace(at_the_mirror, 1), local + 0.5 * e, 1e-9);
}

TEST_CASE("reflection: the mirror direction on a sphere uses its normal at the hit", "[04][reflection]") {
    // A mirror sphere of radius 1 at the origin. The ray along +x at height sin 45 hits
    // it at P = (-cos 45, sin 45, 0), where N = P: d.N = -cos 45, so
    //   R = d - 2 (d.N) N = (1, 0, 0) + sqrt(2) (-1/sqrt(2), 1/sqrt(2), 0) = (0, 1, 0)
    // straight up, to the green emitter 3 above P: the reflection adds 1 * its colour. The
    // red emitter at (3, 0.7, 0) is where the ray would go without reflection, the blue one
    // at (-4, 0.7, 0) where R = -d would go.
    const double s45 = std::sqrt(0.5);
    const point up(-s45, s45 + 3, 0);
    auto build = [&](const surface& looks) {
        test_scene t;
        t.s.ambient = color(1, 1, 1);
        t.add(std::make_unique<test_sphere>(point(0, 0, 0), 1, looks));
        t.add(std::make_unique<test_sphere>(up, 0.5, emitter(color(0, 1, 0))));
        t.add(std::make_unique<test_sphere>(point(3, s45, 0), 0.5, emitter(color(1, 0, 0))));
        t.add(std::make_unique<test_sphere>(point(-4, s45, 0), 0.5, emitter(color(0, 0, 1))));
        return t;
    };
    const surface mirror{.ksr = 1};
    const test_scene t = build(mirror), plain = build(dull(mirror));
    const color e = emitter_colour(t, up);
    REQUIRE_EMITTER_SEEN("the green emitter above the sphere", e);
    const ray r(point(-2.5, s45, 0), vector(1, 0, 0));
    CHECK_COLOR(show(r) << " hits the mirror sphere at (-0.7071, 0.7071, 0), 45 degrees from its normal, and must be "
                           "reflected straight up (R = d - 2 (d.N) N = (0, 1, 0)) to the green emitter "
                        << show(e),
                bounce_part(t, plain, r, 1), e, 1e-9);
}

TEST_CASE("reflection: two facing mirrors stop at the depth limit", "[04][reflection]") {
    // Mirrors x = -1 (facing +x) and x = 1 (facing -x), each white with kdr 0.25 and ksr
    // 0.5, under ambient 1. A ray along +x bounces between them; each hit adds its local
    // light A (what one of these mirrors gives with ksr 0: ambient * c * kdr = 0.25) and
    // half of what comes back from the next one. Depth k allows k bounces, so k + 1 hits:
    //   trace(depth k) = A (1 + 0.5 + 0.5^2 + ... + 0.5^k) = A (2 - 0.5^k)
    //   with A = 0.25: depth 0: 0.25   1: 0.375   2: 0.4375   3: 0.46875   10: 0.499755859375
    auto build = [](const surface& looks) {
        test_scene t;
        t.s.ambient = color(1, 1, 1);
        t.add(std::make_unique<test_plane>(point(-1, 0, 0), vector(1, 0, 0), looks));
        t.add(std::make_unique<test_plane>(point(1, 0, 0), vector(-1, 0, 0), looks));
        return t;
    };
    const surface half_mirror{.kdr = 0.25, .ksr = 0.5};
    const test_scene t = build(half_mirror), plain = build(dull(half_mirror));
    const ray r(point(0, 0, 0), vector(1, 0, 0));
    const color a = plain.trace(r, 0);
    REQUIRE_EMITTER_SEEN("one of the mirrors with ksr 0 (its local light A)", a);
    for (const int depth : {0, 1, 2, 3, 10}) {
        const double sum = 2 - std::pow(0.5, depth);
        CHECK_COLOR(show(r) << " between two facing mirrors (kdr 0.25, ksr 0.5) at depth " << depth << ": " << depth
                            << " bounces, " << depth + 1 << " hits, A (2 - 0.5^" << depth << ") with your A = "
                            << show(a),
                    t.trace(r, depth), sum * a, 1e-9);
    }
}

TEST_CASE("reflection: head on - glass with ksr 0.3 and kst 0.5 reflects ksr + kst F = 0.32", "[04][reflection]") {
    // Glass below y = 0 (ksr 0.3, kst 0.5, ior 1.5, white), hit straight down. Head on F =
    // R0 = ((1 - 1.5) / (1 + 1.5))^2 = 0.04 (Schlick and the exact equations agree), and
    // the mirror ray gets w_r = ksr + kst F = 0.3 + 0.5 * 0.04 = 0.32. It goes straight up
    // and misses everything: it sees the red background B. The transmitted ray goes down
    // onto a black absorber floor at y = -1 inside the glass. So the bounces add 0.32 * B.
    auto build = [](const surface& looks) {
        test_scene t;
        t.s.ambient = color(1, 1, 1);
        t.s.background = color(1, 0, 0);
        t.add(glass_below(looks));
        t.add(floor_plane(absorber(), -1));
        return t;
    };
    const surface glass{.ksr = 0.3, .kst = 0.5, .ior = 1.5};
    const test_scene t = build(glass), plain = build(dull(glass));
    const color sky = t.trace(ray(point(0, 1, 0), vector(0, 1, 0)), 0);
    REQUIRE_EMITTER_SEEN("the red background (a ray up into the empty sky)", sky);
    const ray r(point(0, 5, 0), vector(0, -1, 0));
    CHECK_COLOR(show(r) << " hits glass with ksr 0.3, kst 0.5, ior 1.5 head on: the mirror ray straight back up "
                           "carries w_r = ksr + kst F = 0.32 of the background "
                        << show(sky),
                bounce_part(t, plain, r, 3), 0.32 * sky, 1e-9);
}
