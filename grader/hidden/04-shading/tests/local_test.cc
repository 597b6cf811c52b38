// Hidden tests of the local light (stage_04.hh step 3): ambient, diffuse (Lambert),
// highlight (Blinn-Phong), the surface colour as a filter, lights behind the surface, no
// clamping, and the background where nothing is hit. Each TEST_CASE is one graded item
// in the rubric's "local" category. Every trace is at depth 0 (no reflection or
// refraction) and no object stands between a point and a light, so only the local light
// is seen; every expected colour is computed below in long double.
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

/// The local light of the contract at a point `p` with the unit normal `n` (already
/// facing the viewer's side), seen along unit `d`, from lights none of which is shadowed.
rgb local_light(const rvec& p, const rvec& n, const rvec& d, const surface& s, const color& ambient,
                const std::vector<color_point>& lights) {
    const rgb c = of(s.clr);
    rgb sum = static_cast<real>(s.kdr) * (of(ambient) * c);
    for (const color_point& light : lights) {
        const rvec l = unit(to_r(light.pnt()) - p);
        const real nl = dot(n, l);
        if (!(nl > 0)) continue;
        const real nh = std::max(static_cast<real>(0), dot(n, unit(l - d)));
        const real weight = s.kdr * nl + s.ksr * std::pow(nh, static_cast<real>(s.n));
        sum = sum + weight * (c * of(light.clr()));
    }
    return sum;
}

std::string lights_words(const std::vector<color_point>& lights) {
    if (lights.empty()) return "no light";
    std::string s;
    for (std::size_t k = 0; k < lights.size(); ++k)
        s += (k ? ", " : "") + std::string("a light of colour ") + show(lights[k].clr()) + " at " + show(lights[k].pnt());
    return s;
}

/// Traces `r` at depth 0 into a scene of one plane and checks the local light there.
void check_plane(tally& t, const ray& r, const point& at, const vector& normal, const surface& s, const color& ambient,
                 const std::vector<color_point>& lights, real tol, const std::string& about = "") {
    world w;
    const probe_plane* plane = w.plane(at, normal, s);
    w.s.ambient = ambient;
    w.s.lights = lights;
    const real hit = plane->exact_t(r);
    REQUIRE(hit > 0);
    const rvec p = hit_point(r, hit), d = unit(to_r(r.direction()));
    rvec n = plane->unit_normal();  // a sheet has no inside: its normal is never flipped
    const rgb want = local_light(p, n, d, s, ambient, lights);
    check_color(t,
                show(r) + " at depth 0 hits " + plane->describe() + " at " + show(p) + " (surface " + words(s) +
                    ") under " + lights_words(lights) + " and ambient " + show(ambient) + about,
                trace_in(w.s, r, 0), want, tol);
}

/// The same for one sphere, seen from outside.
void check_ball(tally& t, const ray& r, const point& c, double radius, const surface& s, const color& ambient,
                const std::vector<color_point>& lights, real tol) {
    world w;
    const probe_ball* ball = w.ball(c, radius, s);
    w.s.ambient = ambient;
    w.s.lights = lights;
    const real hit = ball->exact_t(r);
    if (!(hit > 0)) return;
    const rvec p = hit_point(r, hit), d = unit(to_r(r.direction()));
    const rvec n = unit(p - ball->centre());
    const rgb want = local_light(p, n, d, s, ambient, lights);
    check_color(t,
                show(r) + " at depth 0 hits " + ball->describe() + " at " + show(p) + " (surface " + words(s) +
                    ") under " + lights_words(lights) + " and ambient " + show(ambient),
                trace_in(w.s, r, 0), want, tol);
}

}  // namespace

TEST_CASE("local: a lone light straight above a plane gives kdr times the surface colour times the light colour",
          "[04][local][essential]") {
    tally t("points of a plane, each under a light straight above it");
    const surface s = make_surface(color(0.9, 0.6, 0.3), 0.75);
    for (const double x : {0.0, 1.5, -2.25})
        for (const double z : {0.0, -1.0, 3.5})
            for (const double h : {1.0, 4.0, 37.0}) {
                const point p(x, 0, z);
                const std::vector<color_point> lights{color_point(color(0.8, 1.0, 0.5), point(x, h, z))};
                check_plane(t, ray_through(point(x + 2, 3, z + 4), p), point(0, 0, 0), vector(0, 1, 0), s, vl::BLACK, lights,
                            1e-12L);
                // The analytic value itself, N.L = 1: kdr * c * Lc.
                world w;
                w.plane(point(0, 0, 0), vector(0, 1, 0), s);
                w.s.lights = lights;
                const ray r = ray_through(point(x - 1, 2, z + 1), p);
                const rgb want{0.75L * 0.9L * 0.8L, 0.75L * 0.6L * 1.0L, 0.75L * 0.3L * 0.5L};
                check_color(t,
                            show(r) + " hits the plane y = 0 (normal (0, 1, 0), " + words(s) + ") at " + show(p) +
                                " straight below a light of colour (0.8, 1, 0.5) at height " + num(h) +
                                ", no ambient: N.L = 1, so the colour is kdr * c * Lc",
                            trace_in(w.s, r, 0), want, 1e-12L);
            }
    t.report();
}

