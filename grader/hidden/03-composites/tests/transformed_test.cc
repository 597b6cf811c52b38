// Hidden tests of stage 03's transformed instance (transformed.cc). Each TEST_CASE is one
// graded item; the tag [transformed] puts it in the rubric's "transformed" category. The
// child is a probe (hidden_support.hh) that computes its own hits in long double and counts
// its own tests; every expected answer comes from the long-double matrices and formulas
// below (the world-space ellipsoid of a transformed sphere), never from stage 01's code.
#include "vl/catch.hh"

#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "hidden_support.hh"

using vl::intersection;
using vl::matrix;
using vl::point;
using vl::ray;
using vl::rtab_component;
using vl::rtab_composite;
using vl::vector;
using vl::stage03::make_transformed;
using namespace vl::stage03::hidden;

namespace {

struct placed {
    std::string what;  ///< the matrix in words
    rmat m;            ///< object to world (the double matrix handed over, exactly)
};

placed make_case(std::string what, const rmat& m) {
    const matrix d = to_matrix(m);
    return {std::move(what) + " " + show(d), rmat::of(d)};
}

const std::vector<placed>& cases() {
    static const std::vector<placed> all = {
        make_case("translate (1, -2, -6)", r_translate(1, -2, -6)),
        make_case("uniform scale 2.5, then translate (0, 0, -4)", r_translate(0, 0, -4) * r_scale(2.5, 2.5, 2.5)),
        make_case("scale (3, 0.5, 1.5)", r_scale(3, 0.5, 1.5)),
        make_case("rotate 40 degrees about (1, 2, 3)", r_rotate(1, 2, 3, 40)),
        make_case("scale (0.25, 2, 1), rotate 70 degrees about (0, 1, 1), translate (2, 1, -3)",
                  r_translate(2, 1, -3) * r_rotate(0, 1, 1, 70) * r_scale(0.25, 2, 1)),
        make_case("a shear", [] {
            rmat m = r_identity();
            m.e[0][1] = 0.5;
            m.e[1][2] = -0.3;
            m.e[2][0] = 0.2;
            m.e[0][3] = -1;
            return m;
        }()),
        make_case("mirror x, scale z by 4", r_scale(-1, 1, 4)),
        make_case("scale 1e-3 then 1e3 apart", r_translate(500, 0, 0) * r_scale(1e-3, 2e-3, 1e-3)),
    };
    return all;
}

/// The world-space hit of a ray with the sphere (c, r) seen through `m`: the world
/// distance s (0 for none, hits within the child's zero_t in object space excluded),
/// and the object-space point and normal.
struct world_hit {
    real s = 0;
    rvec object_point, world_normal;
    real scale = 0;  ///< what a double computation's error scales with
};
world_hit ellipsoid_oracle(const rmat& m, const point& c, double radius, const ray& r, real zero_t) {
    const rmat inv = m.inverse();
    const rvec o = inv.apply_point(to_r(r.origin())), d = inv.apply_vector(unit(to_r(r.direction())));
    const rvec f = o - to_r(c);
    const real a = dot(d, d), b = dot(d, f), cc = dot(f, f) - static_cast<real>(radius) * radius;
    world_hit out;
    out.scale = len(to_r(r.origin())) + len(m.apply_point(to_r(c))) + radius * std::sqrt(1 / a) * 4 + 1;
    const real disc = b * b - a * cc;
    if (disc < 0) return out;
    const real root = std::sqrt(disc);
    const real q = -(b + std::copysign(root, b));
    real s0 = q / a, s1 = q == 0 ? 0 : cc / q;
    if (s0 > s1) std::swap(s0, s1);
    const real stretch = std::sqrt(a);  // object-space length of one world unit along the ray
    real s = 0;
    if (s0 * stretch > zero_t)
        s = s0;
    else if (s1 * stretch > zero_t)
        s = s1;
    if (s == 0) return out;
    out.s = s;
    out.object_point = o + s * d;
    const rvec n = unit(out.object_point - to_r(c));
    out.world_normal = unit(inv.apply_transposed(n));
    return out;
}

std::string got_words(const intersection& got, const rtab_component* self, const rtab_component* child) {
    if (got.is_miss()) return got.t == 0 ? "a miss" : "t = " + num(got.t) + " with no object";
    const std::string who = got.object == self ? "the TRANSFORM" : got.object == child ? "the child (the object must be the TRANSFORM itself)" : "an object of type " + got.object->type_name();
    if (got.t == 0) return "composite_only of " + who;
    return "a hit at t = " + num(got.t) + " naming " + who;
}

/// Random rays at the world-space ellipsoid of the sphere (c, r) under `m`: from outside
/// through points near it, and from points inside it.
std::vector<ray> rays_at(const rmat& m, const point& c, double radius, dice& random, int count) {
    std::vector<ray> out;
    const rvec centre = m.apply_point(to_r(c));
    // A size for the ellipsoid: the longest image of a radius.
    real size = 0;
    for (const rvec& u : {rvec{1, 0, 0}, rvec{0, 1, 0}, rvec{0, 0, 1}}) size = std::max(size, len(m.apply_vector(static_cast<real>(radius) * u)));
    const double s = static_cast<double>(size);
    for (int k = 0; k < count; ++k) {
        const rvec object_target = to_r(c) + static_cast<real>(radius * random.uniform(0, 1.2)) * to_r(random.direction());
        const point target = to_point(m.apply_point(object_target));
        if (k % 4 == 3) {
            const rvec inside = to_r(c) + static_cast<real>(radius * random.uniform(0, 0.9)) * to_r(random.direction());
            out.push_back(ray(to_point(m.apply_point(inside)), random.direction()));
        } else {
            out.push_back(ray_through(to_point(centre) + s * random.uniform(2, 6) * random.direction(), target));
        }
    }
    return out;
}

}  // namespace

