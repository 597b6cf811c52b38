// Hidden tests of stage 03's box (box.cc). Each TEST_CASE is one graded item; the tag
// [box] puts it in the rubric's "box" category. Every expected answer comes from the
// long-double slab computation below, never from another of your objects; the faces
// themselves are stage 02's polygons (the reference's, in grading).
#include "vl/catch.hh"

#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "hidden_support.hh"

using vl::intersection;
using vl::point;
using vl::ray;
using vl::rtab_component;
using vl::rtab_composite;
using vl::vector;
using vl::stage03::make_box;
using namespace vl::stage03::hidden;

namespace {

struct box_shape {
    point lo, hi;
};

std::string describe(const box_shape& b) { return "the BOX from " + show(b.lo) + " to " + show(b.hi); }

/// Where the line of a ray crosses the box, in long double: entry and exit distances and
/// faces (face 2k is the low side of axis k, 2k + 1 the high side).
struct crossing {
    bool meets = false;
    real t0 = 0, t1 = 0;
    int in_face = -1, out_face = -1;
    real in_gap = 0, out_gap = 0;  ///< how far the other candidates' distances are (0: an edge)
};
crossing cross(const box_shape& b, const ray& r) {
    const rvec o = to_r(r.origin()), d = unit(to_r(r.direction()));
    crossing out;
    real t0 = -std::numeric_limits<real>::infinity(), t1 = std::numeric_limits<real>::infinity();
    real near_k[3], far_k[3];
    int near_f[3], far_f[3];
    for (int k = 0; k < 3; ++k) {
        const real ok = axis_of(o, k), dk = axis_of(d, k), a = axis_of(b.lo, k), c = axis_of(b.hi, k);
        if (dk == 0) {
            if (ok <= a || ok >= c) return out;
            near_k[k] = -std::numeric_limits<real>::infinity();
            far_k[k] = std::numeric_limits<real>::infinity();
            near_f[k] = far_f[k] = -1;
            continue;
        }
        real n = (a - ok) / dk, f = (c - ok) / dk;
        int nf = 2 * k, ff = 2 * k + 1;
        if (n > f) {
            std::swap(n, f);
            std::swap(nf, ff);
        }
        near_k[k] = n;
        far_k[k] = f;
        near_f[k] = nf;
        far_f[k] = ff;
        if (n > t0) {
            t0 = n;
            out.in_face = nf;
        }
        if (f < t1) {
            t1 = f;
            out.out_face = ff;
        }
    }
    if (!(t0 < t1)) return out;
    out.meets = true;
    out.t0 = t0;
    out.t1 = t1;
    out.in_gap = out.out_gap = std::numeric_limits<real>::infinity();
    for (int k = 0; k < 3; ++k) {
        if (near_f[k] >= 0 && near_f[k] != out.in_face) out.in_gap = std::min(out.in_gap, t0 - near_k[k]);
        if (far_f[k] >= 0 && far_f[k] != out.out_face) out.out_gap = std::min(out.out_gap, far_k[k] - t1);
    }
    return out;
}

vector outward(int face) {
    const double s = face % 2 == 0 ? -1 : 1;
    return face / 2 == 0 ? vector(s, 0, 0) : face / 2 == 1 ? vector(0, s, 0) : vector(0, 0, s);
}
const char* face_name(int face) {
    static const char* names[6] = {"x = min", "x = max", "y = min", "y = max", "z = min", "z = max"};
    return face >= 0 && face < 6 ? names[face] : "(none)";
}

/// Which face of `b` the object `o` is (its box is flat in that face's plane), or -1.
int face_of(const rtab_component* o, const box_shape& b) {
    if (o == nullptr) return -1;
    const point lo = o->min_point(), hi = o->max_point();
    for (int k = 0; k < 3; ++k) {
        if (axis_of(lo, k) != axis_of(hi, k)) continue;
        if (axis_of(lo, k) == axis_of(b.lo, k)) return 2 * k;
        if (axis_of(lo, k) == axis_of(b.hi, k)) return 2 * k + 1;
    }
    return -1;
}

real scale_of(const box_shape& b, const ray& r) {
    return len(to_r(b.hi) - to_r(b.lo)) + len(to_r(r.origin())) + len(to_r(b.lo)) + len(to_r(b.hi));
}

std::string got_words(const intersection& got, const rtab_component* box, const box_shape& b) {
    if (got.is_miss()) return got.t == 0 ? "a miss" : "t = " + num(got.t) + " with no object";
    if (got.object == box) return got.t == 0 ? "composite_only of the BOX" : "a hit at t = " + num(got.t) + " naming the BOX itself (the object must be the face polygon)";
    if (got.t == 0) return "composite_only of an object of type " + got.object->type_name();
    const int f = face_of(got.object, b);
    return "a hit at t = " + num(got.t) + (f >= 0 ? std::string(" on the face ") + face_name(f) : " on an object that is not a face");
}

/// Checks one ray that crosses the box: the face it enters (from outside) or leaves
/// (from inside) at the oracle's distance, with that face's polygon as the object and
/// the outward normal there.
void check_hit(tally& t, const rtab_component& box, const box_shape& b, const ray& r, bool inside) {
    const crossing c = cross(b, r);
    if (!c.meets) return;
    const real want = inside ? c.t1 : c.t0;
    const int face = inside ? c.out_face : c.in_face;
    const real gap = inside ? c.out_gap : c.in_gap;
    const real scale = scale_of(b, r);
    const double tol = static_cast<double>(1e-11L * scale);
    const intersection got = box.intersect(r);
    bool ok = got.hit() && got.object != &box && std::fabs(got.t - static_cast<double>(want)) <= tol;
    const bool clear = gap > 1e-9L * scale;  // not at an edge: the face is known
    int got_face = -1;
    vector n;
    if (ok) {
        got_face = face_of(got.object, b);
        n = got.object->normal(r.t_point(got.t));
        if (clear) ok = got_face == face && std::fabs(n.x - outward(face).x) + std::fabs(n.y - outward(face).y) + std::fabs(n.z - outward(face).z) <= 1e-9;
    }
    t.check(ok, [&] {
        return show(r) + (inside ? " starts inside " : " comes from outside ") + describe(b) + ": it should hit the face " +
               (clear ? face_name(face) : "at that edge") + " at t = " + num(static_cast<double>(want)) + " ± " + num(tol) +
               (clear ? ", that face's polygon being the object, with the outward normal " + show(outward(face)) : std::string()) +
               "; yours returned " + got_words(got, &box, b) +
               (got.hit() && got.object != &box && clear ? " whose normal there is " + show(n) : std::string());
    });
}

const box_shape boxes[] = {{point(0, 0, 0), point(1, 1, 1)},
                           {point(-1, -2, -3), point(2, 0.5, -1)},
                           {point(10, 20, 30), point(10.25, 20.5, 31)},
                           {point(-1e3, -5, -1e3), point(1e3, 5, 1e3)},
                           {point(0.125, -0.375, 4), point(0.5, 0.625, 4.0625)}};

point inside_point(dice& random, const box_shape& b, double margin) {
    const auto pick = [&](double lo, double hi) { return lo + (hi - lo) * random.uniform(margin, 1 - margin); };
    return point(pick(b.lo.x, b.hi.x), pick(b.lo.y, b.hi.y), pick(b.lo.z, b.hi.z));
}

point centre_of(const box_shape& b) { return point((b.lo.x + b.hi.x) / 2, (b.lo.y + b.hi.y) / 2, (b.lo.z + b.hi.z) / 2); }
double size_of(const box_shape& b) { return (b.hi - b.lo).length(); }

}  // namespace

