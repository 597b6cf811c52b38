// Hidden tests of stage 02's sphere (sphere.cc). Each TEST_CASE is one graded item; the
// tag [sphere] puts it in the rubric's "sphere" category. Every expected answer comes
// from the long-double formulas in hidden_support.hh, never from another of your objects.
#include "vl/catch.hh"

#include <cmath>
#include <exception>
#include <limits>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "hidden_support.hh"

using vl::intersection;
using vl::point;
using vl::primitive;
using vl::ray;
using vl::rtab_component;
using vl::vector;
using vl::stage02::make_sphere;
using namespace vl::stage02::hidden;

namespace {

struct ball {
    point center;
    double radius;
};

std::string describe(const ball& b) { return "the sphere around " + show(b.center) + " of radius " + num(b.radius); }

// The tolerance of a hit distance: 1e-12 of the size of the numbers involved, which is
// what a formula that does not cancel keeps.
double tolerance_of(const sphere_key& roots) { return 1e-12 * static_cast<double>(roots.scale); }

// The nearest root beyond |zero_t|, as the contract asks.
double expected_t(const sphere_key& roots, double zero_t) {
    const double eps = std::fabs(zero_t);
    if (!roots.meets) return 0;
    if (roots.t0 > eps) return static_cast<double>(roots.t0);
    if (roots.t1 > eps) return static_cast<double>(roots.t1);
    return 0;
}

// Checks one ray against the answer key: a hit at the expected t, or a miss.
void check_ray(tally& t, const primitive& s, const ball& b, const ray& r, double extra_tolerance = 0) {
    const sphere_key roots = sphere_oracle(b.center, b.radius, r);
    const double want = expected_t(roots, s.zero_t());
    const double tol = tolerance_of(roots) + extra_tolerance;
    const intersection i = s.intersect(r);
    if (want > 0)
        check_hit_at(t, i, s, r, want, tol, [&] { return describe(b); });
    else
        t.check(clean_miss(i), [&] { return show(r) + " should miss " + describe(b) + "; yours returned " + show(i, &s); });
}

// A point strictly inside the ball of radius `fraction` * radius around the centre.
point inside(sampler& random, const ball& b, double fraction) {
    return b.center + (fraction * b.radius * std::cbrt(random.uniform(0, 1))) * random.direction();
}

const std::vector<ball> spheres = {
    {point(0, 0, -5), 1},   {point(1, 2, 3), 2},          {point(-40, 12, 7.5), 0.3},
    {point(1e3, -2e3, 5e2), 50}, {point(0.25, -0.5, 0.125), 1e-3},
};

// The same answers from `got` as from `want` (the same sphere made another way): bounds,
// normals and hits, for rays clear of the silhouette.
void check_same_sphere(tally& t, const rtab_component& got, const primitive& want, const ball& b, const std::string& who) {
    const point lo = got.min_point(), hi = got.max_point(), wlo = want.min_point(), whi = want.max_point();
    const double size = std::fabs(b.center.x) + std::fabs(b.center.y) + std::fabs(b.center.z) + b.radius;
    const double slack = 8 * std::numeric_limits<double>::epsilon() * size;
    for (int axis = 0; axis < 3; ++axis) {
        const double g[2] = {axis == 0 ? lo.x : axis == 1 ? lo.y : lo.z, axis == 0 ? hi.x : axis == 1 ? hi.y : hi.z};
        const double w[2] = {axis == 0 ? wlo.x : axis == 1 ? wlo.y : wlo.z, axis == 0 ? whi.x : axis == 1 ? whi.y : whi.z};
        for (int k = 0; k < 2; ++k)
            t.check(std::fabs(g[k] - w[k]) <= slack, [&] {
                return who + "'s " + (k == 0 ? "min_point() " : "max_point() ") + show(k == 0 ? lo : hi) + " should be " +
                       show(k == 0 ? wlo : whi) + " ± " + num(slack) + " in every axis";
            });
    }
    t.check(got.type_name() == "SPHERE", [&] { return who + "'s type_name() is \"" + got.type_name() + "\", not \"SPHERE\""; });
    sampler random(101);
    for (int k = 0; k < 40; ++k) {
        const point in = inside(random, b, 0.9), out = b.center + b.radius * random.uniform(1.1, 3) * random.direction();
        const vector u = random.direction();
        const point on = b.center + b.radius * u;
        const vector gn = got.normal(on), wn = want.normal(on);
        const double normal_tolerance = 1e-9 + 4 * slack / b.radius;
        t.check((gn - wn).length() <= normal_tolerance, [&] {
            return who + ".normal(" + show(on) + ") is " + show(gn) + " where the sphere's is " + show(wn) + " (± " +
                   num(normal_tolerance) + ")";
        });
        const point from = b.center + b.radius * random.uniform(1.5, 20) * random.direction();
        const ray r = ray_through(from, k % 2 == 0 ? in : out);
        const intersection i = got.intersect(r), j = want.intersect(r);
        const double tol = tolerance_of(sphere_oracle(b.center, b.radius, r)) + slack;
        const bool same = (i.hit() && j.hit() && std::fabs(i.t - j.t) <= tol && i.object == &got) ||
                          (clean_miss(i) && clean_miss(j));
        t.check(same, [&] {
            return show(r) + ": " + who + " returned " + show(i, &got) + " where the sphere returned " + show(j, &want) +
                   " (± " + num(tol) + ")";
        });
    }
}

}  // namespace

