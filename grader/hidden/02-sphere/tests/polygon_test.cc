// Hidden tests of stage 02's convex polygon (grader only; students never see this file).
// Each TEST_CASE is one graded item; the tag [polygons] puts it in the rubric's
// "polygons" category.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <sstream>
#include <vector>

#include "hidden_support.hh"
#include "vl/error.hh"

using vl::intersection;
using vl::point;
using vl::primitive;
using vl::ray;
using vl::vector;
using vl::stage02::make_polygon;
using vl::stage02::make_triangle;
using namespace vl::stage02::hidden;

namespace {

// A regular n-gon of `radius` around `centre` in the plane spanned by u and v,
// counter-clockwise seen from the side u % v points to.
std::vector<point> regular(int n, const point& centre, double radius, const vector& u, const vector& v, double turn = 0) {
    std::vector<point> out;
    for (int k = 0; k < n; ++k) {
        const double angle = 2 * std::numbers::pi * k / n + turn;
        out.push_back(centre + radius * std::cos(angle) * u + radius * std::sin(angle) * v);
    }
    return out;
}

bool any_hit(const std::vector<std::unique_ptr<primitive>>& faces, const ray& r) {
    bool hit = false;
    for (const auto& f : faces) hit = clean_hit(f->intersect(r), f.get()) || hit;
    return hit;
}

}  // namespace

TEST_CASE("polygon: a tilted regular hexagon is hit just inside each edge and missed just outside", "[02][polygon][polygons][essential]") {
    const vector n = vector(0.3, -0.4, 1).unit();
    vector u, v;
    plane_axes(n, u, v);
    const point centre(2.5, -1.5, -6);
    const std::vector<point> hexagon = regular(6, centre, 2, u, v, 0.2);
    const auto p = make_polygon(hexagon);
    const point eye(0.5, 1, 4);
    int missed_inside = 0, hit_outside = 0, hit_beyond_corner = 0;
    for (std::size_t e = 0; e < hexagon.size(); ++e) {
        const point a = hexagon[e], b = hexagon[(e + 1) % hexagon.size()];
        for (const double f : {0.05, 0.5, 0.95}) {
            const point on_edge = a + f * (b - a);
            const vector outward = (on_edge - centre).unit();
            if (!clean_hit(p->intersect(through(eye, on_edge - 1e-6 * outward)), p.get())) ++missed_inside;
            if (!clean_miss(p->intersect(through(eye, on_edge + 1e-6 * outward)))) ++hit_outside;
        }
        // Beyond each corner, along the line from the centre.
        if (!clean_miss(p->intersect(through(eye, centre + 1.01 * (a - centre))))) ++hit_beyond_corner;
    }
    CHECK(missed_inside == 0);
    CHECK(hit_outside == 0);
    CHECK(hit_beyond_corner == 0);
}

TEST_CASE("polygon: a three-vertex polygon answers random rays like the triangle with the same vertices", "[02][polygon][polygons]") {
    const point a(0.7, -1.1, 0.4), b(2.9, 0.8, -1.3), c(-0.6, 1.9, 1.1);
    const auto poly = make_polygon({a, b, c});
    const auto tri = make_triangle(a, b, c);
    sampler random(31);
    int disagree = 0, hits = 0;
    for (int k = 0; k < 5000; ++k) {
        const point target = a + random.uniform(-0.3, 1.3) * (b - a) + random.uniform(-0.3, 1.3) * (c - a);
        const ray r = through(random.in_box(10), target);
        const intersection i = poly->intersect(r), j = tri->intersect(r);
        if (clean_hit(i, poly.get()) != clean_hit(j, tri.get())) ++disagree;
        else if (j.hit() && std::fabs(i.t - j.t) > 1e-9 * (1 + j.t)) ++disagree;
        if (j.hit()) ++hits;
    }
    CHECK(hits > 500);
    CHECK(disagree == 0);
}

