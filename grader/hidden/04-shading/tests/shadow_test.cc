// Hidden tests of shadows (stage_04.hh step 4): a light is seen when the shadow ray from
// the point towards it hits nothing before it reaches the light. Each TEST_CASE is one
// graded item in the rubric's "shadows" category. Every trace is at depth 0, so only the
// local light is seen. A point of the floor must show what your own tracer shows at the
// same point of a bare floor lit by only the lights that reach it: a shadowed point loses
// exactly the light that is blocked, and an object beyond the light takes nothing. So a
// mistake in the local light itself costs points in the local light's tests, not here.
#include "vl/catch.hh"

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "hidden_support.hh"

using vl::color;
using vl::color_point;
using vl::point;
using vl::ray;
using vl::surface;
using vl::vector;
using namespace vl::stage04::hidden;

namespace {

const surface floor_surface = make_surface(color(0.8, 0.6, 0.4), 0.9);
const color floor_ambient(0.2, 0.3, 0.1);

/// A floor y = 0 (normal up) of surface `s` under `lights`, with the floor's ambient.
world open_floor(const std::vector<vl::color_point>& lights, const surface& s = floor_surface) {
    world w;
    w.plane(point(0, 0, 0), vector(0, 1, 0), s);
    w.s.ambient = floor_ambient;
    w.s.lights = lights;
    return w;
}
world floor_world() { return open_floor({}); }

std::string light_words(const color_point& l) { return "the light " + show(l.clr()) + " at " + show(l.pnt()); }

/// Traces `r` (which hits the floor of `w`) at depth 0. The answer key is your own tracer
/// on the bare floor under only the lights in `seen`, with nothing else in the scene, so
/// that only the shadows are graded here (the local light itself is graded elsewhere).
void check_floor(tally& t, const world& w, const ray& r, const std::vector<bool>& seen, const std::string& why,
                 const surface& s = floor_surface) {
    std::vector<color_point> reaching;
    std::string lit;
    for (std::size_t k = 0; k < seen.size(); ++k) {
        if (seen[k]) reaching.push_back(w.s.lights[k]);
        lit += std::string(k ? "; " : "") + light_words(w.s.lights[k]) + (seen[k] ? " reaches it" : " is blocked");
    }
    const world bare = open_floor(reaching, s), dark = open_floor({}, s);
    const traced got = trace_in(w.s, r, 0), want = trace_in(bare.s, r, 0), unlit = trace_in(dark.s, r, 0);
    const rvec d = unit(to_r(r.direction())), o = to_r(r.origin());
    const rvec p = o + (-o.y / d.y) * d;
    const std::string asked = show(r) + " at depth 0 hits the floor y = 0 (" + words(s) + ", ambient " +
                              show(floor_ambient) + ") at " + show(p) + ": " + lit + " (" + why + ")";
    const bool sensible = reaching.empty() || (want.ok() && unlit.ok() && !same(want.c, unlit.c, 1e-6));
    t.check(sensible, [&] {
        return "the lights that reach this point should add to its colour, but your tracer gives " + want.words() +
               " with them and " + unlit.words() + " without them, even with nothing in the way (see the local "
               "light's tests). Asked: " + asked;
    });
    t.check(got.ok() && want.ok() && same(got.c, want.c, 1e-12), [&] {
        return "trace() should return what your tracer gives on the bare floor under only the lights that reach the "
               "point, " + want.words() + " ± 1e-12; yours returned " + got.words() + ". Asked: " + asked;
    });
}

}  // namespace

TEST_CASE("shadow: a point behind a blocker gets the ambient light only", "[04][shadow][essential]") {
    tally t("points in a sphere's shadow");
    world w = floor_world();
    w.light(color(1, 1, 1), point(0, 6, 0));
    w.ball(point(0, 3, 0), 1, make_surface(color(0, 0, 1), 1));
    // Points under the sphere, seen by an eye low at the side (its rays pass below the sphere).
    for (const double x : {0.0, 0.5, -0.8, 1.2})
        for (const double z : {0.0, 0.6, -1.1}) {
            const point p(x, 0, z);
            check_floor(t, w, ray_through(point(x + 6, 1, z + 1), p), {false}, "the sphere around (0, 3, 0) of radius 1 lies between");
        }
    // And a highlight is shadowed as well.
    const surface shiny = make_surface(color(0.8, 0.6, 0.4), 0, 0.9, 0, 3);
    world w2 = open_floor({color_point(color(1, 1, 1), point(2, 2, 0))}, shiny);
    // (The blocker is black: the floor's mirror direction meets it too, and a black object
    // shows nothing there even to a tracer that would reflect at depth 0.)
    w2.ball(point(1, 1, 0), 0.3, make_surface(color(0, 0, 0), 1));
    check_floor(t, w2, ray_through(point(-2, 2, 0), point(0, 0, 0)), {false},
                "the sphere around (1, 1, 0) of radius 0.3 hides the light that would give a full highlight", shiny);
    t.report();
}

