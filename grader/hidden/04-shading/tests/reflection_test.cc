// Hidden tests of reflection (stage_04.hh step 5, kst = 0): the mirror direction, the
// weight ksr, the surface colour as a filter, and the depth limit. Each TEST_CASE is one
// graded item in the rubric's "reflection" category. There are no lights: the ambient
// light is (1, 1, 1), so an object of kdr 1 returns exactly its colour (an "emitter"),
// and a mirror returns its own light plus what it reflects; only what the reflection adds
// is graded (your trace() minus the same ray with the mirror's ksr and kst set to 0),
// against what your tracer shows for the emitter itself. A "watcher" object that is never
// hit writes down every ray the tracer asks the scene about, so the tests can read the
// reflected ray itself. Every expected value is computed below in long double.
#include "vl/catch.hh"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "hidden_support.hh"

using vl::color;
using vl::point;
using vl::ray;
using vl::surface;
using vl::vector;
using namespace vl::stage04::hidden;

namespace {

/// Checks that among the rays the watcher saw there is one from (about) `p` along `want`,
/// starting on the side of `n` (or on the surface).
void check_secondary(tally& t, const std::vector<ray>& log, const rvec& p, const rvec& n, const rvec& want,
                     const std::string& asked) {
    const real scale = std::max(static_cast<real>(1), len(p));
    const std::vector<ray> from = rays_from(log, p, 1e-6L * scale);
    bool found = false, side = true;
    for (const ray& r : from)
        if (len(unit(to_r(r.direction())) - want) <= 1e-9L) {
            found = true;
            side = dot(to_r(r.origin()) - p, n) >= -1e-12L * scale;
        }
    t.check(found && side, [&] {
        return "the reflected ray should go towards " + show(want) + " ± 1e-9 from " + show(p) + " (within " +
               num(static_cast<double>(1e-6L * scale)) + ", on the side the normal " + show(n) + " points to); " +
               (found ? "yours starts on the other side of the surface"
                      : "the rays your tracer cast from there: " + show_rays(from, log, p, 1e-6L * scale)) +
               ". Asked: " + asked;
    });
}

/// Checks what the reflection off `mirror` adds to trace(r, depth) in `w`: ksr * c * E,
/// with E what your tracer shows along `at` in `seen_in` at depth 0 (the emitter, or the
/// background, that the mirror direction reaches).
void check_reflected(tally& t, const world& w, vl::primitive& mirror, const ray& r, int depth, const world& seen_in,
                     const ray& at, const std::string& asked) {
    const traced seen = trace_in(seen_in.s, at, 0);
    const bool bright = seen.ok() && std::max({seen.c.r, seen.c.g, seen.c.b}) > 0.2;
    t.check(bright, [&] {
        return "what the mirror direction reaches should show its colour: yours returned " + seen.words() + " for " +
               show(at) + " aimed straight at it, at depth 0. Asked: " + asked;
    });
    if (!bright) return;
    const surface s = mirror.surf();
    const rgb want = static_cast<real>(s.ksr) * (of(s.clr) * of(seen.c));
    const bounced got = bounce_part(w.s, mirror, r, depth);
    t.check(got.ok() && same(got.part, want, 1e-12L), [&] {
        return "the reflection should add ksr * c * E = " + show(want) + " ± 1e-12, with E = " + show(seen.c) +
               " what your tracer shows in the mirror direction; it added " + got.words() + ". Asked: " + asked;
    });
}

/// The six walls of the cube from -5 to 5, each an emitter of its own colour.
const std::array<color, 6> wall_colours{color(1, 0, 0), color(0, 1, 0), color(0, 0, 1),
                                        color(1, 1, 0), color(0, 1, 1), color(1, 0, 1)};
const std::array<vector, 6> wall_normals{vector(1, 0, 0),  vector(-1, 0, 0), vector(0, 1, 0),
                                         vector(0, -1, 0), vector(0, 0, 1),  vector(0, 0, -1)};
void add_walls(world& w) {
    for (int k = 0; k < 6; ++k)
        w.plane(point(0, 0, 0) + (-5.0) * wall_normals[static_cast<std::size_t>(k)], wall_normals[static_cast<std::size_t>(k)],
                emitter(wall_colours[static_cast<std::size_t>(k)]));
}
/// Which wall a ray from `o` along unit `d` (inside the cube) reaches first.
int wall_hit(const rvec& o, const rvec& d) {
    int best = -1;
    real best_t = 0;
    for (int k = 0; k < 6; ++k) {
        const rvec n = to_r(wall_normals[static_cast<std::size_t>(k)]);
        const rvec at = -5.0L * n;
        const real dn = dot(d, n);
        if (dn == 0) continue;
        const real t = dot(at - o, n) / dn;
        if (t > 0 && (best < 0 || t < best_t)) {
            best = k;
            best_t = t;
        }
    }
    return best;
}
/// How far (in t) the wall hit is from the next wall's: near an edge of the cube the wall
/// is not graded.
real wall_margin(const rvec& o, const rvec& d) {
    std::vector<real> ts;
    for (int k = 0; k < 6; ++k) {
        const rvec n = to_r(wall_normals[static_cast<std::size_t>(k)]);
        const real dn = dot(d, n);
        if (dn == 0) continue;
        const real t = dot(-5.0L * n - o, n) / dn;
        if (t > 0) ts.push_back(t);
    }
    std::sort(ts.begin(), ts.end());
    return ts.size() < 2 ? 1 : ts[1] - ts[0];
}

/// Two facing mirrors y = 0 and y = 1, each of kdr 1 and ksr `ksr`, under ambient 0.5 (its
/// own light 0.5: every sum stays below 1).
world facing_mirrors(double ksr = 0.5) {
    world w;
    w.emitters_shine();
    w.s.ambient = color(0.5, 0.5, 0.5);
    const surface s = make_surface(color(1, 1, 1), 1, ksr);
    w.plane(point(0, 0, 0), vector(0, 1, 0), s);
    w.plane(point(0, 1, 0), vector(0, -1, 0), s);
    return w;
}

}  // namespace

