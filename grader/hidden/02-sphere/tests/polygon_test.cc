// Hidden tests of stage 02's convex polygon (polygon.cc). Each TEST_CASE is one graded
// item; the tag [polygon] puts it in the rubric's "polygons" category. Every expected
// answer comes from the long-double formulas in hidden_support.hh, never from another of
// your objects; on an edge shared by two polygons either may report the hit.
#include "vl/catch.hh"

#include <algorithm>
#include <cmath>
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
using vl::stage02::make_polygon;
using namespace vl::stage02::hidden;

namespace {

using shape = std::vector<point>;

std::string describe(const shape& v) {
    std::string s = "the polygon";
    for (const point& p : v) s += " " + show(p);
    return s;
}

// A regular n-gon of `radius` around `centre` in the plane spanned by u and v,
// counter-clockwise seen from the side u % v points to.
shape regular(int n, const point& centre, double radius, const vector& u, const vector& v, double turn = 0) {
    shape out;
    for (int k = 0; k < n; ++k) {
        const double angle = 2 * std::numbers::pi * k / n + turn;
        out.push_back(centre + radius * std::cos(angle) * u + radius * std::sin(angle) * v);
    }
    return out;
}

// A random convex polygon: 3 to 9 points of a tilted ellipse at sorted random angles,
// in either winding.
shape random_convex(sampler& random) {
    const int n = 3 + static_cast<int>(random.uniform(0, 7));
    std::vector<double> angles;
    for (int k = 0; k < n; ++k) angles.push_back(random.uniform(0, 2 * std::numbers::pi));
    std::sort(angles.begin(), angles.end());
    for (std::size_t k = 1; k < angles.size(); ++k)
        if (angles[k] - angles[k - 1] < 0.05) angles[k] = angles[k - 1] + 0.05;
    if (angles.back() - angles.front() > 2 * std::numbers::pi - 0.05 || angles.back() > 2 * std::numbers::pi + angles.front() - 0.3)
        angles.back() = angles.front() + 2 * std::numbers::pi - 0.3;
    vector u, v;
    plane_axes(random.direction(), u, v);
    const point centre = random.in_cube(10);
    const double a = random.uniform(0.5, 3), b = random.uniform(0.5, 3);
    shape out;
    for (const double angle : angles) out.push_back(centre + a * std::cos(angle) * u + b * std::sin(angle) * v);
    if (random.uniform(0, 1) < 0.5) std::reverse(out.begin(), out.end());
    return out;
}

double size_of(const shape& v) {
    point lo = v[0], hi = v[0];
    for (const point& p : v) {
        lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
        hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
    }
    return (hi - lo).length();
}

vector normal_of(const shape& v) {
    const rvec n = unit(newell(v));
    return {static_cast<double>(n.x), static_cast<double>(n.y), static_cast<double>(n.z)};
}

point centre_of(const shape& v) {
    vector sum;
    for (const point& p : v) sum += p - point(0, 0, 0);
    return point(0, 0, 0) + sum / static_cast<double>(v.size());
}

double tolerance_of(const shape& v, const ray& r, double t) {
    const double cosine = std::max(std::fabs(r.direction() * normal_of(v)), 1e-2);
    const point c = centre_of(v);
    const double coordinates = std::fabs(c.x) + std::fabs(c.y) + std::fabs(c.z);
    return 1e-11 * ((r.origin() - c).length() + std::fabs(t) + size_of(v) + coordinates) / cosine;
}

// Checks one ray whose point in the polygon's plane is clearly inside or clearly outside
// (by `margin` of the polygon's size); rays in between are skipped.
void check_ray(tally& t, const primitive& poly, const shape& v, const ray& r, double margin = 1e-6, double extra = 0) {
    const polygon_answer exact = polygon_oracle(v, r);
    if (exact.meets && std::fabs(static_cast<double>(exact.inside)) < margin) return;
    const double want = static_cast<double>(exact.t);
    const bool hits = exact.meets && exact.inside > 0 && want > std::fabs(poly.zero_t());
    const intersection i = poly.intersect(r);
    const std::string side = (r.origin() - v[0]) * normal_of(v) > 0 ? " from the front" : " from behind";
    if (hits) {
        const double tol = tolerance_of(v, r, want) + extra;
        check_hit_at(t, i, poly, r, want, tol, [&] { return describe(v); }, side);
    } else {
        t.check(clean_miss(i), [&] {
            return show(r) + side + " should miss " + describe(v) +
                   (exact.meets && exact.inside > 0 ? " (the polygon is behind it)" : " (it passes outside an edge)") +
                   "; yours returned " + show(i, &poly);
        });
    }
}

// `got` answers like `want`, the same polygon made another way.
void check_same_polygon(tally& t, const rtab_component& got, const primitive& want, const shape& v, const std::string& who) {
    t.check(got.type_name() == "POLYGON", [&] { return who + "'s type_name() is \"" + got.type_name() + "\", not \"POLYGON\""; });
    double coordinates = 0;
    for (const point& p : v) coordinates = std::max({coordinates, std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)});
    const double slack = 8 * std::numeric_limits<double>::epsilon() * coordinates;
    check_same_box(t, got, want, who, slack);
    const point middle = centre_of(v);
    const vector gn = got.normal(middle), wn = want.normal(middle);
    t.check((gn - wn).length() <= 1e-12 + 100 * slack / size_of(v), [&] {
        return who + ".normal(" + show(middle) + ") is " + show(gn) + " where the polygon's is " + show(wn);
    });
    t.check(!got.contains(middle), [&] { return who + ".contains() should be false (a polygon has no inside)"; });
    sampler random(501);
    const vector n = normal_of(v);
    for (int j = 0; j < 40; ++j) {
        const point target = middle + 0.8 * random.uniform(0, 1) * (v[static_cast<std::size_t>(j) % v.size()] - middle) +
                             (j % 3 == 0 ? 0.5 * size_of(v) * random.offset(1) : vector());
        const ray r = ray_through(target + size_of(v) * random.uniform(0.5, 5) * (j % 2 == 0 ? n : -n) + random.offset(size_of(v)),
                              target);
        const polygon_answer exact = polygon_oracle(v, r);
        if (std::fabs(static_cast<double>(exact.inside)) < 1e-6) continue;
        const intersection i = got.intersect(r), w = want.intersect(r);
        check_same_answer(t, r, got, i, want, w, tolerance_of(v, r, w.t) + slack, who, "polygon");
    }
}