TEST_CASE("box: rays from outside hit the face they enter at the right distance - that face being the object with an outward normal", "[03][box][hits][essential]") {
    tally t("rays at boxes from outside");
    dice random(200);
    for (const box_shape& b : boxes) {
        const auto box = make_box(b.lo, b.hi);
        for (int k = 0; k < 300; ++k) {
            const point from = centre_of(b) + size_of(b) * random.uniform(0.8, 5) * random.direction();
            check_hit(t, *box, b, ray_through(from, inside_point(random, b, 0.001)), false);
        }
        // Straight at each face along its normal, and from each side along the axes.
        for (int f = 0; f < 6; ++f) {
            const point c = centre_of(b);
            check_hit(t, *box, b, ray(c + size_of(b) * 2 * outward(f), -outward(f)), false);
        }
    }
    t.report();
}

TEST_CASE("box: rays from inside hit the face they leave through - and rays from a face go on to the far side", "[03][box][inside][essential]") {
    tally t("rays at boxes from inside");
    dice random(210);
    for (const box_shape& b : boxes) {
        const auto box = make_box(b.lo, b.hi);
        for (int k = 0; k < 300; ++k) check_hit(t, *box, b, ray(inside_point(random, b, 0.001), random.direction()), true);
        check_hit(t, *box, b, ray(centre_of(b), vector(0, 0, 1)), true);
        check_hit(t, *box, b, ray(centre_of(b), vector(-1, 0, 0)), true);
        // From a point of a face: into the box, the far side; out of it, nothing.
        for (int f = 0; f < 6; ++f) {
            point on = centre_of(b);
            const int axis = f / 2;
            (axis == 0 ? on.x : axis == 1 ? on.y : on.z) = axis_of(f % 2 == 0 ? b.lo : b.hi, axis);
            vector in = random.direction();
            if (in * outward(f) > -0.2) in = in - (in * outward(f) + 0.7) * outward(f);
            check_hit(t, *box, b, ray(on, in), true);
            vector away = random.direction();
            if (away * outward(f) < 0.2) away = away + (0.7 - away * outward(f)) * outward(f);
            const ray leaving(on, away);
            const intersection got = box->intersect(leaving);
            t.check(!got.hit(), [&] {
                return show(leaving) + " leaves " + describe(b) + " from a point of its face " + face_name(f) +
                       ": it should hit nothing; yours returned " + got_words(got, box.get(), b);
            });
        }
    }
    t.report();
}

