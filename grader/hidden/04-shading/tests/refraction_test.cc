// Hidden tests of refraction for rays that ENTER an object from outside (stage_04.hh
// step 5): Snell's law for the transmitted direction, the Fresnel reflectance F at 0 and
// 90 degrees, and the weights w_r = ksr + kst F and w_t = kst (1 - F). Each TEST_CASE is
// one graded item in the rubric's "refraction" category. There are no lights (ambient
// (1, 1, 1), emitters of kdr 1), and most tests use the bench of hidden_support.hh: glass
// below y = 0 between a red emitter on the reflected side and a green one on the
// transmitted side, so the colour returned is c * (w_r, w_t, 0). Where F is checked, any
// value between Schlick's approximation and the exact Fresnel equations, widened by 0.02,
// passes (the contract allows either). Every expected value is computed in long double.
#include <catch2/catch.hpp>

#include <cmath>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "hidden_support.hh"

using vl::color;
using vl::point;
using vl::ray;
using vl::surface;
using vl::vector;
using namespace vl::stage04::hidden;

namespace {

surface glass(double ior, double ksr = 0, double kst = 1, const color& c = color(1, 1, 1)) {
    return make_surface(c, 0, ksr, kst, 1, ior);
}

/// Checks that among the watcher's rays there is one from (about) `p` along `want`; when
/// `inside_of` is given, that ray must start inside it.
void check_transmitted(tally& t, const std::vector<ray>& log, const rvec& p, const rvec& want, const std::string& asked,
                       const vl::rtab_component* inside_of = nullptr) {
    const real scale = std::max(static_cast<real>(1), len(p));
    const std::vector<ray> from = rays_from(log, p, 1e-6L * scale);
    const ray* found = nullptr;
    for (const ray& r : from)
        if (len(unit(to_r(r.direction())) - want) <= 1e-9L) found = &r;
    const bool starts_inside = found != nullptr && (inside_of == nullptr || inside_of->contains(found->origin()));
    t.check(starts_inside, [&] {
        return "the transmitted ray should go towards " + show(want) + " ± 1e-9 (Snell's law) from " + show(p) +
               " (within " + num(static_cast<double>(1e-6L * scale)) + (inside_of ? ", just inside the object" : "") +
               "); " +
               (found ? "yours starts at " + show(found->origin()) + ", where contains() is false"
                      : "the rays your tracer cast from there: " + show_rays(from)) +
               ". Asked: " + asked;
    });
}

/// Checks a bench trace: red (w_r) and green (w_t) each in its band, blue 0.
void check_weights(tally& t, const bench& b, const ray& r, int depth, const band& w_r, const band& w_t,
                   const std::string& rule) {
    const traced got = trace_in(b.w.s, r, depth);
    const bool ok = got.ok() && w_r.holds(got.c.r) && w_t.holds(got.c.g) && std::fabs(got.c.b) <= 1e-12;
    t.check(ok, [&] {
        return "red (w_r) should be " + w_r.words() + ", green (w_t) " + w_t.words() + ", blue 0; yours returned " +
               got.words() + " (" + rule + "). Asked: " + b.about(r, depth);
    });
}

band exactly(real x, real tol = 1e-9L) { return {x - tol, x + tol}; }
/// kst * F + ksr and kst * (1 - F) for F anywhere in `f`.
band reflected_weight(const band& f, real ksr, real kst) { return {ksr + kst * f.lo, ksr + kst * f.hi}; }
band transmitted_weight(const band& f, real kst) { return {kst * (1 - f.hi), kst * (1 - f.lo)}; }

}  // namespace

TEST_CASE("refraction: the transmitted ray entering glass follows Snell's law", "[04][refraction][essential]") {
    tally t("rays entering a block of glass");
    dice random(4201);
    for (const double ior : {1.33, 1.5, 2.4})
        for (const real deg : {0.0L, 10.0L, 30.0L, 45.0L, 60.0L, 75.0L, 85.0L}) {
            bench b(glass(ior), false);
            const ray r = b.at_angle(radians(deg), random.uniform(0, 6.28));
            const traced got = trace_in(b.w.s, r, 1);
            if (!got.ok()) {
                t.check(false, [&] { return b.about(r, 1) + ": " + got.error; });
                continue;
            }
            const snell s = refract(unit(to_r(r.direction())), b.facing(), 1, ior);
            check_transmitted(t, b.watch->rays(), b.hit(r), s.t, b.about(r, 1));
        }
    t.report();
}