TEST_CASE("polygon: rays exactly parallel to a polygon or lying in its plane miss cleanly", "[02][polygon][polygons]") {
    const auto p = make_polygon({point(-1, 0, -1), point(1, 0, -1.5), point(2, 0, 0.5), point(0, 0, 2), point(-1.5, 0, 1)});
    int wrong = 0;
    std::ostringstream first;
    for (const vector d : {vector(1, 0, 0), vector(0.3, 0, -1), vector(-1, 0, -1), vector(1, 0, 1e-3)}) {
        for (const double y : {0.0, 1e-9, -1e-9, -4.0}) {
            const intersection across = p->intersect(ray(point(0.2, y, 0.1) - 10 * d.unit(), d));
            const intersection from_inside = p->intersect(ray(point(0.2, y, 0.1), d));
            if ((!clean_miss(across) || !clean_miss(from_inside)) && wrong++ == 0)
                first << "direction " << d << " at y = " << y << ": t = " << across.t << " and " << from_inside.t;
        }
    }
    INFO("the first ray that did not miss: " << first.str());
    CHECK(wrong == 0);
}

TEST_CASE("polygon: rays leaving a point of the polygon at grazing angles never hit it again", "[02][polygon][polygons]") {
    const vector n = vector(-0.7, 0.2, 0.5).unit();
    vector u, v;
    plane_axes(n, u, v);
    const point centre(-80.3, 44.7, 301.2);
    const std::vector<point> octagon = regular(8, centre, 9, u, v, 0.1);
    const auto p = make_polygon(octagon);
    sampler random(32);
    int self_hits = 0;
    for (int k = 0; k < 3000; ++k) {
        const double r = 8 * std::sqrt(random.uniform(0, 1)), phi = random.uniform(0, 2 * std::numbers::pi);
        const point on = centre + r * std::cos(phi) * u + r * std::sin(phi) * v;
        const double angle = std::pow(10.0, random.uniform(-5, -1)) * (k % 2 == 0 ? 1 : -1);
        const double turn = random.uniform(0, 2 * std::numbers::pi);
        const vector d = std::cos(angle) * (std::cos(turn) * u + std::sin(turn) * v) + std::sin(angle) * n;
        if (!clean_miss(p->intersect(ray(on, d)))) ++self_hits;
    }
    CHECK(self_hits == 0);
}

TEST_CASE("polygon: a small octagon a million units away keeps its corners and edges sharp", "[02][polygon][polygons]") {
    const point centre(-5e5, 2e5, -8e5);
    const vector towards = (centre - point(0, 0, 0)).unit();
    const vector u = (towards % vector(0, 1, 0)).unit(), v = (u % towards).unit();
    const std::vector<point> octagon = regular(8, centre, 1, u, v, 0.3);
    const auto p = make_polygon(octagon);
    int wrong = 0;
    for (std::size_t e = 0; e < octagon.size(); ++e) {
        const point a = octagon[e], b = octagon[(e + 1) % octagon.size()];
        const point mid = a + 0.5 * (b - a);
        const vector outward = (mid - centre).unit();
        if (!clean_hit(p->intersect(through(point(0, 0, 0), mid - 1e-4 * outward)), p.get())) ++wrong;
        if (!clean_miss(p->intersect(through(point(0, 0, 0), mid + 1e-4 * outward)))) ++wrong;
        // Outside the corner cut off between two edges: inside the octagon's box, not in it.
        const point corner_cut = a + 0.4 * (mid - a) + 0.04 * outward;
        if (!clean_miss(p->intersect(through(point(0, 0, 0), corner_cut)))) ++wrong;
    }
    const intersection centre_hit = p->intersect(through(point(0, 0, 0), centre));
    REQUIRE(clean_hit(centre_hit, p.get()));
    CHECK(centre_hit.t == Approx((centre - point(0, 0, 0)).length()).epsilon(1e-12));
    CHECK(wrong == 0);
}