TEST_CASE("reflection: the reflected ray leaves a mirror plane in the mirror direction d - 2 (d.N) N",
          "[04][reflection][essential]") {
    tally t("reflected rays of mirror planes");
    dice random(4101);
    for (int k = 0; k < 60; ++k) {
        world w;
        w.emitters_shine();
        const point at(random.uniform(-3, 3), random.uniform(-3, 3), random.uniform(-3, 3));
        const vector n = random.direction();
        const probe_plane* sheet = w.plane(at, n, make_surface(color(1, 1, 1), 0, 1));
        const probe_watcher* watch = w.watcher();
        const point eye = at + random.uniform(1, 6) * (n + 0.9 * random.direction()).unit();
        const point target = at + random.uniform(0, 2) * (random.direction() - (random.direction() * n) * n);
        const ray r = ray_through(eye, target);
        const real hit = sheet->exact_t(r);
        if (!(hit > 0) || dot(unit(to_r(r.direction())), sheet->unit_normal()) > -0.05L) continue;
        const traced got = trace_in(w.s, r, 1);
        const rvec p = hit_point(r, hit), d = unit(to_r(r.direction())), nn = sheet->unit_normal();
        if (!got.ok()) {
            t.check(false, [&] { return show(r) + " at depth 1: " + got.error; });
            continue;
        }
        check_secondary(t, watch->rays(), p, nn, mirror(d, nn),
                        show(r) + " at depth 1 hits a mirror, " + sheet->describe() + " at " + show(p));
    }
    t.report();
}