TEST_CASE("refraction: the transmitted ray lands where Snell's law says, on a small emitter below the surface",
          "[04][refraction][essential]") {
    tally t("transmitted rays aimed at a small emitter");
    for (const double ior : {1.2, 1.5, 2.0})
        for (const real deg : {20.0L, 40.0L, 55.0L}) {
            bench b(glass(ior), false, false);
            const ray r = b.at_angle(radians(deg));
            const snell s = refract(unit(to_r(r.direction())), b.facing(), 1, ior);
            const rvec p = b.hit(r);
            const rvec land = p + (-2 / s.t.y) * s.t;  // where it reaches y = -2
            b.w.ball(to_point(land), 0.03, emitter(color(0, 0, 1)));
            const band f = fresnel_band(1, ior, b.cos_i(r));
            const band blue = transmitted_weight(f, 1);
            const traced got = trace_in(b.w.s, r, 1);
            t.check(got.ok() && blue.holds(got.c.b) && std::fabs(got.c.r) <= 1e-12 && std::fabs(got.c.g) <= 1e-12, [&] {
                return "trace() should return (0, 0, w_t) with w_t " + blue.words() + "; yours returned " + got.words() +
                       ". Asked: " + show(r) + " at depth 1 enters glass filling y < 0 (" + words(b.glass_surface) +
                       ") at " + num(static_cast<double>(deg)) +
                       " degrees; by Snell's law the transmitted ray reaches a small blue emitter (radius 0.03) at " +
                       show(land) + " (no lights, ambient 1)";
            });
        }
    t.report();
}

TEST_CASE("refraction: the transmitted ray entering a glass sphere follows Snell's law about the normal there",
          "[04][refraction]") {
    tally t("rays entering glass spheres");
    dice random(4202);
    for (int k = 0; k < 60; ++k) {
        world w;
        w.emitters_shine();
        const double ior = random.uniform(1.1, 2.5);
        const point c(random.uniform(-2, 2), random.uniform(-2, 2), random.uniform(-2, 2));
        const probe_ball* ball = w.ball(c, random.uniform(0.5, 2), glass(ior));
        const probe_watcher* watch = w.watcher();
        const ray r = through(c + random.uniform(4, 10) * random.direction(), c + 0.9 * ball->radius() * random.direction());
        const real hit = ball->exact_t(r);
        if (!(hit > 0)) continue;
        const rvec p = hit_point(r, hit), d = unit(to_r(r.direction())), n = unit(p - ball->centre());
        const std::string asked = show(r) + " at depth 1 enters glass: " + ball->describe() + " (ior " + num(ior) +
                                  ") at " + show(p);
        const traced got = trace_in(w.s, r, 1);
        if (!got.ok()) {
            t.check(false, [&] { return asked + ": " + got.error; });
            continue;
        }
        check_transmitted(t, watch->rays(), p, refract(d, n, 1, ior).t, asked);
    }
    t.report();
}

TEST_CASE("refraction: at normal incidence F = R0 = ((ior - 1) / (ior + 1))^2", "[04][refraction][essential]") {
    tally t("glass seen straight on");
    for (const double ior : {1.2, 1.33, 1.5, 2.0, 2.4}) {
        bench b(glass(ior), false);
        const ray r = b.at_angle(0);
        const real r0 = ((ior - 1.0L) / (ior + 1.0L)) * ((ior - 1.0L) / (ior + 1.0L));
        check_weights(t, b, r, 1, exactly(r0), exactly(1 - r0), "F = R0 at 0 degrees, so w_r = F = " + num(static_cast<double>(r0)));
    }
    t.report();
}