TEST_CASE("polygon: rays from inside a box of six rectangular faces never escape through its edges or corners", "[02][polygon][polygons][watertight]") {
    const vector x = 1.7 * vector(0.6, 0, -0.8), y = 0.9 * vector(0.48, 0.6, 0.36), z = 1.3 * (x % y).unit();
    const point o(10.3, -4.4, 7.9);
    const auto corner = [&](int i, int j, int k) { return o + i * x + j * y + k * z; };
    std::vector<std::unique_ptr<primitive>> faces;
    faces.push_back(make_polygon({corner(0, 0, 0), corner(1, 0, 0), corner(1, 1, 0), corner(0, 1, 0)}));
    faces.push_back(make_polygon({corner(0, 0, 1), corner(0, 1, 1), corner(1, 1, 1), corner(1, 0, 1)}));
    faces.push_back(make_polygon({corner(0, 0, 0), corner(0, 0, 1), corner(1, 0, 1), corner(1, 0, 0)}));
    faces.push_back(make_polygon({corner(0, 1, 0), corner(1, 1, 0), corner(1, 1, 1), corner(0, 1, 1)}));
    faces.push_back(make_polygon({corner(0, 0, 0), corner(0, 1, 0), corner(0, 1, 1), corner(0, 0, 1)}));
    faces.push_back(make_polygon({corner(1, 0, 0), corner(1, 0, 1), corner(1, 1, 1), corner(1, 1, 0)}));
    const point middle = o + 0.5 * (x + y + z);
    sampler random(33);
    int leaks = 0;
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
        if (!any_hit(faces, through(from, target))) ++leaks;
    }
    CHECK(leaks == 0);
}

TEST_CASE("polygon: rays through the shared edges and the hub of a ring of quadrilaterals never slip through", "[02][polygon][polygons][watertight]") {
    // Six convex quadrilaterals around one hub vertex in a tilted plane, each sharing its
    // two spokes with its neighbours.
    const vector n = vector(0.2, 1, -0.3).unit();
    vector u, v;
    plane_axes(n, u, v);
    const point hub(-71.3, 20.9, 5.5);
    const std::vector<point> rim = regular(12, hub, 2.5, u, v, 0.13);
    std::vector<std::unique_ptr<primitive>> ring;
    for (int k = 0; k < 6; ++k) ring.push_back(make_polygon({hub, rim[2 * k], rim[2 * k + 1], rim[(2 * k + 2) % 12]}));
    sampler random(34);
    int leaks = 0;
    for (int k = 0; k < 20000; ++k) {
        const int spoke = 2 * (k % 6);
        const point target = k % 5 == 0 ? hub : hub + random.uniform(0.01, 0.99) * (rim[spoke] - hub);
        vector d = random.direction();
        if (std::fabs(d * n) < 0.2) d = d + 0.5 * (d * n < 0 ? -n : n);
        if (!any_hit(ring, through(target + random.uniform(1, 30) * d.unit(), target))) ++leaks;
    }
    CHECK(leaks == 0);
}

TEST_CASE("polygon: the normal of a twelve-sided polygon in a tilted plane follows its winding", "[02][polygon][polygons]") {
    const vector n = vector(-2, 0.5, 1.5).unit();
    vector u, v;
    plane_axes(n, u, v);
    std::vector<point> ring = regular(12, point(3, 4, 5), 1.7, u, v);
    const auto ccw = make_polygon(ring);
    std::rotate(ring.begin(), ring.begin() + 5, ring.end());
    const auto rotated = make_polygon(ring);
    std::reverse(ring.begin(), ring.end());
    const auto cw = make_polygon(ring);
    const point on = point(3, 4, 5) + 0.3 * u;
    for (const auto* p : {ccw.get(), rotated.get()}) {
        const vector m = p->normal(on);
        CHECK(m.x == Approx(n.x).epsilon(1e-12));
        CHECK(m.y == Approx(n.y).epsilon(1e-12));
        CHECK(m.z == Approx(n.z).epsilon(1e-12));
        CHECK(m.length() == Approx(1).epsilon(1e-14));
    }
    const vector m = cw->normal(on);
    CHECK(m.x == Approx(-n.x).epsilon(1e-12));
    CHECK(m.y == Approx(-n.y).epsilon(1e-12));
    CHECK(m.z == Approx(-n.z).epsilon(1e-12));
    CHECK_FALSE(ccw->contains(on));
}

