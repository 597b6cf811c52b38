// Hidden tests of rays that START INSIDE an object (stage_04.hh steps 2 and 5): the normal
// negated because contains(origin) is true (also for the light on the inside of a
// sphere), refraction out of the object (eta1 = ior, eta2 = 1), total internal
// reflection beyond the critical angle (F = 1, no transmitted ray), and Schlick's F with
// the cosine on the side of the lower index (cos_t). Each TEST_CASE is one graded item
// in the rubric's "leaving" category. Most tests use the bench of hidden_support.hh from
// below: rays start inside glass filling y < 0 and go up; the emitter the reflected ray
// reaches (below) is red, the one the transmitted ray reaches (above) is green, so the
// colour is c * (w_r, w_t, 0). Where F is checked, any value between Schlick's
// approximation and the exact Fresnel equations, widened by 0.02, passes.
#include <catch2/catch.hpp>

#include <cmath>
#include <memory>
#include <string>
#include <utility>
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

surface glass(double ior, double ksr = 0, double kst = 1, const color& c = color(1, 1, 1)) {
    return make_surface(c, 0, ksr, kst, 1, ior);
}

/// The critical angle of glass of index `ior`, in radians.
real critical(real ior) { return std::asin(1 / ior); }

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
band transmitted_weight(const band& f, real kst) { return {kst * (1 - f.hi), kst * (1 - f.lo)}; }

/// Checks a ray that hits the probe sphere `ball` of `w` at depth 0 against your own
/// tracer on a sheet (a plane with no inside) through the same point whose normal is the
/// one the contract says faces the ray there: the inward normal when the ray starts
/// inside, the outward one when it comes from outside. Same lights, same ambient, same
/// surface; so only the choice of the normal is graded here.
void check_like_sheet(tally& t, const world& w, const probe_ball& ball, const ray& r, bool from_inside,
                      const std::string& lights) {
    const rvec p = hit_point(r, ball.exact_t(r)), out = unit(p - ball.centre()), n = from_inside ? -out : out;
    world sheet;
    sheet.s.ambient = w.s.ambient;
    sheet.s.lights = w.s.lights;
    sheet.plane(to_point(p), to_vector(n), ball.surf());
    const traced want = trace_in(sheet.s, r, 0), got = trace_in(w.s, r, 0);
    t.check(got.ok() && want.ok() && same(got.c, want.c, 1e-9), [&] {
        return "trace() should return what your tracer gives for a flat sheet there facing the ray with the normal " +
               show(n) + ", " + want.words() + " ± 1e-9; yours returned " + got.words() + ". Asked: " + show(r) +
               " at depth 0 " + (from_inside ? "starts inside " : "comes from outside ") + ball.describe() + " (" +
               words(ball.surf()) + ") and meets it at " + show(p) + "; " + lights;
    });
}

}  // namespace

TEST_CASE("leaving: on the inside of a sphere the normal is negated, so a light inside lights the wall",
          "[04][leaving][essential]") {
    tally t("rays inside a lit hollow sphere");
    dice random(4301);
    const surface s = make_surface(color(0.9, 0.7, 0.5), 0.8, 0.4, 0, 6);
    for (int k = 0; k < 80; ++k) {
        world w;
        w.s.ambient = color(0.05, 0.05, 0.05);
        const point c(random.uniform(-3, 3), random.uniform(-3, 3), random.uniform(-3, 3));
        probe_ball* ball = w.ball(c, 3, s);
        ball->hit_only_from_within = 2;  // its own wall never blocks the light inside it
        const point light = c + random.uniform(0, 1.5) * random.direction();
        w.light(color(1, 0.9, 0.8), light);
        const ray r(c + random.uniform(0, 1.5) * random.direction(), random.direction());
        const real hit = ball->exact_t(r);
        if (!(hit > 0)) continue;
        check_like_sheet(t, w, *ball, r, true, "a light of colour (1, 0.9, 0.8) inside it at " + show(light));
    }
    t.report();
}