// --- hits from outside, misses -------------------------------------------------------------

TEST_CASE("sphere: rays from outside hit the near side at the distance the geometry gives", "[02][sphere][hits][essential]") {
    tally t("rays from outside aimed into the sphere");
    {
        const auto s = make_sphere(point(0, 0, 0), 1);
        check_ray(t, *s, {point(0, 0, 0), 1}, ray(point(0, 0, 5), vector(0, 0, -1)));
        const auto off = make_sphere(point(1, 2, 3), 2);
        check_ray(t, *off, {point(1, 2, 3), 2}, ray(point(1, 3, 10), vector(0, 0, -1)));  // t = 7 - sqrt(3)
    }
    sampler random(201);
    for (const ball& b : spheres) {
        const auto s = make_sphere(b.center, b.radius);
        for (int k = 0; k < 300; ++k) {
            const point from = b.center + b.radius * random.uniform(1.05, 60) * random.direction();
            check_ray(t, *s, b, ray_through(from, inside(random, b, 0.999)));
        }
    }
    t.report();
}

TEST_CASE("sphere: rays that pass beside it - point away from it or start beyond it miss", "[02][sphere][misses][essential]") {
    tally t("rays that never meet the sphere");
    sampler random(202);
    for (const ball& b : spheres) {
        const auto s = make_sphere(b.center, b.radius);
        for (int k = 0; k < 200; ++k) {
            const vector d = random.direction();
            vector u, v;
            plane_axes(d, u, v);
            const double turn = random.uniform(0, 2 * std::numbers::pi);
            // The line's nearest point to the centre is outside the sphere.
            const point nearest =
                b.center + b.radius * (1 + std::pow(10.0, random.uniform(-6, 0.5))) * (std::cos(turn) * u + std::sin(turn) * v);
            check_ray(t, *s, b, ray(nearest - b.radius * random.uniform(-20, 20) * d, d));
            // From outside, pointing away from the centre.
            const vector out = random.direction();
            const point from = b.center + b.radius * random.uniform(1.01, 30) * out;
            vector away = random.direction();
            if (away * out < 0.05) away = away + (0.05 - away * out + 0.5) * out;
            check_ray(t, *s, b, ray(from, away));
        }
    }
    t.report();
}

// --- rays from inside and from the surface ----------------------------------------------

TEST_CASE("sphere: rays from inside - from the centre or anywhere else - hit the far side ahead", "[02][sphere][inside][essential]") {
    tally t("rays that start inside the sphere");
    sampler random(203);
    for (const ball& b : spheres) {
        const auto s = make_sphere(b.center, b.radius);
        check_ray(t, *s, b, ray(b.center, random.direction()));
        for (int k = 0; k < 300; ++k) check_ray(t, *s, b, ray(inside(random, b, 0.995), random.direction()));
    }
    t.report();
}