std::string polygon_text(const shape& v, const vl::surface& s, bool with_surface) {
    std::string text = "POLYGON {";
    if (with_surface)
        text += surface_text(s);
    text += " vertices";
    for (const point& p : v) text += " (" + num(p.x) + ", " + num(p.y) + ", " + num(p.z) + ")";
    return text + " }";
}

// Sweeps rays at `v` from either side: aimed inside, near the edges, and outside.
void sweep(tally& t, const shape& v, sampler& random, int rays) {
    const auto poly = make_polygon(v);
    const vector n = normal_of(v);
    const point c = centre_of(v);
    for (int j = 0; j < rays; ++j) {
        const point corner = v[static_cast<std::size_t>(j) % v.size()];
        const point target = c + random.uniform(0, 1.3) * (corner - c) + 0.2 * size_of(v) * random.offset(1);
        const point from = target + size_of(v) * random.uniform(0.1, 10) * (j % 2 == 0 ? n : -n) + random.offset(size_of(v));
        const ray r = ray_through(from, target);
        if (std::fabs(r.direction() * n) < 0.02) continue;
        check_ray(t, *poly, v, r);
    }
}

}  // namespace

// --- hits and misses ---------------------------------------------------------------------

TEST_CASE("polygon: rays at random convex polygons hit inside them and miss outside - from either side", "[02][polygon][hits][essential]") {
    tally t("rays at convex polygons");
    sampler random(511);
    for (int k = 0; k < 40; ++k) sweep(t, random_convex(random), random, 60);
    t.report();
}