TEST_CASE("transformed: t is the distance along the world ray for every matrix - and the object hit is the TRANSFORM itself", "[03][transformed][hits][essential]") {
    tally t("rays at transformed spheres");
    dice random(400);
    const point c(0.25, -0.5, 0.75);
    const double radius = 0.8;
    for (const placed& p : cases()) {
        auto child = std::make_unique<probe_sphere>(c, radius);
        const rtab_component* probe = child.get();
        const auto tr = make_transformed(std::move(child), to_matrix(p.m));
        for (const ray& r : rays_at(p.m, c, radius, random, 200)) {
            const world_hit want = ellipsoid_oracle(p.m, c, radius, r, 1e-6L);
            const intersection got = tr->intersect(r);
            const double tol = static_cast<double>(1e-11L * want.scale);
            const bool ok = want.s > 0 ? got.hit() && got.object == tr.get() && std::fabs(got.t - static_cast<double>(want.s)) <= tol
                                       : got.is_miss() && got.t == 0;
            t.check(ok, [&] {
                return show(r) + " at the sphere around " + show(c) + " of radius " + num(radius) + " seen through " + p.what +
                       ": it should " +
                       (want.s > 0 ? "hit the TRANSFORM at the world distance t = " + num(static_cast<double>(want.s)) + " ± " + num(tol)
                                   : std::string("miss")) +
                       "; yours returned " + got_words(got, tr.get(), probe);
            });
        }
    }
    t.report();
}

TEST_CASE("transformed: the normal is the child's normal taken to world space with the inverse transpose - made unit", "[03][transformed][normals][essential]") {
    tally t("normals of transformed spheres");
    dice random(410);
    const point c(0, 0.5, -0.25);
    const double radius = 1.1;
    for (const placed& p : cases()) {
        for (const bool nested : {false, true}) {
            // Nested: the same matrix as a TRANSFORM of a TRANSFORM (outer: a rotation).
            const rmat outer = r_rotate(0.3, -1, 0.2, 25);
            const rmat whole = nested ? rmat::of(to_matrix(outer)) * p.m : p.m;
            std::unique_ptr<rtab_composite> tr = make_transformed(std::make_unique<probe_sphere>(c, radius), to_matrix(p.m));
            if (nested) tr = make_transformed(std::move(tr), to_matrix(outer));
            for (const ray& r : rays_at(whole, c, radius, random, 60)) {
                const world_hit want = ellipsoid_oracle(whole, c, radius, r, 1e-6L);
                const intersection got = tr->intersect(r);
                if (want.s == 0 || !got.hit() || got.object == nullptr) continue;  // the hit tests judge that
                const point at = r.t_point(got.t);
                const vector n = got.object->normal(at);
                const rvec w = want.world_normal;
                const double gap = static_cast<double>(std::max({std::fabs(n.x - w.x), std::fabs(n.y - w.y), std::fabs(n.z - w.z)}));
                t.check(gap <= 1e-8 && n.w == 0, [&] {
                    return "where " + show(r) + " hits the sphere around " + show(c) + " of radius " + num(radius) + " seen through " +
                           (nested ? "a rotation of " : "") + p.what + ", at " + show(at) + ", the normal should be the vector " +
                           show(w) + " ± 1e-8 ((M^-1)^T n, made unit, with w = 0); yours is " + show(n) + " with w = " + num(n.w);
                });
            }
        }
    }
    t.report();
}

