// Hidden tests of rays that START INSIDE an object (stage_04.hh steps 2 and 5): the normal
// negated because contains(origin) is true (also for the light on the inside of a
// sphere), refraction out of the object (eta1 = ior, eta2 = 1), total internal
// reflection beyond the critical angle (F = 1, no transmitted ray), and Schlick's F with
// the cosine on the side of the lower index (cos_t). Each TEST_CASE is one graded item
// in the rubric's "refraction" category (tagged [leaving]: the ray leaves the object).
// Most tests use the bench of hidden_support.hh from below: rays start inside glass
// filling y < 0 and go up. F is read on the transmitted side, from w_t = kst (1 - F): a
// small emitter where Snell's transmitted ray lands; total internal reflection with an
// emitter on each side: all the light, w_r + w_t = ksr + kst, comes back. Only what the
// glass's bounces add is graded (your trace() minus the same with ksr = kst = 0), at depth
// 3, where every secondary ray ends on an emitter or in the black background after one
// bounce. Where F is checked, any value between Schlick's approximation and the exact
// Fresnel equations, widened by 0.02, passes.
#include "vl/catch.hh"

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

/// The critical angle of glass of index `ior`, in radians.
real critical(real ior) { return std::asin(1 / ior); }

band exactly(real x, real tol = 1e-9L) { return {x - tol, x + tol}; }
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

TEST_CASE("leaving: on the inside of a sphere the normal is negated - so a light inside lights the wall",
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
            b.red_green();
            const ray r = b.at_angle(fraction * critical(ior), random.uniform(0, 6.28));
            const traced got = trace_in(b.w.s, r, 3);
            const std::string asked = b.about(r, 3);
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
                       "the rays your tracer cast from there: " + show_rays(from, b.watch->rays(), p, 1e-6L) + ". Asked: " + asked;
            });
        }
    t.report();
}

TEST_CASE("leaving: beyond the critical angle all the light is reflected - none transmitted", "[04][leaving][essential]") {
    tally t("total internal reflection");
    for (const double ior : {1.33, 1.5, 2.4})
        for (const real extra : {0.5L, 5.0L, 20.0L, 40.0L}) {
            const real theta = critical(ior) + radians(extra);
            if (theta >= radians(89.0L)) continue;
            bench b(glass(ior), true);
            b.both_sides();
            check_total_weight(t, b, b.at_angle(theta, 0.7L), 3, exactly(1),
                               "beyond the critical angle F = 1: w_r = ksr + kst F = 1 (and w_t = 0)");
            bench mixed(glass(ior, 0.2, 0.7), true);
            mixed.both_sides();
            check_total_weight(t, mixed, mixed.at_angle(theta), 3, exactly(0.9L),
                               "beyond the critical angle F = 1: w_r = ksr + kst = 0.9, w_t = 0");
        }
    t.report();
}

TEST_CASE("leaving: a ray at the critical angle is totally reflected - F = 1", "[04][leaving][essential]") {
    tally t("rays at the critical angle");
    for (const double ior : {1.25, 1.33, 1.5, 2.0, 2.4}) {
        bench b(glass(ior), true);
        b.both_sides();
        const ray r = b.at_angle(critical(ior));
        check_total_weight(t, b, r, 3, exactly(1, 1e-6L), "at the critical angle F = 1 (sin = 1 / ior): all comes back");
    }
    t.report();
}

TEST_CASE("leaving: just below the critical angle F uses the cosine on the lower index's side - cos_t",
          "[04][leaving][essential]") {
    tally t("rays just below the critical angle");
    for (const double ior : {1.33, 1.5, 2.0})
        for (const real below : {0.25L, 0.5L, 1.0L, 2.0L}) {
            bench b(glass(ior), true);
            const ray r = b.at_angle(critical(ior) - radians(below), 0.3L);
            if (!placed_patch(t, b, r)) continue;
            const band f = fresnel_band(ior, 1, b.cos_i(r));
            check_transmitted_weight(t, b, r, 3, transmitted_weight(f, 1),
                                     "leaving glass " + num(static_cast<double>(below)) +
                                         " degrees below the critical angle, Schlick's F takes cos_t, the cosine in "
                                         "the air, and R0 = ((n1 - n2) / (n1 + n2))^2: F " + f.words(),
                                     transmitted_suspects(ior, 1, b.cos_i(r), 1));
        }
    t.report();
}