TEST_CASE("reflection: the reflected ray leaves a mirror sphere in the mirror direction about its normal there",
          "[04][reflection]") {
    tally t("reflected rays of a mirror sphere");
    dice random(4102);
    for (int k = 0; k < 60; ++k) {
        world w;
        w.emitters_shine();
        const point c(random.uniform(-2, 2), random.uniform(-2, 2), random.uniform(-2, 2));
        const double radius = random.uniform(0.5, 2);
        const probe_ball* ball = w.ball(c, radius, make_surface(color(1, 1, 1), 0, 0.8));
        const probe_watcher* watch = w.watcher();
        const ray r = ray_through(c + random.uniform(3, 9) * random.direction(), c + 0.95 * radius * random.direction());
        const real hit = ball->exact_t(r);
        if (!(hit > 0)) continue;
        const rvec p = hit_point(r, hit), d = unit(to_r(r.direction())), n = unit(p - ball->centre());
        if (dot(d, n) > -0.05L) continue;
        const traced got = trace_in(w.s, r, 1);
        if (!got.ok()) {
            t.check(false, [&] { return show(r) + " at depth 1: " + got.error; });
            continue;
        }
        check_secondary(t, watch->rays(), p, n, mirror(d, n),
                        show(r) + " at depth 1 hits a mirror, " + ball->describe() + " at " + show(p) +
                            " (outward normal " + show(n) + ")");
    }
    t.report();
}

TEST_CASE("reflection: a mirror of weight ksr and colour c shows ksr * c times the colour it reflects",
          "[04][reflection][essential]") {
    tally t("mirrors of several weights and colours");
    const color emitted(0.6, 0.9, 0.3);
    for (const double ksr : {1.0, 0.5, 0.25})
        for (const color& c : {color(1, 1, 1), color(0.9, 0.5, 0.1), color(0, 1, 0.5)}) {
            world w;
            w.emitters_shine();
            const surface s = make_surface(c, 0, ksr);
            vl::primitive* mirror = w.plane(point(0, 0, 0), vector(0, 1, 0), s);
            w.plane(point(0, 3, 0), vector(0, -1, 0), emitter(emitted));
            const ray r = ray_through(point(-1, 1, 0.5), point(0.5, 0, 0));
            check_reflected(t, w, *mirror, r, 1, w, ray(point(2, 1, 0), vector(0, 1, 0)),
                            show(r) + " at depth 1 hits the mirror y = 0 (" + words(s) +
                                ") and its reflection reaches the ceiling y = 3, an emitter of colour " + show(emitted) +
                                ": the reflection adds ksr * c * that colour (channel by channel)");
        }
    t.report();
}

TEST_CASE("reflection: at depth 0 a mirror shows no reflection - at depth 1 it does", "[04][reflection][essential]") {
    tally t("mirrors at depth 0 and 1");
    const color emitted(0.5, 0.75, 1);
    const surface s = make_surface(color(0.8, 0.8, 0.4), 0.25, 0.6);
    world w;
    w.emitters_shine();
    vl::primitive* mirror = w.plane(point(0, 0, 0), vector(0, 1, 0), s);
    w.plane(point(0, 3, 0), vector(0, -1, 0), emitter(emitted));
    const ray r = ray_through(point(0, 1, 1), point(0, 0, 0));
    // At depth 0 the mirror shows what it shows with ksr 0: its own light alone.
    const bounced none = bounce_part(w.s, *mirror, r, 0);
    t.check(none.ok() && same(none.part, rgb{}, 1e-12L), [&] {
        return "at depth 0 the reflection should add nothing, (0, 0, 0); it added " + none.words() + ". Asked: " +
               show(r) + " at depth 0 hits a mirror floor (" + words(s) + ") under a ceiling showing " + show(emitted);
    });
    check_reflected(t, w, *mirror, r, 1, w, ray(point(2, 1, 0), vector(0, 1, 0)),
                    show(r) + " at depth 1 hits the same mirror floor, which reflects a ceiling showing " + show(emitted));
    t.report();
}

TEST_CASE("reflection: between two facing mirrors depth k gives exactly k bounces", "[04][reflection][essential]") {
    tally t("rays between two facing mirrors");
    // Each mirror shows its own light 0.5 (kdr 1 under ambient 0.5) plus half of what it
    // reflects, so depth k gives 0.5 (1 + 1/2 + ... + 1/2^k) = 1 - 1/2^(k + 1).
    // (In words with your tracer's own light of a mirror, E: E (2 - 1/2^k).)
    world w = facing_mirrors();
    const world dull = facing_mirrors(0);
    traced own;
    if (emitter_shows(t, dull.s, ray(point(0, 0.5, 0), vector(0.3, 1, 0.1)), &color::r,
                      "a mirror's own light, with ksr 0", own))
    for (int k = 0; k <= 12; ++k) {
        const ray r(point(0, 0.5, 0), vector(0.3, 1, 0.1));
        const real want = own.c.r * (2 - std::pow(0.5L, static_cast<real>(k)));
        check_color(t,
                    show(r) + " starts between the mirrors y = 0 and y = 1 (each color (1, 1, 1), kdr 1, ksr 0.5, under "
                              "ambient (0.5, 0.5, 0.5)), at depth " + std::to_string(k) + ": " + std::to_string(k) +
                        " reflections give E (1 + 1/2 + ... + 1/2^" + std::to_string(k) + "), with E = " +
                        own.words() + " your tracer's light of a mirror with ksr 0",
                    trace_in(w.s, r, k), rgb{want, want, want}, 1e-12L);
    }
    t.report();
}