TEST_CASE("sphere: rays that start on the surface hit the far side going in and nothing going out", "[02][sphere][surface][essential]") {
    // The origins are computed points of the surface, each off it by round-off. Going
    // out, the only other root is ~1e-16 away: it must be hidden by zero_t, also when
    // zero_t is negative (the contract compares with its absolute value).
    tally t("rays that start on the surface");
    sampler random(204);
    for (const double zero_t : {1e-6, -1e-6}) {
        for (const ball& b : spheres) {
            const auto s = make_sphere(b.center, b.radius);
            vl::surface surf;
            surf.zero_t = zero_t * b.radius;
            s->set_surface(surf);
            for (int k = 0; k < 150; ++k) {
                const vector u = random.direction();
                const point on = b.center + b.radius * u;
                vector d = random.direction();
                if (std::fabs(d * u) < 0.02) continue;  // nearly tangent: either answer is right
                const ray r(on, d);
                const intersection i = s->intersect(r);
                const std::string what = " with zero_t = " + num(s->zero_t());
                if (d * u > 0) {
                    t.check(clean_miss(i), [&] {
                        return show(r) + " leaves " + describe(b) + " outwards" + what + ": it should miss; yours returned " +
                               show(i, s.get());
                    });
                } else {
                    const sphere_key roots = sphere_oracle(b.center, b.radius, r);
                    const double want = static_cast<double>(roots.t1), tol = tolerance_of(roots);
                    t.check(hit_near(i, s.get(), want, tol), [&] {
                        return show(r) + " enters " + describe(b) + what + ": it should hit the far side at t = " + num(want) +
                               " ± " + num(tol) + "; yours returned " + show(i, s.get());
                    });
                }
            }
        }
    }
    t.report();
}

TEST_CASE("sphere: zero_t - positive or negative - hides every hit up to its absolute value", "[02][sphere][zero_t]") {
    // Along -z from the origin the sphere around (0, 0, -1.3) of radius 1 is entered at
    // t = 0.3 and left at t = 2.3; from (0, 0, -1.3) itself the far side is at t = 1.
    tally t("hits with different zero_t");
    const auto s = make_sphere(point(0, 0, -1.3), 1);
    const ball b{point(0, 0, -1.3), 1};
    const ray outside(point(0, 0, 0), vector(0, 0, -1)), from_centre(point(0, 0, -1.3), vector(0, 1, 0));
    const struct {
        double zero_t;
        const ray* r;
    } cases[] = {{0, &outside},    {1e-6, &outside},    {0.2, &outside},      {-0.2, &outside},     {0.5, &outside},
                 {-0.5, &outside}, {2.2, &outside},     {-2.2, &outside},     {2.5, &outside},      {-2.5, &outside},
                 {-1e-6, &from_centre}, {0.9, &from_centre}, {-0.9, &from_centre}, {1.2, &from_centre}, {-1.2, &from_centre}};
    for (const auto& c : cases) {
        vl::surface surf;
        surf.zero_t = c.zero_t;
        s->set_surface(surf);
        const sphere_key roots = sphere_oracle(b.center, b.radius, *c.r);
        const double want = expected_t(roots, c.zero_t), tol = tolerance_of(roots);
        const intersection i = s->intersect(*c.r);
        t.check(want > 0 ? hit_near(i, s.get(), want, tol) : clean_miss(i), [&] {
            return show(*c.r) + " with zero_t = " + num(c.zero_t) + " should " +
                   (want > 0 ? "hit at t = " + num(want) + " ± " + num(tol) : std::string("miss")) + "; yours returned " +
                   show(i, s.get());
        });
    }
    t.report();
}

// --- precision ---------------------------------------------------------------------------