TEST_CASE("leaving: near normal incidence from inside F = R0 and the transmitted weight is kst (1 - F)",
          "[04][leaving]") {
    tally t("glass seen nearly straight on from inside");
    for (const double ior : {1.33, 1.5, 2.4})
        for (const std::pair<double, double>& weights : {std::pair{0.0, 1.0}, std::pair{0.25, 0.7}}) {
            const double ksr = weights.first, kst = weights.second;
            bench b(glass(ior, ksr, kst), true);
            const ray r = b.at_angle(radians(3.0L), 0.9L);
            if (!placed_patch(t, b, r)) continue;
            const real r0 = ((ior - 1.0L) / (ior + 1.0L)) * ((ior - 1.0L) / (ior + 1.0L));
            const real s = schlick(ior, 1, b.cos_i(r)), e = fresnel_exact(ior, 1, b.cos_i(r));
            check_transmitted_weight(t, b, r, 3, transmitted_weight({std::min(s, e) - 1e-6L, std::max(s, e) + 1e-6L}, kst),
                                     "3 degrees from the normal F = R0 = " + num(static_cast<double>(r0)),
                                     transmitted_suspects(ior, 1, b.cos_i(r), kst));
        }
    t.report();
}

TEST_CASE("leaving: on either side of the critical angle light gets out below it and not beyond it", "[04][leaving]") {
    tally t("rays either side of the critical angle");
    for (const double ior : {1.2, 1.33, 1.5, 1.9, 2.4})
        for (const real step : {0.05L, 0.2L}) {
            bench b(glass(ior), true);
            b.both_sides();
            const ray beyond = b.at_angle(critical(ior) + radians(step), 1.3L);
            check_total_weight(t, b, beyond, 3, exactly(1),
                               num(static_cast<double>(step)) + " degrees beyond the critical angle: total internal "
                                                                "reflection, all the light comes back");
            bench u(glass(ior), true);
            const ray under = u.at_angle(critical(ior) - radians(step), 1.3L);
            if (!placed_patch(t, u, under)) continue;
            const band f = fresnel_band(ior, 1, u.cos_i(under));
            check_transmitted_weight(t, u, under, 3, transmitted_weight(f, 1),
                                     num(static_cast<double>(step)) + " degrees below the critical angle: some light "
                                                                      "gets out, F " + f.words(),
                                     transmitted_suspects(ior, 1, u.cos_i(under), 1));
        }
    t.report();
}

