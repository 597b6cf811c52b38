// Hidden tests of refraction for rays that ENTER an object from outside (stage_04.hh
// step 5): Snell's law for the transmitted direction, the Fresnel reflectance F at 0 and
// 90 degrees, and the weights w_r = ksr + kst F and w_t = kst (1 - F). Each TEST_CASE is
// one graded item in the rubric's "refraction" category. There are no lights (ambient
// (1, 1, 1), emitters of kdr 1), and most tests use the bench of hidden_support.hh: glass
// below y = 0 and emitters where the light goes. F is read on the transmitted side, from
// w_t = kst (1 - F): a small emitter where Snell's transmitted ray lands. Only what the
// glass's bounces add is graded (your trace() minus the same with ksr = kst = 0), at depth
// 3, where every secondary ray ends on an emitter or in the black background after one
// bounce, so the answer is the same at any depth from 1 on. Where F is checked, any value
// between Schlick's approximation and the exact Fresnel equations, widened by 0.02,
// passes (the contract allows either). Every expected value is computed in long double.
#include "vl/catch.hh"

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
                      : "the rays your tracer cast from there: " + show_rays(from, log, p, 1e-6L * scale)) +
               ". Asked: " + asked;
    });
}

band exactly(real x, real tol = 1e-9L) { return {x - tol, x + tol}; }
/// kst * (1 - F) for F anywhere in `f`.

/// The angle, a little off the normal, at which "normal incidence" is graded: there F is
/// R0 to 1e-12 (Schlick) or 1e-5 (exact), and the transmitted ray already misses the
/// straight line on, so the patch sees only it.
constexpr real near_normal = 3.0L;
/// F between Schlick's and the exact value, within 1e-6 (where the two agree).
band tight_fresnel(real eta1, real eta2, real cos_i) {
    const real s = schlick(eta1, eta2, cos_i), e = fresnel_exact(eta1, eta2, cos_i);
    return {std::min(s, e) - 1e-6L, std::max(s, e) + 1e-6L};
}

}  // namespace

TEST_CASE("refraction: the transmitted ray entering glass follows Snell's law", "[04][refraction][essential]") {
    tally t("rays entering a block of glass");
    dice random(4201);
    for (const double ior : {1.33, 1.5, 2.4})
        for (const real deg : {0.0L, 10.0L, 30.0L, 45.0L, 60.0L, 75.0L, 85.0L}) {
            bench b(glass(ior), false);
            b.red_green();
            const ray r = b.at_angle(radians(deg), random.uniform(0, 6.28));
            const traced got = trace_in(b.w.s, r, 3);
            if (!got.ok()) {
                t.check(false, [&] { return b.about(r, 3) + ": " + got.error; });
                continue;
            }
            const snell s = refract(unit(to_r(r.direction())), b.facing(), 1, ior);
            check_transmitted(t, b.watch->rays(), b.hit(r), s.t, b.about(r, 3));
        }
    t.report();
}

TEST_CASE("refraction: the transmitted ray lands where Snell's law says - on a small emitter below the surface",
          "[04][refraction][essential]") {
    tally t("transmitted rays aimed at a small emitter");
    for (const double ior : {1.2, 1.5, 2.0})
        for (const real deg : {20.0L, 40.0L, 55.0L}) {
            bench b(glass(ior), false);
            const ray r = b.at_angle(radians(deg));
            if (!placed_patch(t, b, r)) continue;
            check_transmitted_weight(t, b, r, 3, transmitted_weight(fresnel_band(1, ior, b.cos_i(r)), 1),
                                     "by Snell's law the transmitted ray reaches the patch");
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
        probe_ball* ball = w.ball(c, random.uniform(0.5, 2), glass(ior));
        ball->enter_only = true;  // the transmitted ray passes out unhindered
        const probe_watcher* watch = w.watcher();
        const ray r = ray_through(c + random.uniform(4, 10) * random.direction(), c + 0.9 * ball->radius() * random.direction());
        const real hit = ball->exact_t(r);
        if (!(hit > 0)) continue;
        const rvec p = hit_point(r, hit), d = unit(to_r(r.direction())), n = unit(p - ball->centre());
        const std::string asked = show(r) + " at depth 3 enters glass: " + ball->describe() + " (ior " + num(ior) +
                                  ") at " + show(p);
        const traced got = trace_in(w.s, r, 3);
        if (!got.ok()) {
            t.check(false, [&] { return asked + ": " + got.error; });
            continue;
        }
        check_transmitted(t, watch->rays(), p, refract(d, n, 1, ior).t, asked);
    }
    t.report();
}