TEST_CASE("box: a ray that misses costs one box test and no face test - one that enters tests each face at most once", "[03][box][budget][essential]") {
    tally t("the cost of rays at boxes");
    dice random(220);
    for (const box_shape& b : boxes) {
        const auto box = make_box(b.lo, b.hi);
        for (int k = 0; k < 200; ++k) {
            const point from = centre_of(b) + size_of(b) * random.uniform(0.8, 5) * random.direction();
            // Half aimed inside, half at points beside the box.
            point target = inside_point(random, b, 0.01);
            if (k % 2 == 1) {
                const int axis = random.below(3);
                const double lo = axis_of(b.lo, axis), hi = axis_of(b.hi, axis), w = hi - lo;
                const double beyond = random.below(2) == 0 ? lo - w * random.uniform(0.05, 1) : hi + w * random.uniform(0.05, 1);
                (axis == 0 ? target.x : axis == 1 ? target.y : target.z) = beyond;
            }
            const ray r = ray_through(from, target);
            const crossing c = cross(b, r);
            const bool hits = c.meets && c.t1 > 0;
            const real scale = scale_of(b, r);
            // Skip rays within round-off of the box's outline.
            if (c.meets && c.t1 - c.t0 < 1e-9L * scale) continue;
            intersection got;
            const cost spent = measure([&] { got = box->intersect(r); });
            if (hits) {
                t.check(got.hit() && spent.counts.bounding_volume_tests == 1 && spent.counts.primitive_tests <= 6, [&] {
                    return show(r) + " enters " + describe(b) + ": it should hit after one box test and at most 6 face tests; "
                           "yours returned " + got_words(got, box.get(), b) + " after " +
                           std::to_string(spent.counts.bounding_volume_tests) + " box tests and " +
                           std::to_string(spent.counts.primitive_tests) + " face tests";
                });
            } else {
                t.check(got.is_miss() && got.t == 0 && spent.counts.bounding_volume_tests == 1 && spent.counts.primitive_tests == 0, [&] {
                    return show(r) + " misses " + describe(b) + ": it should return a miss (intersection::none()) after one box "
                           "test and no face test; yours returned " + got_words(got, box.get(), b) + " after " +
                           std::to_string(spent.counts.bounding_volume_tests) + " box tests and " +
                           std::to_string(spent.counts.primitive_tests) + " face tests";
                });
            }
        }
    }
    t.report();
}