TEST_CASE("local: diffuse light on a sphere follows Lambert's cosine law: kdr c Lc times N.L where N.L > 0",
          "[04][local][essential]") {
    tally t("rays at a lit diffuse sphere");
    dice random(4001);
    const surface s = make_surface(color(0.7, 0.4, 0.95), 0.6);
    for (int k = 0; k < 120; ++k) {
        const point c(random.uniform(-2, 2), random.uniform(-2, 2), random.uniform(-2, 2));
        const double radius = random.uniform(0.3, 2);
        const point light = c + random.uniform(3, 20) * random.direction();
        const point target = c + 0.9 * radius * random.direction();
        const point eye = c + random.uniform(4, 15) * random.direction();
        check_ball(t, ray_through(eye, target), c, radius, s, vl::BLACK, {color_point(color(1, 0.75, 0.5), light)}, 1e-9L);
    }
    t.report();
}

TEST_CASE("local: with no light a surface shows ambient times its colour times kdr", "[04][local][essential]") {
    tally t("surfaces under ambient light only");
    const color ambients[] = {color(0.1, 0.1, 0.1), color(0.3, 0.6, 0.9), color(1, 1, 1)};
    const surface surfaces[] = {make_surface(color(1, 1, 1), 1), make_surface(color(0.5, 0.25, 0.75), 0.8, 0.5, 0, 30),
                                make_surface(color(0.2, 0.9, 0.4), 0.35)};
    for (const color& a : ambients)
        for (const surface& s : surfaces) {
            check_plane(t, ray_through(point(1, 2, 3), point(0.25, 0, -0.5)), point(0, 0, 0), vector(0, 1, 0), s, a, {},
                        1e-12L);
            check_ball(t, ray_through(point(0, 0, 6), point(0.3, 0.2, 0)), point(0, 0, 0), 1, s, a, {}, 1e-12L);
        }
    t.report();
}

TEST_CASE("local: the light's colour is filtered by the surface colour channel by channel - in the diffuse light and in the highlight",
          "[04][local][essential]") {
    tally t("coloured lights on coloured surfaces");
    const color lights[] = {color(1, 0, 0), color(0.2, 0.9, 0.4), color(0.5, 0.5, 1)};
    const color colours[] = {color(0, 1, 1), color(0.8, 0.3, 0.6), color(1, 1, 1)};
    for (const color& lc : lights)
        for (const color& c : colours) {
            // Diffuse alone, then a highlight alone (the light in the mirror direction of the eye).
            check_plane(t, ray_through(point(-2, 3, 0), point(0, 0, 0)), point(0, 0, 0), vector(0, 1, 0),
                        make_surface(c, 0.9), vl::BLACK, {color_point(lc, point(1, 2, 1))}, 1e-12L);
            check_plane(t, ray_through(point(-2, 3, 0), point(0, 0, 0)), point(0, 0, 0), vector(0, 1, 0),
                        make_surface(c, 0, 0.7, 0, 15), vl::BLACK, {color_point(lc, point(4, 6, 0))}, 1e-12L);
        }
    t.report();
}

TEST_CASE("local: the highlight is ksr times the cosine of the half angle to the power n (Blinn-Phong)",
          "[04][local][essential]") {
    tally t("highlights at chosen half angles");
    // The half vector H makes the angle alpha with the normal; L and the direction to the
    // eye lie 30 degrees either side of H, in the plane of the figure.
    const surface s = make_surface(color(1, 0.8, 0.6), 0, 0.8, 0, 20);
    for (const real alpha_deg : {0.0L, 3.0L, 7.5L, 15.0L, 25.0L, 40.0L}) {
        const real a = radians(alpha_deg), b = radians(30.0L);
        const rvec l{std::sin(a + b), std::cos(a + b), 0}, v{std::sin(a - b), std::cos(a - b), 0};
        const point p(0.5, 0, -0.25);
        const point light = to_point(to_r(p) + 5.0L * l), eye = to_point(to_r(p) + 3.0L * v);
        check_plane(t, ray_through(eye, p), point(0, 0, 0), vector(0, 1, 0), s, vl::BLACK,
                    {color_point(color(0.9, 0.9, 1), light)}, 1e-10L,
                    " (the half angle is " + num(static_cast<double>(alpha_deg)) + " degrees: the highlight is ksr cos(" +
                        num(static_cast<double>(alpha_deg)) + " degrees)^n c Lc)");
    }
    t.report();
}