TEST_CASE("polygon: a tilted regular hexagon is hit just inside each edge and missed just outside and beyond its corners", "[02][polygon][misses][essential]") {
    tally t("rays near the edges of a hexagon");
    const vector n = vector(0.3, -0.4, 1).unit();
    vector u, v;
    plane_axes(n, u, v);
    const point centre(2.5, -1.5, -6);
    const shape hexagon = regular(6, centre, 2, u, v, 0.2);
    const auto p = make_polygon(hexagon);
    for (const point& eye : {point(0.5, 1, 4), point(4, -3, -15)}) {
        for (std::size_t e = 0; e < hexagon.size(); ++e) {
            const point a = hexagon[e], b = hexagon[(e + 1) % hexagon.size()];
            for (const double f : {0.05, 0.5, 0.95}) {
                const point on_edge = a + f * (b - a);
                const vector outward = (on_edge - centre).unit();
                check_ray(t, *p, hexagon, ray_through(eye, on_edge - 1e-5 * outward), 1e-7);
                check_ray(t, *p, hexagon, ray_through(eye, on_edge + 1e-5 * outward), 1e-7);
            }
            // Beyond each corner, along the line from the centre, and in the corner of the
            // hexagon's box (inside the box, outside the hexagon).
            check_ray(t, *p, hexagon, ray_through(eye, centre + 1.01 * (a - centre)));
            check_ray(t, *p, hexagon, ray_through(eye, a + 0.45 * (b - a) + 0.15 * (a + 0.5 * (b - a) - centre)));
        }
        // Away from it.
        check_ray(t, *p, hexagon, ray(eye, eye - centre));
    }
    t.report();
}

TEST_CASE("polygon: a polygon is hit from behind as well as from the front", "[02][polygon][hits][essential]") {
    tally t("pairs of rays from either side through the same point");
    sampler random(512);
    for (int k = 0; k < 60; ++k) {
        const shape v = random_convex(random);
        const auto poly = make_polygon(v);
        const vector n = normal_of(v);
        const point c = centre_of(v);
        for (int j = 0; j < 5; ++j) {
            const point target = c + random.uniform(0, 0.5) * (v[static_cast<std::size_t>(j) % v.size()] - c);
            vector d = random.direction();
            if (std::fabs(d * n) < 0.1) d = d + 0.5 * n;
            check_ray(t, *poly, v, ray_through(target + random.uniform(0.1, 10) * d, target));
            check_ray(t, *poly, v, ray_through(target - random.uniform(0.1, 10) * d, target));
        }
    }
    t.report();
}

TEST_CASE("polygon: a three-vertex polygon is hit inside and missed outside like the triangle it is", "[02][polygon][hits]") {
    tally t("rays at a three-vertex polygon");
    const shape v = {point(0.7, -1.1, 0.4), point(2.9, 0.8, -1.3), point(-0.6, 1.9, 1.1)};
    const auto poly = make_polygon(v);
    sampler random(513);
    for (int k = 0; k < 2000; ++k) {
        const point target = v[0] + random.uniform(-0.3, 1.3) * (v[1] - v[0]) + random.uniform(-0.3, 1.3) * (v[2] - v[0]);
        check_ray(t, *poly, v, ray_through(random.in_cube(10), target));
    }
    t.report();
}

TEST_CASE("polygon: rays exactly parallel to a polygon or lying in its plane miss cleanly", "[02][polygon][parallel]") {
    tally t("rays parallel to a polygon");
    const shape v = {point(-1, 0, -1), point(1, 0, -1.5), point(2, 0, 0.5), point(0, 0, 2), point(-1.5, 0, 1)};
    const auto p = make_polygon(v);
    check_parallel_rays_miss(t, *p, describe(v), point(0.2, 0, 0.1), vector(0, 1, 0),
                             {vector(1, 0, 0), vector(0.3, 0, -1), vector(-1, 0, -1), vector(1, 0, 1e-3)},
                             {0.0, 1e-9, -1e-9, -4.0});
    t.report();
}

TEST_CASE("polygon: rays leaving a point of the polygon never hit it again - whatever the sign of zero_t", "[02][polygon][surface]") {
    tally t("rays leaving a polygon");
    const vector n = vector(-0.7, 0.2, 0.5).unit();
    vector u, v;
    plane_axes(n, u, v);
    const point centre(-80.3, 44.7, 301.2);
    const shape octagon = regular(8, centre, 9, u, v, 0.1);
    const auto p = make_polygon(octagon);
    sampler random(514);
    for (const double zero_t : {1e-6, -1e-6}) {
        vl::surface s;
        s.zero_t = zero_t;
        p->set_surface(s);
        for (int k = 0; k < 1500; ++k) {
            const double r = 8 * std::sqrt(random.uniform(0, 1)), phi = random.uniform(0, 2 * std::numbers::pi);
            const point on = centre + r * std::cos(phi) * u + r * std::sin(phi) * v;
            const vector d = leaving_direction(random, k, n, u, v, -5);
            check_leaving_misses(t, *p, ray(on, d), zero_t, [&] { return "the octagon around " + show(centre); });
        }
    }
    t.report();
}