TEST_CASE("refraction: towards 90 degrees from the normal F goes to 1", "[04][refraction][essential]") {
    tally t("glass seen at grazing angles");
    for (const double ior : {1.33, 1.5, 2.0})
        for (const real deg : {88.0L, 89.5L, 89.9L}) {
            bench b(glass(ior), false);
            const ray r = b.at_angle(radians(deg));
            const band f = fresnel_band(1, ior, b.cos_i(r));
            check_weights(t, b, r, 1, f, transmitted_weight(f, 1), "nearly all the light is reflected");
        }
    t.report();
}

TEST_CASE("refraction: glass with both ksr and kst reflects ksr + kst F and transmits kst (1 - F)", "[04][refraction][essential]") {
    tally t("glass with ksr and kst");
    for (const double ior : {1.5, 2.0})
        for (const std::pair<double, double>& weights :
             {std::pair{0.3, 0.6}, std::pair{0.0, 0.5}, std::pair{0.5, 0.5}, std::pair{0.1, 0.9}}) {
            const double ksr = weights.first, kst = weights.second;
            bench b(glass(ior, ksr, kst), false);
            const ray straight = b.at_angle(0);
            const real r0 = ((ior - 1.0L) / (ior + 1.0L)) * ((ior - 1.0L) / (ior + 1.0L));
            check_weights(t, b, straight, 1, exactly(ksr + kst * r0), exactly(kst * (1 - r0)),
                          "at 0 degrees F = R0 = " + num(static_cast<double>(r0)));
            const ray slant = b.at_angle(radians(70.0L), 1.0L);
            const band f = fresnel_band(1, ior, b.cos_i(slant));
            check_weights(t, b, slant, 1, reflected_weight(f, ksr, kst), transmitted_weight(f, kst),
                          "w_r = ksr + kst F and w_t = kst (1 - F) with F " + f.words());
            // Whatever F is, w_r + w_t = ksr + kst.
            const traced got = trace_in(b.w.s, slant, 1);
            t.check(got.ok() && std::fabs(got.c.r + got.c.g - (ksr + kst)) <= 1e-9, [&] {
                return "red + green (w_r + w_t) should be ksr + kst = " + num(ksr + kst) + " ± 1e-9; yours returned " +
                       got.words() + ". Asked: " + b.about(slant, 1);
            });
        }
    t.report();
}

TEST_CASE("refraction: the surface colour filters both the reflected and the transmitted light", "[04][refraction]") {
    tally t("coloured glass");
    for (const color& c : {color(0.5, 0.8, 1), color(1, 0.2, 0.6)}) {
        world w;
        w.emitters_shine();
        const surface s = glass(1.5, 0, 1, c);
        w.plane(point(0, 0, 0), vector(0, 1, 0), s, probe_plane::interior::below);
        const color above(1, 0.5, 0.25), below(0.25, 0.5, 1);
        w.plane(point(0, 2, 0), vector(0, -1, 0), emitter(above));
        w.plane(point(0, -2, 0), vector(0, 1, 0), emitter(below));
        const ray r(point(0, 1, 0), vector(0, -1, 0));
        const real r0 = 0.04L;
        check_color(t,
                    show(r) + " at depth 1 enters glass filling y < 0 (" + words(s) + ") straight on, between an emitter " +
                        show(above) + " above and one " + show(below) + " below: c * (R0 * above + (1 - R0) * below)",
                    trace_in(w.s, r, 1), of(c) * (r0 * of(above) + (1 - r0) * of(below)), 1e-9L);
    }
    t.report();
}

TEST_CASE("refraction: at oblique angles F is between Schlick's approximation and the exact Fresnel value",
          "[04][refraction][detail]") {
    tally t("glass at oblique angles");
    for (const double ior : {1.33, 1.5, 2.4})
        for (const real deg : {30.0L, 45.0L, 60.0L, 75.0L}) {
            bench b(glass(ior), false);
            const ray r = b.at_angle(radians(deg), 0.5L);
            const band f = fresnel_band(1, ior, b.cos_i(r));
            check_weights(t, b, r, 1, f, transmitted_weight(f, 1), "entering glass, Schlick's F uses cos_i");
        }
    t.report();
}