TEST_CASE("local: the highlight narrows as n grows: n = 1 - 10 - 100 and 1000 at the same half angle",
          "[04][local]") {
    tally t("highlights with several exponents");
    for (const double n : {1.0, 10.0, 100.0, 1000.0})
        for (const real alpha_deg : {0.0L, 2.0L, 6.0L}) {
            const real a = radians(alpha_deg), b = radians(20.0L);
            const rvec l{0, std::cos(a + b), std::sin(a + b)}, v{0, std::cos(a - b), std::sin(a - b)};
            const point p(0, 0, 0);
            check_plane(t, ray_through(to_point(3.0L * v), p), p, vector(0, 1, 0), make_surface(color(1, 1, 1), 0, 0.6, 0, n),
                        vl::BLACK, {color_point(color(1, 1, 1), to_point(4.0L * l))}, 1e-10L);
        }
    t.report();
}

TEST_CASE("local: a light behind the surface adds neither diffuse light nor a highlight", "[04][local][essential]") {
    tally t("lights on the far side of a surface");
    // The eye looks at the plane y = 0 from above at a slant; each light is below the plane,
    // placed so that the half vector H still has N.H > 0 (a highlight would show if N.L
    // were not checked).
    const surface s = make_surface(color(0.9, 0.9, 0.9), 0.7, 0.6, 0, 5);
    const point p(0, 0, 0);
    for (const point light : {point(5, -0.5, 0), point(3, -0.2, 1), point(0, -3, 0), point(-4, -1, 2)})
        for (const point eye : {point(-1, 4, 0), point(-3, 0.8, 0.5)})
            check_plane(t, ray_through(eye, p), p, vector(0, 1, 0), s, color(0.1, 0.2, 0.3),
                        {color_point(color(1, 1, 1), light)}, 1e-12L, " (the light is below the plane: ambient only)");
    // A sphere lit from one side, seen from the other.
    check_ball(t, ray_through(point(0, 0, 5), point(0, 0, 0)), point(0, 0, 0), 1, s, color(0.2, 0.2, 0.2),
               {color_point(color(1, 1, 1), point(0, 0, -5))}, 1e-12L);
    t.report();
}

TEST_CASE("local: a flat object seen from the side its normal points away from is lit only by lights on that side",
          "[04][local]") {
    tally t("a sheet seen from behind");
    // The eye is below the sheet y = 0 whose normal is (0, 1, 0); the sheet has no inside,
    // so its normal is not flipped: a light above it lights it, one below does not. No
    // light lies on the line of a ray (there L = d, and the half vector is not defined).
    const surface s = make_surface(color(0.6, 0.8, 1), 0.8, 0.3, 0, 8);
    const point p(0.5, 0, 0.5);
    for (const point eye : {point(0, -3, 1), point(2, -1, -2)}) {
        check_plane(t, ray_through(eye, p), point(0, 0, 0), vector(0, 1, 0), s, color(0.1, 0.1, 0.1),
                    {color_point(color(1, 1, 1), point(1.5, 3, 0.2))}, 1e-12L, " (the light is on the normal's side: it lights the sheet)");
        check_plane(t, ray_through(eye, p), point(0, 0, 0), vector(0, 1, 0), s, color(0.1, 0.1, 0.1),
                    {color_point(color(1, 1, 1), point(1, -3, 0))}, 1e-12L, " (the light is on the eye's side, behind the normal: ambient only)");
    }
    t.report();
}

TEST_CASE("local: trace() does not clamp - so bright lights give values above 1", "[04][local]") {
    tally t("bright lights");
    const surface s = make_surface(color(1, 0.5, 1), 0.9, 0.8, 0, 4);
    check_plane(t, ray_through(point(-1, 2, 0), point(0, 0, 0)), point(0, 0, 0), vector(0, 1, 0), s, color(2, 2, 2),
                {color_point(color(5, 3, 4), point(1, 2, 0))}, 1e-11L);
    check_plane(t, ray_through(point(0, 3, 3), point(0, 0, 0)), point(0, 0, 0), vector(0, 1, 0), s, vl::BLACK,
                {color_point(color(2, 2, 2), point(0, 5, 0)), color_point(color(3, 1, 2), point(0, 3, -3))}, 1e-11L);
    t.report();
}