TEST_CASE("leaving: inside a glass sphere no light gets out beyond the critical angle - and 1 - F of it below",
          "[04][leaving]") {
    tally t("rays inside glass spheres");
    dice random(4303);
    for (int k = 0; k < 80; ++k) {
        world w;
        w.emitters_shine();
        const double ior = random.uniform(1.2, 2.2);
        const point c(random.uniform(-2, 2), random.uniform(-2, 2), random.uniform(-2, 2));
        probe_ball* ball = w.ball(c, 1.5, glass(ior));
        ball->hit_only_from_within = 1.45L;  // a ray that bounces inside passes out unhindered
        const ray r(c + random.uniform(0, 1.4) * random.direction(), random.direction());
        const real hit = ball->exact_t(r);
        if (!(hit > 0)) continue;
        const rvec p = hit_point(r, hit), n = unit(ball->centre() - p), d = unit(to_r(r.direction()));
        const real cos_i = -dot(d, n);
        const real angle = std::acos(std::min(static_cast<real>(1), cos_i));
        if (std::fabs(angle - critical(ior)) < radians(0.05L)) continue;  // too close to call
        const bool total = angle > critical(ior);
        // Total internal reflection: a green emitter all around, so all the light comes
        // back whichever way it goes. Below the critical angle: only a small green
        // emitter where the transmitted ray lands, 1 outside the wall.
        rvec land;
        ray at;
        if (total) {
            w.ball(c, 10, emitter(color(0, 1, 0)));
            at = ray(c + vector(0, 2, 0), vector(0, 1, 0));  // from outside the glass
        } else {
            const snell s = refract(d, n, ior, 1);
            land = p + 1.0L * unit(s.t);
            if (!passes_by(p, d, land, 0.03L) || !passes_by(p, mirror(d, n), land, 0.03L)) continue;
            w.ball(to_point(land), 0.01, emitter(color(0, 1, 0)));
            at = ray(to_point(land - 0.5L * unit(s.t)), to_vector(unit(s.t)));
        }
        const std::string asked =
            show(r) + " at depth 3 starts inside glass: " + ball->describe() + " (ior " + num(ior) +
            ", kdr 0, kst 1) and meets its wall at " + num(static_cast<double>(degrees(angle))) +
            " degrees from the normal (critical angle " + num(static_cast<double>(degrees(critical(ior)))) + "); " +
            (total ? "all around it a green emitter" : "only a small green emitter at " + show(land) +
                                                           ", where the transmitted ray lands") +
            "; no lights, ambient 1";
        traced seen;
        if (!emitter_shows(t, w.s, at, &color::g, "the green emitter", seen)) continue;
        const band f = fresnel_band(ior, 1, cos_i);
        const band green = scaled(total ? exactly(1) : transmitted_weight(f, 1), seen.c.g);
        const bounced got = bounce_part(w.s, *ball, r, 3);
        t.check(got.ok() && green.holds(got.part.g) && std::fabs(got.part.r) <= 1e-9 && std::fabs(got.part.b) <= 1e-9,
                [&] {
                    return "the bounces should bring back (0, " + green.words() + ", 0) (" +
                           (total ? std::string("total internal reflection: all of it comes back")
                                  : "w_t = 1 - F, with F " + f.words()) +
                           ", times your emitter's " + show(seen.c) + "); they brought back " + got.words() +
                           ". Asked: " + asked;
                });
    }
    t.report();
}

TEST_CASE("leaving: whether a ray is inside is asked of its origin - not of the point it hits", "[04][leaving][detail]") {
    tally t("spheres whose surface counts as inside");
    // These spheres' contains() is true on the surface itself (within 1e-9 of the radius):
    // only the ray's origin tells whether it comes from inside. Every light is on the side
    // the normal faces.
    dice random(4304);
    const surface s = make_surface(color(0.6, 0.9, 0.7), 0.9);
    for (int k = 0; k < 40; ++k) {
        world w;
        const point c(random.uniform(-2, 2), random.uniform(-2, 2), random.uniform(-2, 2));
        probe_ball* ball = w.ball(c, 1, s);
        ball->slack = 1e-9L;
        const bool from_inside = k % 2 == 1;
        if (from_inside) ball->hit_only_from_within = 0.7L;  // its own wall never blocks the light inside it
        const ray r = from_inside ? ray(c + 0.5 * random.direction(), random.direction())
                                  : ray_through(c + 4 * random.direction(), c + 0.8 * random.direction());
        const real hit = ball->exact_t(r);
        if (!(hit > 0)) continue;
        const rvec p = hit_point(r, hit), out = unit(p - ball->centre());
        const point light = from_inside ? c + 0.5 * random.direction()
                                        : to_point(p + 3.0L * unit(out + 0.8L * to_r(random.direction())));
        w.light(color(1, 1, 1), light);
        check_like_sheet(t, w, *ball, r, from_inside,
                         "its contains() is true also on its surface; a light of colour (1, 1, 1) is at " + show(light));
    }
    t.report();
}