TEST_CASE("sphere: the near side of a huge sphere seen from close by keeps its digits", "[02][sphere][precision]") {
    // A ground sphere of radius 1e6 seen from about 1 unit above it. The coordinates are
    // of size 1e6, so each carries an error of about 1e-10: 1e-9 of the distance is allowed.
    tally t("rays at a huge sphere from just above it");
    const ball b{point(0, -1e6, 0), 1e6};
    const auto s = make_sphere(b.center, b.radius);
    sampler random(207);
    for (int k = 0; k < 200; ++k) {
        const point from(random.uniform(-50, 50), random.uniform(0.5, 2), random.uniform(-50, 50));
        const vector d = k == 0 ? vector(0, -1, 0) : vector(random.uniform(-0.5, 0.5), -1, random.uniform(-0.5, 0.5));
        const ray r(k == 0 ? point(0, 1, 0) : from, d);
        const sphere_key roots = sphere_oracle(b.center, b.radius, r);
        const double want = expected_t(roots, s->zero_t()), tol = 1e-9 * want;
        const intersection i = s->intersect(r);
        check_hit_at(t, i, *s, r, want, tol, [&] { return describe(b); });
    }
    t.report();
}

// --- normals, contains, bounds -------------------------------------------------------------

TEST_CASE("sphere: normals all over the surface are outward unit vectors - also where a ray from inside hits", "[02][sphere][normals][essential]") {
    tally t("normals");
    sampler random(208);
    std::vector<ball> all = spheres;
    all.push_back({point(1e5, -3e4, 2e4), 0.5});
    for (const ball& b : all) {
        const auto s = make_sphere(b.center, b.radius);
        for (int k = 0; k < 100; ++k) {
            const point p = b.center + b.radius * random.direction();
            const rvec want = unit(to_r(p) - to_r(b.center));
            const vector n = s->normal(p);
            const double gap = static_cast<double>(
                std::max({std::fabs(n.x - want.x), std::fabs(n.y - want.y), std::fabs(n.z - want.z)}));
            t.check(gap <= 1e-9, [&] {
                return "the normal of " + describe(b) + " at " + show(p) + " should be (" + num(static_cast<double>(want.x)) +
                       ", " + num(static_cast<double>(want.y)) + ", " + num(static_cast<double>(want.z)) +
                       ") ± 1e-9 (unit, pointing away from the centre); yours is " + show(n);
            });
        }
        // From inside, the hit is on the far side and its normal still points outward:
        // along the ray, not against it.
        for (int k = 0; k < 20; ++k) {
            const ray r(inside(random, b, 0.9), random.direction());
            const intersection i = s->intersect(r);
            if (!clean_hit(i, s.get())) continue;  // the hit tests above judge that
            const point p = r.t_point(i.t);
            const vector n = s->normal(p);
            t.check(n * r.direction() > 0 && std::fabs(n.length() - 1) < 1e-9, [&] {
                return "where " + show(r) + " leaves " + describe(b) + ", at " + show(p) +
                       ", the normal should point outward (along the ray); yours is " + show(n);
            });
        }
    }
    t.report();
}

TEST_CASE("sphere: contains is true strictly inside and false on the surface and outside", "[02][sphere][contains]") {
    tally t("contains()");
    sampler random(209);
    for (const ball& b : {ball{point(0.5, -1.25, 2), 0.75}, ball{point(1e5, 2e5, -3e5), 1e-3}, ball{point(0, 0, 0), 1e4}}) {
        const auto s = make_sphere(b.center, b.radius);
        const auto expect = [&](const point& p, bool want) {
            const bool got = s->contains(p);
            t.check(got == want, [&] {
                return "contains(" + show(p) + ") of " + describe(b) + " should be " + (want ? "true" : "false") + "; yours is " +
                       (got ? "true" : "false");
            });
        };
        expect(b.center, true);
        for (int k = 0; k < 50; ++k) {
            expect(inside(random, b, 0.999), true);
            expect(b.center + b.radius * random.uniform(1.001, 10) * random.direction(), false);
        }
    }
    // Points exactly on the surface (every number here is exact in binary): not inside.
    const auto s = make_sphere(point(0.5, -1.25, 2), 0.75);
    for (const point& p : {point(1.25, -1.25, 2), point(0.5, -0.5, 2), point(0.5, -1.25, 1.25), point(-0.25, -1.25, 2)}) {
        const bool got = s->contains(p);
        t.check(!got, [&] {
            return "contains(" + show(p) + ") of the sphere around (0.5, -1.25, 2) of radius 0.75 should be false (the point is "
                   "on the surface, not strictly inside); yours is true";
        });
    }
    t.report();
}