TEST_CASE("local: a ray that hits nothing sees the scene's background - at any depth", "[04][local][essential]") {
    tally t("rays that hit nothing");
    for (const int depth : {0, 1, 5}) {
        world w;
        w.s.background = color(0.25, 0.5, 0.125);
        w.s.ambient = color(1, 1, 1);
        w.light(color(1, 1, 1), point(0, 5, 0));
        const ray empty_ray(point(0, 0, 0), vector(0.2, -1, 0.3));
        check_color(t, show(empty_ray) + " in a scene with no objects at depth " + std::to_string(depth),
                    trace_in(w.s, empty_ray, depth), of(w.s.background), 0);
        w.ball(point(0, 0, -5), 1, make_surface(color(1, 0, 0), 1, 0.5, 0.3, 10, 1.5));
        w.plane(point(0, -2, 0), vector(0, 1, 0), make_surface(color(0, 1, 0), 1, 0.5));
        const ray away(point(0, 0, 0), vector(0.1, 0.3, 1));
        check_color(t, show(away) + " passes beside a sphere and away from a floor, at depth " + std::to_string(depth),
                    trace_in(w.s, away, depth), of(w.s.background), 0);
    }
    t.report();
}

TEST_CASE("local: a ray for which the scene's root answers composite_only sees the background", "[04][local]") {
    tally t("composite_only from the root");
    world w;
    w.s.root = std::make_unique<probe_root>();
    w.s.background = color(0.3, 0.1, 0.7);
    w.s.ambient = color(0.5, 0.5, 0.5);
    w.light(color(1, 1, 1), point(0, 5, 0));
    w.ball(point(0, 0, -5), 1, make_surface(color(1, 1, 0), 1));
    for (const vector d : {vector(0, 1, 0), vector(1, 0.2, 0), vector(0.3, 0.3, -1)}) {
        const ray r(point(0, 0, 0), d);
        check_color(t,
                    show(r) + " misses every object; the scene's root returns composite_only (rule 2: t = 0, the object "
                              "a composite), which is not a hit",
                    trace_in(w.s, r, 2), of(w.s.background), 0);
    }
    t.report();
}

TEST_CASE("local: lights do not fade with distance", "[04][local][detail]") {
    tally t("near and far lights");
    const surface s = make_surface(color(0.5, 0.7, 0.9), 0.8);
    for (const double h : {0.5, 10.0, 1000.0, 1e5})
        check_plane(t, ray_through(point(1, 1, 1), point(0, 0, 0)), point(0, 0, 0), vector(0, 1, 0), s, vl::BLACK,
                    {color_point(color(1, 1, 1), point(h * 0.6, h * 0.8, 0))}, 1e-12L,
                    " (the same direction to the light at any distance: the same colour)");
    t.report();
}

TEST_CASE("local: several lights add up - each with its own direction and colour", "[04][local]") {
    tally t("several lights");
    dice random(4013);
    for (int k = 0; k < 30; ++k) {
        std::vector<color_point> lights;
        for (int j = 0; j < 3; ++j)
            lights.emplace_back(color(random.uniform(0, 1), random.uniform(0, 1), random.uniform(0, 1)),
                                point(random.uniform(-6, 6), random.uniform(0.5, 8), random.uniform(-6, 6)));
        const point target(random.uniform(-1, 1), 0, random.uniform(-1, 1));
        check_plane(t, ray_through(point(random.uniform(-3, 3), 4, 5), target), point(0, 0, 0), vector(0, 1, 0),
                    make_surface(color(0.9, 0.5, 0.7), 0.6, 0.4, 0, 12), color(0.05, 0.1, 0.05), lights, 1e-10L);
    }
    t.report();
}

TEST_CASE("local: kdt - diffuse transmission - is not part of the model and changes nothing", "[04][local][detail]") {
    tally t("surfaces with kdt");
    for (const double kdt : {0.0, 0.5, 1.0}) {
        surface s = make_surface(color(0.8, 0.6, 0.4), 0.7, 0.2, 0, 10);
        s.kdt = kdt;
        check_plane(t, ray_through(point(0, 2, 2), point(0, 0, 0)), point(0, 0, 0), vector(0, 1, 0), s, color(0.1, 0.1, 0.1),
                    {color_point(color(1, 1, 1), point(1, 3, -1)), color_point(color(1, 1, 1), point(0, -3, 0))}, 1e-12L,
                    " (kdt " + num(kdt) + " is not read)");
    }
    t.report();
}