TEST_CASE("transformed: each ray intersects the child exactly once - and a child's composite_only comes back as composite_only of the TRANSFORM", "[03][transformed][rules][essential]") {
    tally t("the child's tests and the rules");
    dice random(420);
    for (const placed& p : cases()) {
        auto child = std::make_unique<probe_sphere>(point(0, 0, 0), 1);
        const probe* pr = child.get();
        const auto tr = make_transformed(std::move(child), to_matrix(p.m));
        for (const ray& r : rays_at(p.m, point(0, 0, 0), 1, random, 80)) {
            const std::uint64_t before = pr->tests();
            const cost c = measure([&] { tr->intersect(r); });
            const std::uint64_t own = pr->tests() - before;
            t.check(own == 1 && c.probe == 1 && c.counts.primitive_tests == 1, [&] {
                return show(r) + " at a TRANSFORM (" + p.what + ") of a sphere should intersect the child exactly once, through "
                       "its intersect(); the child counted " + std::to_string(own) + " tests and vl::counts() " +
                       std::to_string(c.counts.primitive_tests);
            });
        }
        // A child that answers composite_only of itself, and one that answers a miss.
        auto hollow = std::make_unique<probe_hollow>(point(-1, -1, -1), point(1, 1, 1));
        const rtab_component* h = hollow.get();
        const auto th = make_transformed(std::move(hollow), to_matrix(p.m));
        // Rays made in object space and taken to world space.
        const ray in(to_point(p.m.apply_point({0.1, 0.2, 5})), to_vector(p.m.apply_vector({0, 0, -1})));
        const intersection got = th->intersect(in);
        t.check(got.is_composite_only() && got.object == th.get(), [&] {
            return show(in) + " passes through the box of a child that answers composite_only of itself, seen through " + p.what +
                   ": the TRANSFORM should return composite_only of the TRANSFORM; yours returned " + got_words(got, th.get(), h);
        });
        const ray away(to_point(p.m.apply_point({0, 0, 5})), to_vector(p.m.apply_vector({0, 0, 1})));
        const intersection g2 = th->intersect(away);
        t.check(g2.is_miss() && g2.t == 0, [&] {
            return show(away) + " points away from the child seen through " + p.what + ": it should miss; yours returned " +
                   got_words(g2, th.get(), h);
        });
    }
    t.report();
}

TEST_CASE("transformed: contains() asks the child about the object-space point", "[03][transformed][contains]") {
    tally t("contains() of transformed spheres");
    dice random(430);
    const point c(0.5, 0, 0);
    for (const placed& p : cases()) {
        const auto tr = make_transformed(std::make_unique<probe_sphere>(c, 1), to_matrix(p.m));
        for (int k = 0; k < 60; ++k) {
            const double f = random.uniform(0, 2);
            if (std::fabs(f - 1) < 0.02) continue;
            const rvec object_point = to_r(c) + static_cast<real>(f) * to_r(random.direction());
            const point world = to_point(p.m.apply_point(object_point));
            const bool want = f < 1, got = tr->contains(world);
            t.check(got == want, [&] {
                return "contains(" + show(world) + ") of the unit sphere around " + show(c) + " seen through " + p.what + " should be " +
                       (want ? "true" : "false") + " (the point is " + (want ? "inside" : "outside") + " the ellipsoid); yours is " +
                       (got ? "true" : "false");
            });
        }
    }
    t.report();
}