TEST_CASE("polygon: zero_t - positive or negative - hides a hit up to its absolute value", "[02][polygon][zero_t]") {
    tally t("a polygon hit at t = 0.3 with different zero_t");
    const shape v = {point(0, 0, -0.3), point(1, 0, -0.3), point(1, 1, -0.3), point(0, 1, -0.3)};
    const auto p = make_polygon(v);
    check_zero_t_hides_hit_at_0_3(t, *p, "the unit square at z = -0.3", {ray(point(0.5, 0.25, 0), vector(0, 0, -1)), ray(point(0.5, 0.25, -0.6), vector(0, 0, 1))});
    t.report();
}

TEST_CASE("polygon: a small octagon a million units away keeps its corners and edges sharp", "[02][polygon][far]") {
    tally t("rays at a far octagon");
    const point centre(-5e5, 2e5, -8e5);
    const vector towards = (centre - point(0, 0, 0)).unit();
    const vector u = (towards % vector(0, 1, 0)).unit(), v = (u % towards).unit();
    const shape octagon = regular(8, centre, 1, u, v, 0.3);
    const auto p = make_polygon(octagon);
    const point eye(0, 0, 0);
    for (std::size_t e = 0; e < octagon.size(); ++e) {
        const point a = octagon[e], b = octagon[(e + 1) % octagon.size()];
        const point mid = a + 0.5 * (b - a);
        const vector outward = (mid - centre).unit();
        check_ray(t, *p, octagon, ray_through(eye, mid - 1e-4 * outward), 1e-5);
        check_ray(t, *p, octagon, ray_through(eye, mid + 1e-4 * outward), 1e-5);
        check_ray(t, *p, octagon, ray_through(eye, a + 0.4 * (mid - a) + 0.04 * outward), 1e-5);  // inside its box
    }
    check_ray(t, *p, octagon, ray_through(eye, centre));
    t.report();
}

// --- watertight --------------------------------------------------------------------------

TEST_CASE("polygon: rays from inside a box of six rectangular faces never escape through its edges or corners", "[02][polygon][watertight][essential]") {
    const vector x = 1.7 * vector(0.6, 0, -0.8), y = 0.9 * vector(0.48, 0.6, 0.36), z = 1.3 * (x % y).unit();
    const point o(10.3, -4.4, 7.9);
    const auto corner = [&](int i, int j, int k) { return o + i * x + j * y + k * z; };
    const std::vector<std::unique_ptr<primitive>> faces = box_of_polygons(o, x, y, z, false);
    const point middle = o + 0.5 * (x + y + z);
    tally t("rays from inside a closed box of polygons (none of its faces hit)");
    sampler random(33);
    std::vector<ray> rays;
    std::vector<point> targets;
    for (int k = 0; k < 20000; ++k) {
        const int i = k % 2, j = (k / 2) % 2, l = (k / 4) % 2;
        point target = corner(i, j, l);
        if (k % 7 != 0) {  // a point on one of the three edges from that corner
            const int axis = (k / 8) % 3;
            const vector along = axis == 0 ? (i == 0 ? x : -x) : axis == 1 ? (j == 0 ? y : -y) : (l == 0 ? z : -z);
            target = target + random.uniform(0, 1) * along;
        }
        const point from = middle + random.uniform(-0.4, 0.4) * x + random.uniform(-0.4, 0.4) * y +
                           random.uniform(-0.4, 0.4) * z;
        rays.push_back(ray_through(from, target));
        targets.push_back(target);
    }
    const std::vector<bool> hit = hits_any(faces, rays);
    for (std::size_t k = 0; k < rays.size(); ++k)
        t.check(hit[k], [&] { return show(rays[k]) + " aimed at " + show(targets[k]) + " escapes through the box"; });
    t.report();
}