TEST_CASE("box: rays aimed exactly at edges and corners never slip between the faces", "[03][box][watertight][essential]") {
    tally t("rays at edges and corners");
    dice random(230);
    for (const box_shape& b : boxes) {
        const auto box = make_box(b.lo, b.hi);
        std::vector<point> targets;
        for (int i = 0; i < 2; ++i)
            for (int j = 0; j < 2; ++j)
                for (int k = 0; k < 2; ++k) targets.push_back(point(i ? b.hi.x : b.lo.x, j ? b.hi.y : b.lo.y, k ? b.hi.z : b.lo.z));
        // Points along the twelve edges.
        for (int e = 0; e < 12; ++e) {
            const int axis = e / 4;
            for (const double s : {0.25, 0.5, 0.8125}) {
                double c[3];
                for (int k = 0; k < 3; ++k) c[k] = axis_of(b.lo, k);
                const int u = (axis + 1) % 3, v = (axis + 2) % 3;
                if (e & 1) c[u] = axis_of(b.hi, u);
                if (e & 2) c[v] = axis_of(b.hi, v);
                c[axis] = axis_of(b.lo, axis) + s * (axis_of(b.hi, axis) - axis_of(b.lo, axis));
                targets.push_back(point(c[0], c[1], c[2]));
            }
        }
        for (const point& target : targets) {
            for (int k = 0; k < 6; ++k) {
                // From outside, towards the box's inside through the edge or corner.
                vector d = (centre_of(b) - target).unit() + 0.6 * random.direction();
                d = d.unit();
                const ray r(target - size_of(b) * 2 * d, d);
                const crossing c = cross(b, r);
                if (!c.meets || c.t1 - c.t0 < 1e-6L * size_of(b)) continue;  // through the outline only
                const real scale = scale_of(b, r);
                const double want = static_cast<double>(c.t0), tol = static_cast<double>(1e-11L * scale);
                const intersection got = box->intersect(r);
                t.check(got.hit() && got.object != box.get() && std::fabs(got.t - want) <= tol, [&] {
                    return show(r) + " enters " + describe(b) + " exactly through the edge or corner " + show(target) +
                           ": it should hit a face there, at t = " + num(want) + " ± " + num(tol) + " (no gap between the "
                           "faces); yours returned " + got_words(got, box.get(), b);
                });
                // From inside, out through the same point.
                const ray out(centre_of(b), target - centre_of(b));
                const double want_out = (target - centre_of(b)).length();
                const intersection g2 = box->intersect(out);
                t.check(g2.hit() && g2.object != box.get() && std::fabs(g2.t - want_out) <= tol, [&] {
                    return show(out) + " leaves " + describe(b) + " exactly through the edge or corner " + show(target) +
                           ": it should hit a face there, at t = " + num(want_out) + " ± " + num(tol) + "; yours returned " +
                           got_words(g2, box.get(), b);
                });
            }
        }
    }
    t.report();
}

TEST_CASE("box: normal(p) is the outward unit normal of the face p lies on", "[03][box][normals]") {
    tally t("normals of boxes");
    dice random(240);
    for (const box_shape& b : boxes) {
        const auto box = make_box(b.lo, b.hi);
        for (int f = 0; f < 6; ++f) {
            for (int k = 0; k < 20; ++k) {
                point p = inside_point(random, b, 0.05);
                const int axis = f / 2;
                (axis == 0 ? p.x : axis == 1 ? p.y : p.z) = axis_of(f % 2 == 0 ? b.lo : b.hi, axis);
                const vector n = box->normal(p), want = outward(f);
                t.check(std::fabs(n.x - want.x) + std::fabs(n.y - want.y) + std::fabs(n.z - want.z) <= 1e-12, [&] {
                    return "normal(" + show(p) + ") of " + describe(b) + " (a point of its face " + face_name(f) +
                           ") should be " + show(want) + "; yours is " + show(n);
                });
            }
        }
    }
    t.report();
}