TEST_CASE("transformed: min_point() and max_point() are the box around the child's eight corners taken to world space", "[03][transformed][bounds]") {
    tally t("boxes of transformed objects");
    const point lo(-0.5, 0.25, -2), hi(1.5, 1, -1.25);
    for (const placed& p : cases()) {
        const auto tr = make_transformed(std::make_unique<probe_cuboid>(lo, hi), to_matrix(p.m));
        rvec wlo{1e300L, 1e300L, 1e300L}, whi{-1e300L, -1e300L, -1e300L};
        for (int i = 0; i < 8; ++i) {
            const rvec q = p.m.apply_point({i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z});
            wlo = {std::min(wlo.x, q.x), std::min(wlo.y, q.y), std::min(wlo.z, q.z)};
            whi = {std::max(whi.x, q.x), std::max(whi.y, q.y), std::max(whi.z, q.z)};
        }
        const real tol = 1e-12L * (len(wlo) + len(whi) + 1);
        const std::string who = "the box from " + show(lo) + " to " + show(hi) + " seen through " + p.what;
        check_point(t, "min_point() of " + who, tr->min_point(), wlo, tol);
        check_point(t, "max_point() of " + who, tr->max_point(), whi, tol);
    }
    const auto unbounded = make_transformed(std::make_unique<probe_boxless>(vl::NaN_point, vl::NaN_point), to_matrix(r_scale(2, 2, 2)));
    t.check(unknown(unbounded->min_point()) && unknown(unbounded->max_point()), [&] {
        return "a TRANSFORM of a child whose box is unknown should have an unknown box (NaN_point); yours runs from " +
               show(unbounded->min_point()) + " to " + show(unbounded->max_point());
    });
    const auto empty = make_transformed(nullptr, to_matrix(r_scale(2, 2, 2)));
    t.check(unknown(empty->min_point()) && unknown(empty->max_point()), [&] {
        return "a TRANSFORM without a child should have an unknown box (NaN_point); yours runs from " + show(empty->min_point()) +
               " to " + show(empty->max_point());
    });
    t.report();
}

TEST_CASE("transformed: the surface members are the child's - and a hit on the TRANSFORM shows them", "[03][transformed][surface]") {
    tally t("the surface of a TRANSFORM");
    const vl::surface surf = full_precision_surface(-1e-7 / 3);
    auto child = std::make_unique<probe_sphere>(point(0, 0, 0), 1);
    child->set_surface(surf);
    const auto tr = make_transformed(std::move(child), to_matrix(r_translate(0, 0, -5) * r_scale(1, 2, 3)));
    compare_surface(surface_of(*tr), surf, "the TRANSFORM of a sphere with every surface key set", t);
    const ray r(point(0, 0, 0), vector(0, 0, -1));
    const intersection got = tr->intersect(r);
    t.check(got.hit() && got.object == tr.get() && std::fabs(got.t - 2) < 1e-12, [&] {
        return show(r) + " should hit the TRANSFORM (the sphere scaled (1, 2, 3) and moved to z = -5) at t = 2; yours returned " +
               got_words(got, tr.get(), nullptr);
    });
    if (got.hit() && got.object != nullptr) compare_surface(surface_of(*got.object), surf, "the object the ray hit", t);
    t.report();
}

TEST_CASE("transformed: a TRANSFORM without a child misses every ray - insert() gives it its one child and refuses a second", "[03][transformed][insert]") {
    tally t("TRANSFORM and insert()");
    auto tr = make_transformed(nullptr, to_matrix(r_translate(0, 0, -5)));
    const ray r(point(0, 0, 0), vector(0, 0, -1));
    const intersection empty = tr->intersect(r);
    t.check(empty.is_miss() && empty.t == 0, [&] { return "a TRANSFORM without a child should miss " + show(r) + "; yours returned " + got_words(empty, tr.get(), nullptr); });
    auto child = std::make_unique<probe_sphere>(point(0, 0, 0), 1);
    const rtab_component* pc = child.get();
    tr->insert(std::move(child));
    const intersection got = tr->intersect(r);
    t.check(got.hit() && got.object == tr.get() && std::fabs(got.t - 4) < 1e-12, [&] {
        return "after insert() of the unit sphere into a TRANSFORM that moves it to z = -5, " + show(r) +
               " should hit the TRANSFORM at t = 4; yours returned " + got_words(got, tr.get(), pc);
    });
    std::string message;
    t.check(throws_usage_error([&] { tr->insert(std::make_unique<probe_sphere>(point(3, 0, 0), 1)); }, message),
            [&] { return "a second insert() into a TRANSFORM should throw vl::usage_error (it holds one object); " + message; });
    const intersection again = tr->intersect(r);
    t.check(again.hit() && std::fabs(again.t - 4) < 1e-12, [&] { return "after the refused insert(), " + show(r) + " should still hit at t = 4; yours returned " + got_words(again, tr.get(), pc); });
    t.report();
}