TEST_CASE("polygon: rays through the shared edges and the hub of a ring of quadrilaterals never slip through", "[02][polygon][watertight][essential]") {
    // Six convex quadrilaterals around one hub vertex in a tilted plane, each sharing its
    // two spokes with its neighbours.
    const vector n = vector(0.2, 1, -0.3).unit();
    vector u, v;
    plane_axes(n, u, v);
    const point hub(-71.3, 20.9, 5.5);
    const shape rim = regular(12, hub, 2.5, u, v, 0.13);
    std::vector<std::unique_ptr<primitive>> ring;
    for (std::size_t k = 0; k < 6; ++k) ring.push_back(make_polygon({hub, rim[2 * k], rim[2 * k + 1], rim[(2 * k + 2) % 12]}));
    tally t("rays through the spokes and the hub of a ring of quadrilaterals (none of them hit)");
    sampler random(34);
    std::vector<ray> rays;
    std::vector<point> targets;
    for (int k = 0; k < 20000; ++k) {
        const std::size_t spoke = 2 * static_cast<std::size_t>(k % 6);
        const point target = k % 5 == 0 ? hub : hub + random.uniform(0.01, 0.99) * (rim[spoke] - hub);
        vector d = random.direction();
        if (std::fabs(d * n) < 0.2) d = d + 0.5 * (d * n < 0 ? -n : n);
        rays.push_back(ray_through(target + random.uniform(1, 30) * d.unit(), target));
        targets.push_back(target);
    }
    const std::vector<bool> hit = hits_any(ring, rays);
    for (std::size_t k = 0; k < rays.size(); ++k)
        t.check(hit[k], [&] { return show(rays[k]) + " aimed at " + show(targets[k]) + " slips through the ring"; });
    t.report();
}

// --- collinear vertices, normal, bounds ----------------------------------------------------

TEST_CASE("polygon: three vertices in a row on one edge are allowed - and the polygon is hit - missed and faces as usual", "[02][polygon][collinear]") {
    // The contract refuses a vertex *outside* the line of an edge; one on it is fine. The
    // normal must then not come from the first three vertices alone.
    tally t("polygons with collinear consecutive vertices");
    const vector n = vector(0.2, -0.5, 1).unit();
    vector u, v;
    plane_axes(n, u, v);
    const point o(1.5, -2, 0.75);
    const auto in_plane = [&](double a, double b) { return o + a * u + b * v; };
    const std::vector<shape> shapes = {
        // The first three vertices are on one line.
        {in_plane(0, 0), in_plane(1, 0), in_plane(2, 0), in_plane(2, 1), in_plane(0, 1)},
        // Four in a row, and the last, first and second on one line.
        {in_plane(0, 0), in_plane(0.5, 0), in_plane(1, 0), in_plane(1.5, 0), in_plane(2, 0), in_plane(2, 2), in_plane(0, 2),
         in_plane(0, 1)},
        // A triangle with an extra vertex in the middle of each edge, wound clockwise.
        {in_plane(0, 0), in_plane(0, 1), in_plane(0, 2), in_plane(1, 1), in_plane(2, 0), in_plane(1, 0)},
    };
    sampler random(515);
    for (const shape& s : shapes) {
        std::unique_ptr<primitive> poly;
        try {
            poly = make_polygon(s);
        } catch (const std::exception& e) {
            t.check(false, [&] { return "make_polygon(" + describe(s) + ") should make the polygon; it threw: " + e.what(); });
            continue;
        }
        const vector want = normal_of(s), got = poly->normal(centre_of(s));
        t.check(unit_gap(got, want) <= 1e-12, [&] {
            return "the normal of " + describe(s) + " should be " + show(want) + " ± 1e-12 (counter-clockwise side); yours is " +
                   show(got);
        });
        sweep(t, s, random, 300);
    }
    t.report();
}