TEST_CASE("sphere: the box is the centre minus and plus the radius in every axis", "[02][sphere][bounds]") {
    tally t("bounds");
    for (const ball& b : {ball{point(1, 2, 3), 0.5}, ball{point(-7.25, 1e3, -0.125), 3.75}, ball{point(1e5, -2e5, 3e-3), 1e-3},
                          ball{point(0, 0, 0), 1e6}}) {
        const auto s = make_sphere(b.center, b.radius);
        const point lo = s->min_point(), hi = s->max_point();
        const double want_lo[3] = {b.center.x - b.radius, b.center.y - b.radius, b.center.z - b.radius};
        const double want_hi[3] = {b.center.x + b.radius, b.center.y + b.radius, b.center.z + b.radius};
        const double got_lo[3] = {lo.x, lo.y, lo.z}, got_hi[3] = {hi.x, hi.y, hi.z};
        bool ok = true;
        for (int a = 0; a < 3; ++a) ok = ok && within_ulps(got_lo[a], want_lo[a], 2) && within_ulps(got_hi[a], want_hi[a], 2);
        t.check(ok, [&] {
            return "the box of " + describe(b) + " should run from (" + num(want_lo[0]) + ", " + num(want_lo[1]) + ", " +
                   num(want_lo[2]) + ") to (" + num(want_hi[0]) + ", " + num(want_hi[1]) + ", " + num(want_hi[2]) +
                   ") (± 2 ulps); yours runs from " + show(lo) + " to " + show(hi);
        });
    }
    t.report();
}

// --- the factory and scene files ----------------------------------------------------------

TEST_CASE("sphere: make_sphere refuses a radius that is zero - negative - NaN or infinite and a centre that is not finite", "[02][sphere][refusals]") {
    const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
    tally t("make_sphere with input that is not a sphere");
    for (const double radius : {0.0, -0.0, -1.0, -1e-300, nan, inf, -inf})
        expect_usage_error(t, "make_sphere((0, 0, 0), " + num(radius) + ")", [&] { return make_sphere(point(0, 0, 0), radius); });
    for (const point& c : {point(nan, 0, 0), point(0, inf, 0), point(0, 0, -inf), point(1, 2, 3, 0)})
        expect_usage_error(t, "make_sphere(point(" + num(c.x) + ", " + num(c.y) + ", " + num(c.z) + ", " + num(c.w) + "), 1)",
                           [&] { return make_sphere(c, 1); });
    // Small and large spheres are spheres: they are made and hit.
    for (const ball& b : {ball{point(1, 1, 1), 1e-3}, ball{point(0, 0, 0), 1e4}}) {
        const auto s = make_sphere(b.center, b.radius);
        check_ray(t, *s, b, ray_through(b.center + vector(0, 0, 3 * b.radius), b.center));
    }
    t.report();
}

TEST_CASE("sphere: a SPHERE in a scene file is the sphere its centre - radius and surface keys describe", "[02][sphere][scene_io]") {
    tally t("SPHERE read from a scene file");
    const ball b{point(0.1 + 1e-13, -1.0 / 3, 7.25), 2.0 / 3};
    const vl::surface surf = full_precision_surface(-1e-7 / 3);
    const std::string text = "SPHERE { radius " + num(b.radius) + " center (" + num(b.center.x) + ", " + num(b.center.y) + ", " +
                             num(b.center.z) + ")" + surface_text(surf) + " }";
    const auto want = make_sphere(b.center, b.radius);
    check_read_as(t, text, "SPHERE", *want, surf,
                  [&](const rtab_component& got, const std::string& what) { check_same_sphere(t, got, *want, b, what); });
    t.report();
}