TEST_CASE("reflection: the recursion ends: depth 1000 between two facing mirrors returns", "[04][reflection][detail]") {
    tally t("a deep recursion");
    world w = facing_mirrors();
    const world dull = facing_mirrors(0);
    const ray r(point(0, 0.5, 0), vector(0.2, -1, 0.05));
    traced own;
    if (emitter_shows(t, dull.s, r, &color::r, "a mirror's own light, with ksr 0", own))
        check_color(t,
                    show(r) + " between two facing mirrors (kdr 1, ksr 0.5) at depth 1000 (1000 reflections, each traced "
                              "with depth - 1): twice your tracer's light of a mirror with ksr 0, " + own.words(),
                    trace_in(w.s, r, 1000), 2 * of(own.c), 1e-12L);
    t.report();
}

TEST_CASE("reflection: a reflected ray that hits nothing brings back the background", "[04][reflection]") {
    tally t("mirrors that reflect the sky");
    world w;
    w.emitters_shine();
    w.s.background = color(0.2, 0.4, 0.8);
    const surface s = make_surface(color(1, 0.5, 0.75), 0, 0.9);
    vl::primitive* mirror = w.plane(point(0, 0, 0), vector(0, 1, 0), s);
    for (const point eye : {point(0, 1, 3), point(2, 5, 0)}) {
        const ray r = ray_through(eye, point(0, 0, 0));
        check_reflected(t, w, *mirror, r, 3, w, ray(point(0, 1, 0), vector(0.1, 1, 0.2)),
                        show(r) + " at depth 3 hits a mirror floor (" + words(s) +
                            "); its reflection hits nothing: the reflection adds ksr * c * background");
    }
    t.report();
}

TEST_CASE("reflection: a curved mirror in a room of coloured walls shows the wall in the mirror direction",
          "[04][reflection]") {
    tally t("rays at a mirror sphere in a coloured room");
    dice random(4103);
    const surface s = make_surface(color(0.9, 0.8, 0.7), 0, 0.75);
    for (int k = 0; k < 150; ++k) {
        world w;
        w.emitters_shine();
        add_walls(w);
        const point c(random.uniform(-1, 1), random.uniform(-1, 1), random.uniform(-1, 1));
        probe_ball* ball = w.ball(c, 1.5, s);
        const ray r = ray_through(c + random.uniform(2, 3.2) * random.direction(), c + 1.4 * random.direction());
        const real hit = ball->exact_t(r);
        if (!(hit > 0)) continue;
        const rvec p = hit_point(r, hit), d = unit(to_r(r.direction())), n = unit(p - ball->centre()), m = mirror(d, n);
        if (wall_margin(p, m) < 1e-3L) continue;  // too near an edge of the room
        const int wall = wall_hit(p, m);
        world room;
        room.emitters_shine();
        add_walls(room);
        check_reflected(t, w, *ball, r, 1, room, ray(to_point(p), to_vector(m)),
                        show(r) + " at depth 1 hits a mirror, " + ball->describe() + " (" + words(s) + ") at " + show(p) +
                            "; the mirror direction " + show(m) + " reaches the wall of colour " +
                            show(wall_colours[static_cast<std::size_t>(wall)]) + " of the room from -5 to 5");
    }
    t.report();
}