TEST_CASE("polygon: the normal follows the winding of a twelve-sided polygon - from any first vertex", "[02][polygon][normals][essential]") {
    tally t("normals");
    const vector n = vector(-2, 0.5, 1.5).unit();
    vector u, v;
    plane_axes(n, u, v);
    shape ring = regular(12, point(3, 4, 5), 1.7, u, v);
    const point on = point(3, 4, 5) + 0.3 * u;
    sampler random(516);
    std::vector<shape> all;
    for (int k = 0; k < 12; k += 5) {
        shape rotated = ring;
        std::rotate(rotated.begin(), rotated.begin() + k, rotated.end());
        all.push_back(rotated);
        std::reverse(rotated.begin(), rotated.end());
        all.push_back(rotated);
    }
    for (int k = 0; k < 10; ++k) all.push_back(random_convex(random));
    for (const shape& s : all) {
        const auto p = make_polygon(s);
        const vector want = normal_of(s);
        // Rays from behind must not change it.
        for (int j = 0; j < 3; ++j) p->intersect(ray_through(centre_of(s) - 3 * want, centre_of(s)));
        const vector got = p->normal(on);
        t.check(unit_gap(got, want) <= 1e-12, [&] {
            return "the normal of " + describe(s) + " should be " + show(want) + " ± 1e-12 (unit, counter-clockwise side); yours is " +
                   show(got);
        });
        t.check(!p->contains(centre_of(s)), [&] { return describe(s) + ".contains() should be false (it has no inside)"; });
    }
    t.report();
}

TEST_CASE("polygon: its box is exactly the smallest one around the vertices", "[02][polygon][bounds]") {
    tally t("bounds");
    const struct {
        shape v;
        point lo, hi;
    } cases[] = {
        {{point(1, 0, 0), point(3, 1, -1), point(4, 3, -3), point(2, 4, -4), point(0, 2, -2)}, point(0, 0, -4), point(4, 4, 0)},
        {{point(-1e5, 0.25, 7), point(3, -2e-3, -8.5), point(0.5, 9e4, 7.5)}, point(-1e5, -2e-3, -8.5), point(3, 9e4, 7.5)},
        {{point(0, 0, 2), point(1, 0, 2), point(1, 1, 2), point(0, 1, 2)}, point(0, 0, 2), point(1, 1, 2)},
    };
    for (const auto& c : cases) {
        check_exact_box(t, *make_polygon(c.v), describe(c.v), c.lo, c.hi);
    }
    t.report();
}

// --- the factory and scene files ----------------------------------------------------------

TEST_CASE("polygon: make_polygon refuses too few - repeated - non-finite - collinear - bent or dented vertices and takes rounded ones", "[02][polygon][refusals]") {
    const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
    tally t("make_polygon");
    const point a(0, 0, 0), b(1, 0, 0), c(1, 1, 0), d(0, 1, 0);
    const std::vector<shape> bad = {
        {},
        {a},
        {a, b},
        {a, b, b, c},
        {a, b, c, d, a},
        {a, b, point(nan, 1, 0), d},
        {a, b, c, point(0, inf, 0)},
        {a, b, c, point(0, 1, 0, 0)},
        {a, b, point(2, 0, 0)},
        {a, b, point(3, 0, 0), point(-1, 0, 0)},
        {a, b, point(1, 1, 0.2), d},
        {a, b, point(0.3, 0.3, 0), d},
        {a, c, b, d},  // crossed
    };
    for (const shape& s : bad) expect_usage_error(t, "make_polygon(" + describe(s) + ")", [&] { return make_polygon(s); });
    // Vertices written with seven decimals are off the plane and the edges by ~1e-8 of
    // the size: within the contract's 1e-6, so accepted, and hit like the exact ones.
    const vector n = vector(1, 2, 3).unit();
    vector u, v;
    plane_axes(n, u, v);
    shape rounded = regular(7, point(0.5, -0.25, 1), 1, u, v);
    for (point& p : rounded) p = point(std::round(p.x * 1e7) / 1e7, std::round(p.y * 1e7) / 1e7, std::round(p.z * 1e7) / 1e7);
    try {
        const auto p = make_polygon(rounded);
        // The vertices are off one plane by up to ~1e-7: so may the hit be.
        check_ray(t, *p, rounded, ray_through(point(0.5, -0.25, 1) + 3 * n, point(0.5, -0.25, 1)), 1e-6, 1e-6);
    } catch (const std::exception& e) {
        t.check(false, [&] { return "make_polygon(" + describe(rounded) + ") should be accepted; it threw: " + e.what(); });
    }
    shape bent = rounded;
    bent[3] = bent[3] + 1e-3 * n;
    expect_usage_error(t, "make_polygon(" + describe(bent) + ")", [&] { return make_polygon(bent); });
    t.report();
}