TEST_CASE("sphere: a bad SPHERE in a scene file is refused at the value at fault - a good one is read", "[02][sphere][scene_io][detail]") {
    tally t("SPHERE blocks in scene files");
    check_refused(t, {{"SPHERE { radius 0 }", "hidden.ray_trace:1:17"},
                      {"SPHERE {\n  center 0 0 0\n  radius -2.5\n}", "hidden.ray_trace:3:10"},
                      {"SPHERE { center (1, 2, 3, 0) radius 1 }", "hidden.ray_trace:1:17"}});
    const auto good = read_one("SPHERE { center 0 0 -10 radius 2 }");
    const auto want = make_sphere(point(0, 0, -10), 2);
    check_same_sphere(t, *good, *want, {point(0, 0, -10), 2}, "SPHERE { center 0 0 -10 radius 2 }");
    t.report();
}

TEST_CASE("sphere: an empty SPHERE block is the unit sphere at the origin with the default surface", "[02][sphere][scene_io][detail]") {
    tally t("SPHERE { }");
    const auto got = read_one("SPHERE { }");
    const auto want = make_sphere(point(0, 0, 0), 1);
    compare_surface(surface_of(*got), vl::surface{}, "SPHERE { }", t);
    check_same_sphere(t, *got, *want, {point(0, 0, 0), 1}, "SPHERE { }");
    t.report();
}

TEST_CASE("sphere: write() keeps every digit of the centre - the radius and each surface key", "[02][sphere][scene_io]") {
    tally t("write() of a SPHERE read back");
    for (const ball& b : {ball{point(0.1 + 1e-13, -1.0 / 3, 2.0 / 3 + 1e-12), 1.0 / 3 + 1e-14},
                          ball{point(123456.789012345, 1e-7, -1.0 / 7), 2.5e-7 / 3}}) {
        const auto original = make_sphere(b.center, b.radius);
        original->set_surface(full_precision_surface(-1e-9 / 3));
        check_write_reads_back(
            t, *original, "SPHERE", describe(b),
            [&](const written_object& w, const std::string& who) {
                const std::vector<double> c = w.keys.at("center");
                const double want_c[3] = {b.center.x, b.center.y, b.center.z};
                for (int a = 0; a < 3; ++a)
                    t.check(within_ulps(c[static_cast<std::size_t>(a)], want_c[a], 4), [&] {
                        return who + " has centre " + std::string(1, "xyz"[a]) + " = " + num(c[static_cast<std::size_t>(a)]) +
                               "; it should be " + num(want_c[a]) + " (± 4 ulps)";
                    });
                const double r = w.keys.at("radius")[0];
                t.check(within_ulps(r, b.radius, 4),
                        [&] { return who + " has radius " + num(r) + "; it should be " + num(b.radius) + " (± 4 ulps)"; });
            },
            [&](const rtab_component& back, const std::string& what) { check_same_sphere(t, back, *original, b, what); });
    }
    t.report();
}

// --- stability sweeps ------------------------------------------------------------------------
// Each sweep reports, per value of its parameter, how many of its rays got a wrong answer
// (rubric.toml's [[sweep]] says where none may). The rays never depend on your answers,
// so every submission is asked the same questions. An exception counts as a wrong answer.

namespace {

/// check_ray, with an exception from the sphere counted as a wrong answer.
void sweep_ray(tally& t, const primitive& s, const ball& b, const ray& r, double extra_tolerance = 0) {
    try {
        check_ray(t, s, b, r, extra_tolerance);
    } catch (const std::exception& e) {
        t.check(false, [&] { return show(r) + " at " + describe(b) + ": intersect() threw: " + e.what(); });
    } catch (...) {
        t.check(false, [&] { return show(r) + " at " + describe(b) + ": intersect() threw"; });
    }
}

/// Makes the sphere; when make_sphere throws, every ray of the trial is a failure.
std::unique_ptr<primitive> try_make(tally& t, const ball& b, int rays) {
    try {
        return make_sphere(b.center, b.radius);
    } catch (...) {
        for (int k = 0; k < rays; ++k) t.check(false, [&] { return "make_sphere threw for " + describe(b); });
        return nullptr;
    }
}

}  // namespace