TEST_CASE("reflection: a surface with both kdr and ksr adds its reflection to its own light", "[04][reflection][detail]") {
    tally t("half-mirrors");
    const color emitted(1, 0.5, 0.25);
    const surface s = make_surface(color(0.5, 1, 0.8), 0.3, 0.6);
    world w;
    w.emitters_shine();
    vl::primitive* mirror = w.plane(point(0, 0, 0), vector(0, 1, 0), s);
    w.plane(point(0, 2, 0), vector(0, -1, 0), emitter(emitted));
    const ray r = ray_through(point(1, 1, 1), point(0, 0, 0));
    check_reflected(t, w, *mirror, r, 2, w, ray(point(0, 1, 0), vector(0, 1, 0)),
                    show(r) + " at depth 2 hits a floor (" + words(s) + ") under a ceiling showing " + show(emitted) +
                        ": its own light plus the reflection, ksr * c * " + show(emitted));
    t.report();
}

TEST_CASE("reflection: the reflected ray starts at the hit point on the side the normal points to", "[04][reflection][detail]") {
    tally t("where reflected rays start");
    dice random(4104);
    for (int k = 0; k < 40; ++k) {
        world w;
        w.emitters_shine();
        const point c(random.uniform(-50, 50), random.uniform(-50, 50), random.uniform(-50, 50));
        const probe_ball* ball = w.ball(c, 2, make_surface(color(1, 1, 1), 0, 1));
        const probe_watcher* watch = w.watcher();
        const ray r = ray_through(c + 6 * random.direction(), c + 1.5 * random.direction());
        const real hit = ball->exact_t(r);
        if (!(hit > 0)) continue;
        const rvec p = hit_point(r, hit), d = unit(to_r(r.direction())), n = unit(p - ball->centre());
        if (dot(d, n) > -0.05L) continue;
        const traced got = trace_in(w.s, r, 1);
        t.check(got.ok(), [&] { return show(r) + " at depth 1: " + got.error; });
        check_secondary(t, watch->rays(), p, n, mirror(d, n), show(r) + " at depth 1 hits a mirror, " + ball->describe());
    }
    t.report();
}

TEST_CASE("reflection: at depth 0 glass shows neither reflection nor transmission", "[04][reflection][detail]") {
    tally t("glass at depth 0");
    for (const double kdr : {0.0, 0.2}) {
        const surface s = make_surface(color(0.5, 0.75, 1), kdr, 0.1, 0.9, 1, 1.5);
        bench b(s, false);
        b.red_green();
        const ray r = ray_through(point(0.5, 1, 0), point(0, 0, 0));
        const bounced none = b.bounces(r, 0);
        t.check(none.ok() && same(none.part, rgb{}, 1e-12L), [&] {
            return "at depth 0 the bounces should add nothing, (0, 0, 0); they added " + none.words() +
                   ". Asked: " + b.about(r, 0);
        });
        const bounced some = b.bounces(r, 1);
        t.check(some.ok() && some.part.r > 0.01 && some.part.g > 0.01, [&] {
            return "at depth 1 the same glass should reflect some red and transmit some green; the bounces added " +
                   some.words() + ". Asked: " + b.about(r, 1);
        });
    }
    t.report();
}

TEST_CASE("reflection: glass with ksr and kst reflects ksr + kst F - at normal incidence ksr + kst R0",
          "[04][reflection]") {
    tally t("the reflected weight of glass");
    for (const double ior : {1.5, 2.0})
        for (const std::pair<double, double>& weights :
             {std::pair{0.0, 1.0}, std::pair{0.3, 0.6}, std::pair{0.5, 0.5}, std::pair{0.1, 0.9}}) {
            const double ksr = weights.first, kst = weights.second;
            bench b(make_surface(color(1, 1, 1), 0, ksr, kst, 1, ior), false);
            b.mirror_side();
            const ray r = b.at_angle(0);
            const real r0 = ((ior - 1.0L) / (ior + 1.0L)) * ((ior - 1.0L) / (ior + 1.0L)), w_r = ksr + kst * r0;
            check_bounced(t, b, r, 3, b.at_near_side(), &color::r, band{w_r - 1e-9L, w_r + 1e-9L}, "the red emitter",
                          "w_r = ksr + kst F with F = R0 = " + num(static_cast<double>(r0)) + " at 0 degrees");
        }
    t.report();
}