TEST_CASE("polygon: a POLYGON in a scene file is the polygon its vertices and surface keys describe", "[02][polygon][scene_io]") {
    tally t("POLYGON read from a scene file");
    const vector n = vector(1.0 / 3, -0.2, 1).unit();
    vector u, v;
    plane_axes(n, u, v);
    const shape s = regular(5, point(0.1 + 1e-13, -1.0 / 3, 7.25), 2.0 / 3, u, v, 0.1);
    const vl::surface surf = full_precision_surface(-1e-7 / 3);
    const std::string text = polygon_text(s, surf, true);
    const auto want = make_polygon(s);
    check_read_as(t, text, "POLYGON", *want, surf,
                  [&](const rtab_component& got, const std::string& what) { check_same_polygon(t, got, *want, s, what); });
    t.report();
}

TEST_CASE("polygon: a bad POLYGON in a scene file is refused at the vertex at fault - a good one is read", "[02][polygon][scene_io][detail]") {
    tally t("POLYGON blocks in scene files");
    check_refused(t, {
        {"POLYGON {\n  vertices (0, 0, 0) (2, 0, 0) (2, 2, 0) (0, 2, 0)\n  (-0.5, 1, 0.3)\n}", "hidden.ray_trace:3:3"},
        {"POLYGON {\n  vertices (0, 0, 0) (2, 0, 0)\n  (2, 0, 0) (0, 2, 0)\n}", "hidden.ray_trace:3:3"},
        {"POLYGON {\n  vertices (0, 0, 0) (2, 0, 0)\n  (2, 2, 0, 0) (0, 2, 0)\n}", "hidden.ray_trace:3:"},
        {"POLYGON { vertices (0, 0, 0) (1, 0, 0) }", "hidden.ray_trace:1:"},
    });
    const shape s = {point(0, 0, -2), point(2, 0, -2), point(2.5, 1, -2), point(0, 2, -2)};
    const auto good = read_one(polygon_text(s, {}, false));
    const auto want = make_polygon(s);
    check_same_polygon(t, *good, *want, s, polygon_text(s, {}, false));
    t.report();
}

TEST_CASE("polygon: an empty POLYGON block is the unit square facing plus z with the default surface", "[02][polygon][scene_io][detail]") {
    tally t("POLYGON { }");
    const shape s = {point(0, 0, 0), point(1, 0, 0), point(1, 1, 0), point(0, 1, 0)};
    const auto got = read_one("POLYGON { }");
    const auto want = make_polygon(s);
    compare_surface(surface_of(*got), vl::surface{}, "POLYGON { }", t);
    check_same_polygon(t, *got, *want, s, "POLYGON { }");
    t.report();
}

TEST_CASE("polygon: write() keeps every digit of the vertices - in order - and of each surface key", "[02][polygon][scene_io]") {
    tally t("write() of a POLYGON read back");
    const vector n = vector(1.0 / 3, -0.2, 1).unit();
    vector u, v;
    plane_axes(n, u, v);
    for (const shape& s : {regular(5, point(0.1 + 1e-13, -1.0 / 3, 2.0 / 3 + 1e-12), 1.0 / 3, u, v, 0.1),
                           regular(6, point(123456.789012345, 1e-7, -1.0 / 7), 0.25, u, v, 0.7)}) {
        const auto original = make_polygon(s);
        original->set_surface(full_precision_surface(-1e-9 / 3));
        check_write_reads_back(
            t, *original, "POLYGON", describe(s),
            [&](const written_object& w, const std::string& who) {
                t.check(w.vertices.size() == s.size(), [&] {
                    return who + " has " + std::to_string(w.vertices.size()) + " vertices; it should have " + std::to_string(s.size());
                });
                for (std::size_t k = 0; k < std::min(w.vertices.size(), s.size()); ++k) {
                    const point q = w.vertices[k], p = s[k];
                    t.check(within_ulps(q.x, p.x, 4) && within_ulps(q.y, p.y, 4) && within_ulps(q.z, p.z, 4), [&] {
                        return who + " has vertex " + std::to_string(k + 1) + " = " + show(q) + "; it should be " + show(p) +
                               " (± 4 ulps, in the order given)";
                    });
                }
            },
            [&](const rtab_component& back, const std::string& what) { check_same_polygon(t, back, *original, s, what); });
    }
    t.report();
}