TEST_CASE("leaving: the transmitted ray out of glass follows Snell's law with eta = ior", "[04][leaving][essential]") {
    tally t("rays leaving a block of glass");
    dice random(4302);
    for (const double ior : {1.33, 1.5, 2.0})
        for (const real fraction : {0.0L, 0.3L, 0.6L, 0.9L, 0.98L}) {
            bench b(glass(ior), true);
            const ray r = b.at_angle(fraction * critical(ior), random.uniform(0, 6.28));
            const traced got = trace_in(b.w.s, r, 1);
            const std::string asked = b.about(r, 1);
            if (!got.ok()) {
                t.check(false, [&] { return asked + ": " + got.error; });
                continue;
            }
            const rvec p = b.hit(r), want = refract(unit(to_r(r.direction())), b.facing(), ior, 1).t;
            const std::vector<ray> from = rays_from(b.watch->rays(), p, 1e-6L);
            bool found = false;
            for (const ray& x : from) found = found || len(unit(to_r(x.direction())) - want) <= 1e-9L;
            t.check(found, [&] {
                return "the transmitted ray should go towards " + show(want) + " ± 1e-9 from " + show(p) +
                       " (within 1e-6): Snell's law with eta1 = ior, eta2 = 1 and the normal facing the ray, (0, -1, 0); "
                       "the rays your tracer cast from there: " + show_rays(from) + ". Asked: " + asked;
            });
        }
    t.report();
}

TEST_CASE("leaving: beyond the critical angle all the light is reflected, none transmitted", "[04][leaving][essential]") {
    tally t("total internal reflection");
    for (const double ior : {1.33, 1.5, 2.4})
        for (const real extra : {0.5L, 5.0L, 20.0L, 40.0L}) {
            const real theta = critical(ior) + radians(extra);
            if (theta >= radians(89.0L)) continue;
            bench b(glass(ior), true);
            check_weights(t, b, b.at_angle(theta, 0.7L), 1, exactly(1), exactly(0),
                          "beyond the critical angle F = 1 and there is no transmitted ray");
            bench mixed(glass(ior, 0.2, 0.7), true);
            check_weights(t, mixed, mixed.at_angle(theta), 1, exactly(0.9L), exactly(0),
                          "beyond the critical angle F = 1: w_r = ksr + kst, w_t = 0");
        }
    t.report();
}

TEST_CASE("leaving: a ray at the critical angle is totally reflected, F = 1", "[04][leaving][essential]") {
    tally t("rays at the critical angle");
    for (const double ior : {1.25, 1.33, 1.5, 2.0, 2.4}) {
        bench b(glass(ior), true);
        const ray r = b.at_angle(critical(ior));
        check_weights(t, b, r, 1, exactly(1, 1e-6L), exactly(0, 1e-6L), "at the critical angle F = 1 (sin = 1 / ior)");
    }
    t.report();
}

TEST_CASE("leaving: just below the critical angle F uses the cosine on the lower index's side, cos_t",
          "[04][leaving][essential]") {
    tally t("rays just below the critical angle");
    for (const double ior : {1.33, 1.5, 2.0})
        for (const real below : {0.25L, 0.5L, 1.0L, 2.0L}) {
            bench b(glass(ior), true);
            const ray r = b.at_angle(critical(ior) - radians(below), 0.3L);
            const band f = fresnel_band(ior, 1, b.cos_i(r));
            check_weights(t, b, r, 1, f, transmitted_weight(f, 1),
                          "leaving glass " + num(static_cast<double>(below)) +
                              " degrees below the critical angle, Schlick's F uses cos_t, the cosine in the air, "
                              "not cos_i");
        }
    t.report();
}

TEST_CASE("leaving: at normal incidence from inside F = R0 and the weights are ksr + kst F and kst (1 - F)",
          "[04][leaving]") {
    tally t("glass seen straight on from inside");
    for (const double ior : {1.33, 1.5, 2.4})
        for (const std::pair<double, double>& weights : {std::pair{0.0, 1.0}, std::pair{0.25, 0.7}}) {
            const double ksr = weights.first, kst = weights.second;
            bench b(glass(ior, ksr, kst), true);
            const real r0 = ((ior - 1.0L) / (ior + 1.0L)) * ((ior - 1.0L) / (ior + 1.0L));
            check_weights(t, b, b.at_angle(0), 1, exactly(ksr + kst * r0), exactly(kst * (1 - r0)),
                          "F = R0 = " + num(static_cast<double>(r0)) + " at 0 degrees");
        }
    t.report();
}