TEST_CASE("sweep: sphere: hits on spheres 1 to 1e9 radii away", "[02][sweep]") {
    // x = the distance from the eye to the sphere's near side, in radii. The textbook
    // discriminant b^2 - c subtracts two numbers of size (x r)^2 to find one of size r^2:
    // it keeps about 16 - 2 log10(x) digits, none at x = 1e8 (Ray Tracing Gems, chapter 7).
    // The hit must keep 12 digits (the tolerance of the other sphere tests).
    sampler random(208);
    for (int e10 = 0; e10 <= 9; ++e10) {
        const double x = std::pow(10.0, e10);
        tally t("rays at spheres " + num(x) + " radii away");
        for (int sphere = 0; sphere < 6; ++sphere) {
            const double radius = std::pow(10.0, random.uniform(-2, 2));
            const point eye = random.in_cube(10);
            const vector towards = random.direction();
            const ball b{eye + (1 + x) * radius * towards, radius};
            const int rays = 20;
            const auto s = try_make(t, b, rays);
            if (!s) continue;
            vector u, v;
            plane_axes(towards, u, v);
            for (int k = 0; k < rays; ++k) {
                const double turn = random.uniform(0, 2 * std::numbers::pi);
                const vector side = std::cos(turn) * u + std::sin(turn) * v;
                // Inside the disc, near its rim, and just outside it.
                const double offset = k % 3 == 0   ? random.uniform(0, 0.99)
                                      : k % 3 == 1 ? random.uniform(0.99, 0.9999)
                                                   : random.uniform(1.0001, 1.01);
                sweep_ray(t, *s, b, ray_through(eye, b.center + offset * b.radius * side));
            }
        }
        t.report_sweep_point(x);
    }
}

TEST_CASE("sweep: sphere: grazing rays from 1e-15 to 0.1 radii inside and outside the silhouette", "[02][sweep]") {
    // x = how far the ray passes inside (it must hit) or outside (it must miss) the
    // silhouette, in radii, for spheres about ten radii away. What is measured is the
    // decision, hit or miss: a hit must be near the tangent point (within 1e-6 of the
    // distances involved), not to twelve digits, since near the silhouette the distance
    // itself is ill-conditioned (the far-sphere sweep measures the digits).
    sampler random(209);
    for (int e10 = -15; e10 <= -1; ++e10) {
        const double margin = std::pow(10.0, e10);
        tally t("grazing rays " + num(margin) + " radii from the silhouette");
        for (const ball& b : {ball{point(0, 0, -10), 2}, ball{point(3.3, -1.7, 12.9), 0.6}, ball{point(-25, 4, 7.5), 0.9}}) {
            const int rays = 20;
            const auto s = try_make(t, b, rays);
            if (!s) continue;
            for (int k = 0; k < rays / 2; ++k) {
                const vector d = random.direction();
                vector u, v;
                plane_axes(d, u, v);
                const double turn = random.uniform(0, 2 * std::numbers::pi);
                const vector side = std::cos(turn) * u + std::sin(turn) * v;
                for (const double offset : {1 - margin, 1 + margin}) {
                    const ray r(b.center + offset * b.radius * side - 10 * b.radius * d, d);
                    const sphere_key roots = sphere_oracle(b.center, b.radius, r);
                    const double want = expected_t(roots, s->zero_t());
                    const double tol = 1e-6 * static_cast<double>(roots.scale);
                    intersection i;
                    std::string threw;
                    try {
                        i = s->intersect(r);
                    } catch (const std::exception& e) {
                        threw = std::string("intersect() threw: ") + e.what();
                    } catch (...) {
                        threw = "intersect() threw";
                    }
                    const std::string where = " (it passes " + num(margin) + " radii " +
                                              (offset < 1 ? "inside" : "outside") + " the silhouette)";
                    if (want > 0)
                        t.check(threw.empty() && hit_near(i, s.get(), want, tol), [&] {
                            return show(r) + " should hit " + describe(b) + " near t = " + num(want) + " ± " + num(tol) +
                                   where + "; yours " + (threw.empty() ? "returned " + show(i, s.get()) : threw);
                        });
                    else
                        t.check(threw.empty() && clean_miss(i), [&] {
                            return show(r) + " should miss " + describe(b) + where + "; yours " +
                                   (threw.empty() ? "returned " + show(i, s.get()) : threw);
                        });
                }
            }
        }
        t.report_sweep_point(margin);
    }
}