TEST_CASE("transformed: make_transformed() refuses a matrix that is singular - not affine or not finite", "[03][transformed][refusals][detail]") {
    tally t("matrices that cannot place an object");
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    const matrix bad[] = {to_matrix(r_scale(0, 1, 1)),
                          matrix(1, 2, 3, 0, 2, 4, 6, 0, 0, 0, 1, 0, 0, 0, 0, 1),
                          matrix(1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 1, 1),
                          matrix(2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 2),
                          matrix(1, 0, 0, nan, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1),
                          matrix(1, 0, 0, 0, 0, inf, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1)};
    for (const matrix& m : bad) {
        std::string message;
        t.check(throws_usage_error([&] { make_transformed(std::make_unique<probe_sphere>(point(0, 0, 0), 1), m); }, message),
                [&] { return "make_transformed(a sphere, " + show(m) + ") should throw vl::usage_error; " + message; });
    }
    const auto fine = make_transformed(std::make_unique<probe_sphere>(point(0, 0, 0), 1), to_matrix(r_scale(1e-3, 1, 1)));
    const ray r(point(0, 0, 5), vector(0, 0, -1));
    const intersection got = fine->intersect(r);
    t.check(got.hit() && std::fabs(got.t - 4) < 1e-12, [&] {
        return "a TRANSFORM that squashes the unit sphere to a thickness of 1e-3 in x is fine: " + show(r) +
               " should hit it at t = 4; yours returned " + got_words(got, fine.get(), nullptr);
    });
    t.report();
}

// --- scene files ------------------------------------------------------------------------------

namespace {
struct step_case {
    std::string text;
    rmat m;
    point c;
    double radius;
};
}  // namespace

TEST_CASE("transformed: the steps of a TRANSFORM apply in the order written - rotate turns right-handed in degrees - matrix reads 16 numbers row by row", "[03][transformed][scene_io][essential]") {
    tally t("TRANSFORM steps in scene files");
    rmat shear = r_identity();
    shear.e[0][2] = 0.5;
    shear.e[1][3] = -2;
    const step_case steps[] = {
        {"TRANSFORM { scale 2 3 4  translate 1 0 -5  PROBE { } }", r_translate(1, 0, -5) * r_scale(2, 3, 4), point(0, 0, 0), 1},
        {"TRANSFORM { translate 1 0 -5  scale 2 3 4  PROBE { } }", r_scale(2, 3, 4) * r_translate(1, 0, -5), point(0, 0, 0), 1},
        {"TRANSFORM { rotate 0 0 1 90  PROBE { center 2 0 0 radius 0.5 } }", r_rotate(0, 0, 1, 90), point(2, 0, 0), 0.5},
        {"TRANSFORM { rotate 0 0 1 90  translate 3 0 0  PROBE { center 2 0 0 radius 0.5 } }",
         r_translate(3, 0, 0) * r_rotate(0, 0, 1, 90), point(2, 0, 0), 0.5},
        {"TRANSFORM { matrix 1 0 0.5 0  0 1 0 -2  0 0 1 0  0 0 0 1  PROBE { center 0 1 0 } }", shear, point(0, 1, 0), 1},
        {"TRANSFORM { rotate 1 1 0 30  scale 1 2 1  rotate 0 1 0 -45  translate 0.5 0.25 -3  PROBE { radius 0.75 } }",
         r_translate(0.5, 0.25, -3) * r_rotate(0, 1, 0, -45) * r_scale(1, 2, 1) * r_rotate(1, 1, 0, 30), point(0, 0, 0), 0.75},
    };
    dice random(440);
    for (const step_case& s : steps) {
        const auto object = read_one(s.text);
        for (const ray& r : rays_at(s.m, s.c, s.radius, random, 60)) {
            const world_hit want = ellipsoid_oracle(s.m, s.c, s.radius, r, 1e-6L);
            const intersection got = object->intersect(r);
            const double tol = static_cast<double>(1e-9L * want.scale);
            const bool ok = want.s > 0 ? got.hit() && got.object == object.get() && std::fabs(got.t - static_cast<double>(want.s)) <= tol
                                       : !got.hit();
            t.check(ok, [&] {
                return show(r) + " at " + s.text + " (object_to_world " + show(to_matrix(s.m)) + "): it should " +
                       (want.s > 0 ? "hit at t = " + num(static_cast<double>(want.s)) + " ± " + num(tol) : std::string("miss")) +
                       "; yours returned " + got_words(got, object.get(), nullptr);
            });
        }
        // The box: the child's box's eight corners through the same matrix.
        rvec wlo{1e300L, 1e300L, 1e300L}, whi{-1e300L, -1e300L, -1e300L};
        for (int i = 0; i < 8; ++i) {
            const rvec q = s.m.apply_point({s.c.x + (i & 1 ? s.radius : -s.radius), s.c.y + (i & 2 ? s.radius : -s.radius),
                                            s.c.z + (i & 4 ? s.radius : -s.radius)});
            wlo = {std::min(wlo.x, q.x), std::min(wlo.y, q.y), std::min(wlo.z, q.z)};
            whi = {std::max(whi.x, q.x), std::max(whi.y, q.y), std::max(whi.z, q.z)};
        }
        check_point(t, "min_point() of " + s.text, object->min_point(), wlo, 1e-9L);
        check_point(t, "max_point() of " + s.text, object->max_point(), whi, 1e-9L);
    }
    t.report();
}