TEST_CASE("box: contains() is true strictly inside and false on the faces and outside in any one axis", "[03][box][contains]") {
    tally t("contains() of boxes");
    dice random(250);
    for (const box_shape& b : boxes) {
        const auto box = make_box(b.lo, b.hi);
        const auto expect = [&](const point& p, bool want, const char* where) {
            const bool got = box->contains(p);
            t.check(got == want, [&] {
                return "contains(" + show(p) + ") of " + describe(b) + " (" + where + ") should be " + (want ? "true" : "false") +
                       "; yours is " + (got ? "true" : "false");
            });
        };
        expect(centre_of(b), true, "its centre");
        for (int k = 0; k < 30; ++k) {
            expect(inside_point(random, b, 0.001), true, "inside");
            for (int axis = 0; axis < 3; ++axis) {
                point p = inside_point(random, b, 0.01);
                const double lo = axis_of(b.lo, axis), hi = axis_of(b.hi, axis);
                const int side = random.below(4);
                const double value = side == 0 ? lo : side == 1 ? hi : side == 2 ? lo - (hi - lo) * 0.1 : hi + (hi - lo) * 0.1;
                (axis == 0 ? p.x : axis == 1 ? p.y : p.z) = value;
                expect(p, false, side < 2 ? "on a face" : "outside in one axis only");
            }
        }
        expect(b.lo, false, "its min corner");
        expect(b.hi, false, "its max corner");
    }
    t.report();
}

TEST_CASE("box: min_point() and max_point() are the corners - and BOX { } is the unit cube", "[03][box][bounds][detail]") {
    tally t("the corners of boxes");
    for (const box_shape& b : boxes) {
        const auto box = make_box(b.lo, b.hi);
        check_point(t, "min_point() of " + describe(b), box->min_point(), to_r(b.lo), 0);
        check_point(t, "max_point() of " + describe(b), box->max_point(), to_r(b.hi), 0);
    }
    const auto unit_box = read_one("BOX { }");
    check_point(t, "min_point() of BOX { }", unit_box->min_point(), rvec{0, 0, 0}, 0);
    check_point(t, "max_point() of BOX { }", unit_box->max_point(), rvec{1, 1, 1}, 0);
    dice random(260);
    const box_shape unit{point(0, 0, 0), point(1, 1, 1)};
    for (int k = 0; k < 50; ++k)
        check_hit(t, *unit_box, unit, ray_through(point(0.5, 0.5, 0.5) + 4 * random.direction(), inside_point(random, unit, 0.01)), false);
    t.report();
}

TEST_CASE("box: insert() and delete_all_children() are refused with the reason - and the box still works afterwards", "[03][box][refusals]") {
    tally t("a box refuses to change");
    const box_shape b{point(-1, -1, -1), point(1, 1, 1)};
    auto box = make_box(b.lo, b.hi);
    std::string message;
    t.check(throws_usage_error([&] { box->insert(std::make_unique<probe_sphere>(point(5, 0, 0), 1)); }, message),
            [&] { return "insert() into a BOX should throw vl::usage_error (a box is made of its six faces); " + message; });
    t.check(message.find("LIST") != std::string::npos || message.find("face") != std::string::npos, [&] {
        return "the refusal of insert() should say why (a box is made of its six faces) and what to do (a LIST); yours says: " + message;
    });
    t.check(throws_usage_error([&] { box->delete_all_children(); }, message),
            [&] { return "delete_all_children() of a BOX should throw vl::usage_error (its faces are the box); " + message; });
    t.check(box->children().size() == 6, [&] {
        return "after the refused insert() and delete_all_children() the BOX should still have its 6 faces; it has " +
               std::to_string(box->children().size());
    });
    dice random(270);
    for (int k = 0; k < 30; ++k)
        check_hit(t, *box, b, ray_through(point(0, 0, 0) + 6 * random.direction(), inside_point(random, b, 0.01)), false);
    t.report();
}