TEST_CASE("shadow: objects beyond the light - on the line to it or beside it - cast no shadow", "[04][shadow][essential]") {
    tally t("blockers beyond the light");
    world w = floor_world();
    w.light(color(1, 0.9, 0.8), point(0, 2, 0));
    w.ball(point(0, 4, 0), 1, make_surface(color(0, 0, 1), 1));                          // on the line, beyond the light
    w.plane(point(0, 8, 0), vector(0, -1, 0), make_surface(color(1, 0, 0), 1));          // a ceiling far above
    w.ball(point(0.5, 2.5, 0.2), 0.2, make_surface(color(0, 1, 0), 1));                  // just beyond the light
    for (const double x : {0.0, 0.3, -0.4, 1.0})
        for (const double z : {0.0, -0.3, 0.5}) {
            const point p(x, 0, z);
            check_floor(t, w, ray_through(point(x + 5, 1, z), p), {true},
                        "the spheres around (0, 4, 0), (0.5, 2.5, 0.2) and the ceiling y = 8 are all beyond the light");
        }
    t.report();
}

TEST_CASE("shadow: a shadow ray for which the root answers composite_only is not blocked", "[04][shadow][essential]") {
    tally t("composite_only on the way to the light");
    world w = floor_world();
    w.s.root = std::make_unique<probe_root>();
    w.plane(point(0, 0, 0), vector(0, 1, 0), floor_surface);
    w.light(color(1, 1, 1), point(1, 5, 2));
    for (const point p : {point(0, 0, 0), point(1, 0, 1), point(-2, 0, 0.5)})
        check_floor(t, w, ray_through(point(4, 3, 4), p), {true},
                    "the scene's root answers composite_only (t = 0) for the shadow ray: that is not a hit");
    t.report();
}

TEST_CASE("shadow: with several lights each is shadowed on its own", "[04][shadow][essential]") {
    tally t("two lights, one blocked");
    world w = floor_world();
    w.light(color(1, 0.5, 0.25), point(-4, 4, 0));
    w.light(color(0.25, 0.5, 1), point(4, 4, 0));
    w.ball(point(-2, 2, 0), 0.5, make_surface(color(1, 1, 1), 1));  // blocks the first light from (0, 0, 0)
    w.ball(point(3, 2, 1), 0.5, make_surface(color(1, 1, 1), 1));   // blocks the second light from (2, 0, 2)
    check_floor(t, w, ray_through(point(0, 1, 5), point(0, 0, 0)), {false, true}, "the sphere around (-2, 2, 0) blocks the first light");
    check_floor(t, w, ray_through(point(2, 1, 6), point(2, 0, 2)), {true, false}, "the sphere around (3, 2, 1) blocks the second light");
    check_floor(t, w, ray_through(point(0, 1, -6), point(0, 0, -3)), {true, true}, "nothing blocks either light");
    t.report();
}

TEST_CASE("shadow: transparent and mirror objects block the light too", "[04][shadow]") {
    tally t("transparent blockers");
    for (const surface& s : {make_surface(color(1, 1, 1), 0, 0, 1, 1, 1), make_surface(color(1, 1, 1), 0, 0, 0.9, 1, 1.5),
                             make_surface(color(1, 1, 1), 0, 1, 0, 1, 1)}) {
        world w = floor_world();
        w.light(color(1, 1, 1), point(0, 5, 0));
        w.ball(point(0, 2.5, 0), 0.8, s);
        check_floor(t, w, ray_through(point(5, 0.5, 0), point(0.2, 0, 0.1)), {false},
                    "the sphere around (0, 2.5, 0) with " + words(s) + " lies between: every object blocks");
    }
    t.report();
}

TEST_CASE("shadow: a blocker just before the light blocks it and one just beyond does not", "[04][shadow]") {
    tally t("blockers near the light");
    const point light(0, 3, 0);
    for (const double gap : {0.01, 0.1}) {
        world before = floor_world();
        before.light(color(1, 1, 1), light);
        before.ball(point(0, 3 - gap - 0.2, 0), 0.2, make_surface(color(1, 1, 1), 1));  // its top gap below the light
        check_floor(t, before, ray_through(point(3, 1, 0), point(0, 0, 0)), {false},
                    "a sphere of radius 0.2 whose top is " + num(gap) + " below the light is in the way");
        world beyond = floor_world();
        beyond.light(color(1, 1, 1), light);
        beyond.ball(point(0, 3 + gap + 0.2, 0), 0.2, make_surface(color(1, 1, 1), 1));  // its bottom gap above it
        check_floor(t, beyond, ray_through(point(3, 1, 0), point(0, 0, 0)), {true},
                    "a sphere of radius 0.2 whose bottom is " + num(gap) + " above the light is beyond it");
    }
    t.report();
}

TEST_CASE("shadow: the shadow ray reaches as far as the light - however far it is", "[04][shadow][detail]") {
    tally t("far lights and far blockers");
    for (const double h : {100.0, 1e4}) {
        world w = floor_world();
        w.light(color(1, 1, 1), point(0, h, 0));
        w.ball(point(0, h / 2, 0), h / 20, make_surface(color(1, 1, 1), 1));
        check_floor(t, w, ray_through(point(3, 1, 0), point(0, 0, 0)), {false},
                    "the light is at height " + num(h) + ", a sphere of radius " + num(h / 20) + " halfway up blocks it");
    }
    t.report();
}

TEST_CASE("shadow: a small blocker close above the surface still casts its shadow", "[04][shadow][detail]") {
    tally t("blockers close to the surface");
    for (const double h : {0.05, 0.005}) {
        world w = floor_world();
        w.light(color(1, 1, 1), point(0, 4, 0));
        w.ball(point(0, 2 * h, 0), h, make_surface(color(1, 1, 1), 1));
        check_floor(t, w, ray_through(point(3, 1, 0.5), point(0, 0, 0)), {false},
                    "a sphere of radius " + num(h) + " lies " + num(h) + " above the point, under the light");
    }
    t.report();
}