TEST_CASE("transformed: write() gives TRANSFORM { matrix M11 ... M44 CHILD } - which reads back as the same object", "[03][transformed][scene_io]") {
    tally t("TRANSFORM written and read back");
    dice random(450);
    for (const placed& p : cases()) {
        auto child = std::make_unique<probe_sphere>(point(0.5, -0.25, 0.125), 0.625);
        child->id = 7;
        const auto tr = make_transformed(std::move(child), to_matrix(p.m));
        const std::string text = text_of(*tr);
        const std::vector<double> m = numbers_after(text, "matrix", 16);
        bool same = m.size() == 16 && text.rfind("TRANSFORM", 0) == 0 && text.find("PROBE") != std::string::npos;
        for (std::size_t k = 0; same && k < 16; ++k) same = m[k] == static_cast<double>(p.m.e[k / 4][k % 4]);
        t.check(same, [&] {
            return "write() of the TRANSFORM of a probe through " + p.what + " should be \"TRANSFORM { matrix\" and the 16 "
                   "elements row by row with every digit, then the child; yours wrote \"" + text + "\"";
        });
        const auto back = read_one(text);
        for (const ray& r : rays_at(p.m, point(0.5, -0.25, 0.125), 0.625, random, 40)) {
            const intersection a = tr->intersect(r), b = back->intersect(r);
            const bool ok = (a.hit() && b.hit() && std::fabs(a.t - b.t) <= 1e-12 * std::max(1.0, a.t) && b.object == back.get()) ||
                            (!a.hit() && !b.hit());
            t.check(ok, [&] {
                return show(r) + ": the TRANSFORM read back from \"" + text + "\" returned " + got_words(b, back.get(), nullptr) +
                       " where the one written returned " + got_words(a, tr.get(), nullptr);
            });
        }
    }
    t.report();
}

TEST_CASE("transformed: a bad TRANSFORM in a scene file is refused at the step at fault", "[03][transformed][scene_io][detail]") {
    tally t("bad TRANSFORM blocks");
    check_refused(t, {{"TRANSFORM {\n  scale 1 0 1\n  PROBE { }\n}", "hidden.ray_trace:2:3"},
                      {"TRANSFORM { translate 1 2 3 matrix 1 0 0 0 0 1 0 0 0 0 1 0 0 0 1 1 PROBE { } }", "hidden.ray_trace:1:29"},
                      {"TRANSFORM { rotate 0 0 0 45 PROBE { } }", "hidden.ray_trace:1:13"},
                      {"TRANSFORM { scale 2 2 2 }", "hidden.ray_trace:1:25"},
                      {"TRANSFORM { PROBE { } PROBE { } }", "hidden.ray_trace:1:23"}});
    const auto good = read_one("TRANSFORM { translate 0 0 -5 PROBE { } }");
    const ray r(point(0, 0, 0), vector(0, 0, -1));
    const intersection got = good->intersect(r);
    t.check(got.hit() && std::fabs(got.t - 4) < 1e-12, [&] {
        return "TRANSFORM { translate 0 0 -5 PROBE { } }: " + show(r) + " should hit at t = 4; yours returned " + got_words(got, good.get(), nullptr);
    });
    t.report();
}