TEST_CASE("refraction: an object of ior 1 does not bend the light", "[04][refraction][detail]") {
    tally t("ior 1");
    for (const real deg : {0.0L, 30.0L, 60.0L}) {
        bench b(glass(1), false);
        const ray r = b.at_angle(radians(deg), 2.0L);
        const traced got = trace_in(b.w.s, r, 1);
        if (!got.ok()) {
            t.check(false, [&] { return b.about(r, 1) + ": " + got.error; });
            continue;
        }
        check_transmitted(t, b.watch->rays(), b.hit(r), unit(to_r(r.direction())),
                          b.about(r, 1) + " (with ior 1 the transmitted ray goes straight on)");
    }
    t.report();
}

// Where a secondary ray starts is graded with robustness (it is what keeps a ray from
// hitting the surface it leaves), so this test is in the "robust" category.
TEST_CASE("robust: the transmitted ray starts just inside the object it enters", "[04][robust][detail]") {
    tally t("where transmitted rays start");
    dice random(4203);
    for (int k = 0; k < 60; ++k) {
        world w;
        w.emitters_shine();
        const point c(random.uniform(-100, 100), random.uniform(-100, 100), random.uniform(-100, 100));
        const probe_ball* ball = w.ball(c, 3, glass(1.5));
        const probe_watcher* watch = w.watcher();
        const ray r = through(c + 10 * random.direction(), c + 0.8 * random.direction());
        const real hit = ball->exact_t(r);
        if (!(hit > 0)) continue;
        const rvec p = hit_point(r, hit), d = unit(to_r(r.direction())), n = unit(p - ball->centre());
        if (-dot(d, n) < 0.85L) continue;  // near the normal, so a transmitted ray is sure to exist
        const std::string asked = show(r) + " at depth 1 enters glass: " + ball->describe() + " (ior 1.5)";
        const traced got = trace_in(w.s, r, 1);
        if (!got.ok()) {
            t.check(false, [&] { return asked + ": " + got.error; });
            continue;
        }
        // The rays cast from the hit point into the sphere (the transmitted one) must start inside it.
        const real scale = std::max(static_cast<real>(1), len(p));
        const std::vector<ray> from = rays_from(watch->rays(), p, 1e-6L * scale);
        int inward = 0;
        const ray* outside = nullptr;
        for (const ray& x : from)
            if (dot(to_r(x.direction()), n) < 0) {
                ++inward;
                if (!ball->contains(x.origin())) outside = &x;
            }
        (void)d;
        t.check(inward > 0 && outside == nullptr, [&] {
            return std::string(inward == 0 ? "your tracer should cast a transmitted ray into the sphere from " + show(p) +
                                                 "; it cast none (the rays from there: " + show_rays(from) + ")"
                                           : "the transmitted ray should start just inside the sphere, where contains() "
                                             "is true; yours starts at " + show(outside->origin()) + ", outside it") +
                   ". Asked: " + asked;
        });
    }
    t.report();
}

TEST_CASE("refraction: at depth 0 glass shows neither reflection nor transmission", "[04][refraction][detail]") {
    tally t("glass at depth 0");
    for (const double kdr : {0.0, 0.2}) {
        world w;
        w.emitters_shine();
        const surface s = make_surface(color(0.5, 0.75, 1), kdr, 0.1, 0.9, 1, 1.5);
        w.plane(point(0, 0, 0), vector(0, 1, 0), s, probe_plane::interior::below);
        w.plane(point(0, 2, 0), vector(0, -1, 0), emitter(color(1, 0, 0)));
        w.plane(point(0, -2, 0), vector(0, 1, 0), emitter(color(0, 1, 0)));
        const ray r = through(point(0.5, 1, 0), point(0, 0, 0));
        check_color(t, show(r) + " at depth 0 enters glass filling y < 0 (" + words(s) + ") under ambient (1, 1, 1): its own ambient * c * kdr only",
                    trace_in(w.s, r, 0), static_cast<real>(kdr) * of(s.clr), 1e-12L);
    }
    t.report();
}