TEST_CASE("leaving: on either side of the critical angle light gets out below it and not beyond it", "[04][leaving]") {
    tally t("rays either side of the critical angle");
    for (const double ior : {1.2, 1.33, 1.5, 1.9, 2.4})
        for (const real step : {0.05L, 0.2L}) {
            bench b(glass(ior), true);
            const ray beyond = b.at_angle(critical(ior) + radians(step), 1.3L);
            check_weights(t, b, beyond, 1, exactly(1), exactly(0),
                          num(static_cast<double>(step)) + " degrees beyond the critical angle: total internal reflection");
            const ray under = b.at_angle(critical(ior) - radians(step), 1.3L);
            const band f = fresnel_band(ior, 1, b.cos_i(under));
            check_weights(t, b, under, 1, f, transmitted_weight(f, 1),
                          num(static_cast<double>(step)) + " degrees below the critical angle: some light gets out");
        }
    t.report();
}

TEST_CASE("leaving: inside a glass sphere no light gets out beyond the critical angle, and 1 - F of it below",
          "[04][leaving]") {
    tally t("rays inside glass spheres");
    dice random(4303);
    for (int k = 0; k < 80; ++k) {
        world w;
        w.emitters_shine();
        const double ior = random.uniform(1.2, 2.2);
        const point c(random.uniform(-2, 2), random.uniform(-2, 2), random.uniform(-2, 2));
        const probe_ball* ball = w.ball(c, 1.5, glass(ior));
        w.ball(c, 10, emitter(color(0, 1, 0)));  // all around, outside the glass
        const ray r(c + random.uniform(0, 1.4) * random.direction(), random.direction());
        const real hit = ball->exact_t(r);
        if (!(hit > 0)) continue;
        const rvec p = hit_point(r, hit), n = unit(ball->centre() - p);
        const real cos_i = -dot(unit(to_r(r.direction())), n);
        const real angle = std::acos(std::min(static_cast<real>(1), cos_i));
        if (std::fabs(angle - critical(ior)) < radians(0.05L)) continue;  // too close to call
        const band f = fresnel_band(ior, 1, cos_i);
        const band green = angle > critical(ior) ? exactly(0) : transmitted_weight(f, 1);
        const traced got = trace_in(w.s, r, 1);
        t.check(got.ok() && green.holds(got.c.g) && std::fabs(got.c.r) <= 1e-12 && std::fabs(got.c.b) <= 1e-12, [&] {
            return "trace() should return (0, w_t, 0) with w_t " + green.words() + "; yours returned " + got.words() +
                   ". Asked: " + show(r) + " at depth 1 starts inside glass: " + ball->describe() + " (ior " +
                   num(ior) + ", kdr 0, kst 1) and meets its wall at " + num(static_cast<double>(degrees(angle))) +
                   " degrees from the normal (critical angle " + num(static_cast<double>(degrees(critical(ior)))) +
                   "); all around it a green emitter; no lights, ambient 1";
        });
    }
    t.report();
}

TEST_CASE("leaving: whether a ray is inside is asked of its origin, not of the point it hits", "[04][leaving][detail]") {
    tally t("spheres whose surface counts as inside");
    // These spheres' contains() is true on the surface itself (within 1e-9 of the radius):
    // only the ray's origin tells whether it comes from inside.
    dice random(4304);
    const surface s = make_surface(color(0.6, 0.9, 0.7), 0.9);
    for (int k = 0; k < 40; ++k) {
        world w;
        const point c(random.uniform(-2, 2), random.uniform(-2, 2), random.uniform(-2, 2));
        probe_ball* ball = w.ball(c, 1, s);
        ball->slack = 1e-9L;
        const bool from_inside = k % 2 == 1;
        if (from_inside) ball->hit_only_from_within = 0.7L;  // its own wall never blocks the light inside it
        const point light = from_inside ? c + 0.5 * random.direction() : c + 5 * random.direction();
        w.light(color(1, 1, 1), light);
        const ray r = from_inside ? ray(c + 0.5 * random.direction(), random.direction())
                                  : through(c + 4 * random.direction(), c + 0.8 * random.direction());
        if (!(ball->exact_t(r) > 0)) continue;
        check_like_sheet(t, w, *ball, r, from_inside,
                         "its contains() is true also on its surface; a light of colour (1, 1, 1) is at " + show(light));
    }
    t.report();
}