TEST_CASE("box: make_box() and the scene file refuse corners that are not finite or not below one another", "[03][box][refusals][detail]") {
    tally t("bad boxes");
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    const box_shape bad[] = {{point(0, 0, 0), point(1, 1, 0)},   {point(0, 0, 0), point(-1, 1, 1)}, {point(1, 1, 1), point(0, 0, 0)},
                             {point(nan, 0, 0), point(1, 1, 1)}, {point(0, 0, 0), point(1, inf, 1)}, {point(0, 0, 0), point(1, 1, 1, 0)}};
    for (const box_shape& b : bad) {
        std::string message;
        t.check(throws_usage_error([&] { make_box(b.lo, b.hi); }, message), [&] {
            return "make_box(point(" + num(b.lo.x) + ", " + num(b.lo.y) + ", " + num(b.lo.z) + ", " + num(b.lo.w) + "), point(" +
                   num(b.hi.x) + ", " + num(b.hi.y) + ", " + num(b.hi.z) + ", " + num(b.hi.w) + ")) should throw vl::usage_error; " + message;
        });
    }
    for (const char* text : {"BOX { min 0 0 0 max 1 0 1 }", "BOX { min 2 2 2 }"}) {
        const std::string message = read_error(text);
        t.check(message.find("hidden.ray_trace:1:") != std::string::npos,
                [&] { return std::string("reading \"") + text + "\" should fail with a vl::file_error; it gave: " + message; });
    }
    // A thin box is a box.
    const box_shape thin{point(0, 0, 0), point(1e-6, 1, 1)};
    const auto box = make_box(thin.lo, thin.hi);
    check_hit(t, *box, thin, ray(point(-1, 0.5, 0.5), vector(1, 0, 0)), false);
    check_hit(t, *box, thin, ray(point(5e-7, 0.5, 0.5), vector(0, 1, 0.25)), true);
    t.report();
}

TEST_CASE("box: the surface keys of a BOX reach every face - and write() gives back the corners and the keys", "[03][box][scene_io]") {
    tally t("BOX in scene files");
    const vl::surface surf = full_precision_surface(1e-7 / 3);
    const box_shape b{point(-0.5 + 1e-13, -1.0 / 3, 0.25), point(2.0 / 3, 0.75, 1.5 + 1e-12)};
    std::string text = "BOX { min " + num(b.lo.x) + " " + num(b.lo.y) + " " + num(b.lo.z) + " max " + num(b.hi.x) + " " +
                       num(b.hi.y) + " " + num(b.hi.z) + surface_text(surf) + " }";
    for (int pass = 0; pass < 2; ++pass) {
        const std::string who = pass == 0 ? "the BOX read from \"" + text + "\"" : "the BOX read back from what write() wrote, \"" + text + "\"";
        const auto box = read_one(text);
        check_point(t, "min_point() of " + who, box->min_point(), to_r(b.lo), 0);
        check_point(t, "max_point() of " + who, box->max_point(), to_r(b.hi), 0);
        for (int f = 0; f < 6; ++f) {
            const ray r(centre_of(b) + 3 * outward(f), -outward(f));
            const intersection got = box->intersect(r);
            if (!t.check(got.hit() && got.object != nullptr && got.object != box.get(), [&] {
                    return show(r) + " should hit the face " + std::string(face_name(f)) + " of " + who + "; yours returned " +
                           got_words(got, box.get(), b);
                }))
                continue;
            compare_surface(surface_of(*got.object), surf, std::string("the face ") + face_name(f) + " of " + who, t);
        }
        text = text_of(*box);
    }
    const std::vector<double> lo = numbers_after(text, "min", 3), hi = numbers_after(text, "max", 3);
    t.check(lo.size() == 3 && hi.size() == 3 && lo[0] == b.lo.x && lo[1] == b.lo.y && lo[2] == b.lo.z && hi[0] == b.hi.x &&
                hi[1] == b.hi.y && hi[2] == b.hi.z,
            [&] { return "write() should give every digit of the corners after min and max; yours wrote \"" + text + "\""; });
    t.report();
}