TEST_CASE("polygon: its box is exactly the smallest one around the vertices of a tilted polygon", "[02][polygon][polygons]") {
    const std::vector<point> v = {point(1, 0, 0), point(3, 1, -1), point(4, 3, -3), point(2, 4, -4), point(0, 2, -2)};
    const auto p = make_polygon(v);
    CHECK(p->min_point() == point(0, 0, -4));
    CHECK(p->max_point() == point(4, 4, 0));
}

TEST_CASE("polygon: vertices written with seven decimals are accepted while a bent or dented polygon is refused", "[02][polygon][polygons]") {
    const vector n = vector(1, 2, 3).unit();
    vector u, v;
    plane_axes(n, u, v);
    std::vector<point> rounded = regular(7, point(0.5, -0.25, 1), 1, u, v);
    for (point& p : rounded) p = point(std::round(p.x * 1e7) / 1e7, std::round(p.y * 1e7) / 1e7, std::round(p.z * 1e7) / 1e7);
    CHECK_NOTHROW(make_polygon(rounded));
    std::vector<point> bent = rounded;
    bent[3] = bent[3] + 1e-3 * n;
    CHECK_THROWS_AS(make_polygon(bent), vl::usage_error);
    std::vector<point> dented = rounded;
    dented[4] = point(0.5, -0.25, 1) + 0.6 * (dented[4] - point(0.5, -0.25, 1));
    CHECK_THROWS_AS(make_polygon(dented), vl::usage_error);
    CHECK_THROWS_AS(make_polygon({point(0, 0, 0), point(1, 0, 0), point(1, 1, 0), point(1, 1, 0), point(0, 1, 0)}),
                    vl::usage_error);
}

TEST_CASE("polygon: an empty POLYGON in a scene file is the unit square facing plus z", "[02][polygon][polygons][detail]") {
    const auto p = read_one("POLYGON { }");
    const intersection i = p->intersect(ray(point(0.9, 0.9, 3), vector(0, 0, -1)));
    REQUIRE(clean_hit(i, p.get()));
    CHECK(i.t == Approx(3).epsilon(1e-12));
    CHECK(clean_miss(p->intersect(ray(point(1.1, 0.5, 3), vector(0, 0, -1)))));
    CHECK(p->normal(point(0.5, 0.5, 0)) == vector(0, 0, 1));
    CHECK(p->min_point() == point(0, 0, 0));
    CHECK(p->max_point() == point(1, 1, 0));
}

TEST_CASE("polygon: a POLYGON written by write reads back with its vertices in order and its surface", "[02][polygon][polygons]") {
    const auto first = read_one(
        "POLYGON { vertices (0.25, 0, 0) (1.5, 0.1, -0.14) (2, 1.3, -0.37) (1.1, 2.2, -0.415) (-0.3, 1.2, -0.125) "
        "color 0.3 0.6 0.9 zero_t 2e-6 }");
    const std::string out = text_of(*first);
    INFO("write() gave: " << out);
    const auto second = read_one(out);
    CHECK(second->type_name() == "POLYGON");
    CHECK(text_of(*second) == out);
    CHECK(second->clr() == first->clr());
    CHECK(second->zero_t() == first->zero_t());
    CHECK(second->min_point() == first->min_point());
    CHECK(second->max_point() == first->max_point());
    CHECK(second->normal(point(1, 1, 0)) == first->normal(point(1, 1, 0)));
    sampler random(35);
    int differ = 0, hits = 0;
    for (int k = 0; k < 300; ++k) {
        const point target(random.uniform(-0.5, 2.2), random.uniform(-0.2, 2.4), random.uniform(-0.5, 0));
        const ray r = through(random.in_box(6), target);
        const intersection i = first->intersect(r), j = second->intersect(r);
        if (i.hit() != j.hit() || i.t != j.t) ++differ;
        if (i.hit()) ++hits;
    }
    CHECK(differ == 0);
    CHECK(hits > 10);
}