TEST_CASE("refraction: near normal incidence F = R0 = ((ior - 1) / (ior + 1))^2", "[04][refraction][essential]") {
    tally t("glass seen nearly straight on");
    for (const double ior : {1.2, 1.33, 1.5, 2.0, 2.4}) {
        bench b(glass(ior), false);
        const ray r = b.at_angle(radians(near_normal), 0.4L);
        if (!placed_patch(t, b, r)) continue;
        const real r0 = ((ior - 1.0L) / (ior + 1.0L)) * ((ior - 1.0L) / (ior + 1.0L));
        check_transmitted_weight(t, b, r, 3, transmitted_weight(tight_fresnel(1, ior, b.cos_i(r)), 1),
                                 num(static_cast<double>(near_normal)) + " degrees from the normal F = R0 = " +
                                     num(static_cast<double>(r0)) + ", so w_t = 1 - R0",
                                 transmitted_suspects(1, ior, b.cos_i(r), 1));
    }
    t.report();
}

TEST_CASE("refraction: towards 90 degrees from the normal F goes to 1", "[04][refraction][essential]") {
    tally t("glass seen at grazing angles");
    for (const double ior : {1.33, 1.5, 2.0})
        for (const real deg : {88.0L, 89.5L, 89.9L}) {
            bench b(glass(ior), false);
            const ray r = b.at_angle(radians(deg));
            if (!placed_patch(t, b, r)) continue;
            const band f = fresnel_band(1, ior, b.cos_i(r));
            check_transmitted_weight(t, b, r, 3, transmitted_weight(f, 1),
                                     "nearly all the light is reflected: F " + f.words() + ", little is transmitted",
                                     transmitted_suspects(1, ior, b.cos_i(r), 1));
        }
    t.report();
}

TEST_CASE("refraction: glass with both ksr and kst transmits kst (1 - F) - and w_r + w_t = ksr + kst",
          "[04][refraction][essential]") {
    tally t("glass with ksr and kst");
    for (const double ior : {1.5, 2.0})
        for (const std::pair<double, double>& weights :
             {std::pair{0.3, 0.6}, std::pair{0.0, 0.5}, std::pair{0.5, 0.5}, std::pair{0.1, 0.9}}) {
            const double ksr = weights.first, kst = weights.second;
            const real r0 = ((ior - 1.0L) / (ior + 1.0L)) * ((ior - 1.0L) / (ior + 1.0L));
            {
                bench b(glass(ior, ksr, kst), false);
                const ray straight = b.at_angle(radians(near_normal), 2.0L);
                if (placed_patch(t, b, straight))
                    check_transmitted_weight(t, b, straight, 3,
                                             transmitted_weight(tight_fresnel(1, ior, b.cos_i(straight)), kst),
                                             "near the normal F = R0 = " + num(static_cast<double>(r0)),
                                             transmitted_suspects(1, ior, b.cos_i(straight), kst));
            }
            {
                bench b(glass(ior, ksr, kst), false);
                const ray slant = b.at_angle(radians(70.0L), 1.0L);
                const band f = fresnel_band(1, ior, b.cos_i(slant));
                if (placed_patch(t, b, slant))
                    check_transmitted_weight(t, b, slant, 3, transmitted_weight(f, kst), "F " + f.words(),
                                             transmitted_suspects(1, ior, b.cos_i(slant), kst));
            }
            {
                // Whatever F is, w_r + w_t = ksr + kst: the same emitter on both sides.
                bench b(glass(ior, ksr, kst), false);
                b.both_sides();
                const ray slant = b.at_angle(radians(70.0L), 1.0L);
                check_total_weight(t, b, slant, 3, exactly(ksr + kst), "ksr + kst F + kst (1 - F) = ksr + kst");
            }
        }
    t.report();
}

TEST_CASE("refraction: the surface colour filters the transmitted light", "[04][refraction]") {
    tally t("coloured glass");
    for (const color& c : {color(0.5, 0.8, 1), color(1, 0.2, 0.6)}) {
        bench b(glass(1.5, 0, 1, c), false);
        const ray r = b.at_angle(radians(near_normal), 1.0L);
        const color below(0.25, 0.5, 1);
        if (!placed_patch(t, b, r, below)) continue;
        traced seen;
        if (!emitter_shows(t, b.w.s, b.at_patch(), &color::b, "the patch " + show(below), seen)) continue;
        const band f = tight_fresnel(1, 1.5, b.cos_i(r));
        const bounced got = b.bounces(r, 3);
        bool ok = got.ok();
        std::string want;
        for (double color::*ch : {&color::r, &color::g, &color::b}) {
            const band k = scaled(transmitted_weight(f, 1), c.*ch * seen.c.*ch);
            ok = ok && k.holds(got.part.*ch);
            want += (want.empty() ? "" : ", ") + k.words();
        }
        t.check(ok, [&] {
            return "the bounces should bring back c * (1 - F) * (what your tracer shows for the patch, " + show(seen.c) +
                   "), channel by channel: red, green, blue " + want + "; they brought back " + got.words() +
                   ". Asked: " + b.about(r, 3);
        });
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
            if (!placed_patch(t, b, r)) continue;
            const band f = fresnel_band(1, ior, b.cos_i(r));
            check_transmitted_weight(t, b, r, 3, transmitted_weight(f, 1),
                                     "entering glass, Schlick's F takes cos_i and R0 = ((n1 - n2) / (n1 + n2))^2: F " +
                                         f.words(),
                                     transmitted_suspects(1, ior, b.cos_i(r), 1));
        }
    t.report();
}

TEST_CASE("refraction: an object of ior 1 does not bend the light", "[04][refraction][detail]") {
    tally t("ior 1");
    for (const real deg : {0.0L, 30.0L, 60.0L}) {
        bench b(glass(1), false);
        b.red_green();
        const ray r = b.at_angle(radians(deg), 2.0L);
        const traced got = trace_in(b.w.s, r, 3);
        if (!got.ok()) {
            t.check(false, [&] { return b.about(r, 3) + ": " + got.error; });
            continue;
        }
        check_transmitted(t, b.watch->rays(), b.hit(r), unit(to_r(r.direction())),
                          b.about(r, 3) + " (with ior 1 the transmitted ray goes straight on)");
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
        probe_ball* ball = w.ball(c, 3, glass(1.5));
        ball->enter_only = true;  // the transmitted ray passes out unhindered
        const probe_watcher* watch = w.watcher();
        const ray r = ray_through(c + 10 * random.direction(), c + 0.8 * random.direction());
        const real hit = ball->exact_t(r);
        if (!(hit > 0)) continue;
        const rvec p = hit_point(r, hit), d = unit(to_r(r.direction())), n = unit(p - ball->centre());
        if (-dot(d, n) < 0.85L) continue;  // near the normal, so a transmitted ray is sure to exist
        const std::string asked = show(r) + " at depth 3 enters glass: " + ball->describe() + " (ior 1.5)";
        const traced got = trace_in(w.s, r, 3);
        if (!got.ok()) {
            t.check(false, [&] { return asked + ": " + got.error; });
            continue;
        }
        // The rays cast from the hit point into the sphere (whatever their direction) must
        // start inside it.
        const real scale = std::max(static_cast<real>(1), len(p));
        const std::vector<ray> from = rays_from(watch->rays(), p, 1e-6L * scale);
        int inward = 0;
        const ray* outside = nullptr;
        for (const ray& x : from)
            if (dot(to_r(x.direction()), n) < 0) {
                ++inward;
                if (!ball->contains(x.origin())) outside = &x;
            }
        t.check(inward > 0 && outside == nullptr, [&] {
            return std::string(inward == 0 ? "your tracer should cast a transmitted ray into the sphere from " + show(p) +
                                                 "; it cast none (the rays from there: " + show_rays(from, watch->rays(), p, 1e-6L * scale) + ")"
                                           : "the transmitted ray should start just inside the sphere, where contains() "
                                             "is true; yours starts at " + show(outside->origin()) + ", outside it") +
                   ". Asked: " + asked;
        });
    }
    t.report();
}
