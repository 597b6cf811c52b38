// Public tests of the triangle (stage_02.hh, triangle.cc). Run them with `ctest -L 02-sphere`.
#include "vl/catch.hh"
#include <cmath>
#include <memory>
#include <numbers>
#include <vector>

#include "test_support.hh"

using namespace vl;
using namespace vl::stage02;
using namespace vl::stage02::testing;

TEST_CASE("triangle: a ray through the inside hits at the right distance from the front and from behind", "[02][triangle]") {
    const auto tri = make_triangle(point(0, 0, -2), point(2, 0, -2), point(0, 2, -2));
    const intersection front = tri->intersect(ray(point(0.5, 0.5, 0), vector(0, 0, -1)));
    REQUIRE(front.hit());
    CHECK(front.object == tri.get());
    CHECK(front.t == Approx(2));

    const intersection back = tri->intersect(ray(point(0.5, 0.5, -5), vector(0, 0, 1)));
    REQUIRE(back.hit());
    CHECK(back.t == Approx(3));

    const ray slanted = ray_through(point(4, -3, 6), point(0.2, 1.1, -2));
    const intersection i = tri->intersect(slanted);
    REQUIRE(i.hit());
    CHECK(distance(slanted.t_point(i.t), point(0.2, 1.1, -2)) == Approx(0).margin(1e-12));
}

TEST_CASE("triangle: rays just outside each edge and beyond each vertex miss", "[02][triangle]") {
    const auto tri = make_triangle(point(0, 0, 0), point(2, 0, 0), point(0, 2, 0));
    const vector down(0, 0, -1);
    CHECK(tri->intersect(ray(point(1, -1e-6, 1), down)).is_miss());       // below edge a-b
    CHECK(tri->intersect(ray(point(-1e-6, 1, 1), down)).is_miss());       // left of edge c-a
    CHECK(tri->intersect(ray(point(1.000001, 1, 1), down)).is_miss());    // beyond edge b-c
    CHECK(tri->intersect(ray(point(2.1, 0, 1), down)).is_miss());         // beyond vertex b
    CHECK(tri->intersect(ray(point(-0.1, -0.1, 1), down)).is_miss());     // beyond vertex a
    CHECK(tri->intersect(ray(point(1, 1e-6, 1), down)).hit());            // just inside a-b
    CHECK(tri->intersect(ray(point(0.999999, 1, 1), down)).hit());        // just inside b-c
    CHECK(tri->intersect(ray(point(0.5, 0.5, -1), down)).is_miss());      // behind the ray
}

TEST_CASE("triangle: the normal follows the counter-clockwise winding and the box holds the vertices", "[02][triangle]") {
    const auto ccw = make_triangle(point(0, 0, 0), point(1, 0, 0), point(0, 1, 0));
    const auto cw = make_triangle(point(0, 0, 0), point(0, 1, 0), point(1, 0, 0));
    CHECK(ccw->normal(point(0.2, 0.2, 0)) == vector(0, 0, 1));
    CHECK(cw->normal(point(0.2, 0.2, 0)) == vector(0, 0, -1));

    const auto tilted = make_triangle(point(1, 0, 0), point(0, 1, 0), point(0, 0, 1));
    const vector n = tilted->normal(point(1.0 / 3, 1.0 / 3, 1.0 / 3));
    CHECK(n.x == Approx(1 / std::sqrt(3.0)));
    CHECK(n.y == Approx(1 / std::sqrt(3.0)));
    CHECK(n.z == Approx(1 / std::sqrt(3.0)));
    CHECK_FALSE(tilted->contains(point(0.1, 0.1, 0.1)));

    const auto t = make_triangle(point(1, -2, 3), point(-4, 5, 0), point(2, 2, -6));
    CHECK(t->min_point() == point(-4, -2, -6));
    CHECK(t->max_point() == point(2, 5, 3));
    CHECK_THROWS_AS(make_triangle(point(0, 0, 0), point(1, 1, 1), point(2, 2, 2)), usage_error);
}

TEST_CASE("triangle: a ray in or parallel to the triangle's plane misses", "[02][triangle][stability]") {
    const auto tri = make_triangle(point(0, 0, 0), point(2, 0, 0), point(0, 2, 0));
    CHECK(tri->intersect(ray(point(-1, 0.5, 0), vector(1, 0, 0))).is_miss());  // in the plane, across it
    CHECK(tri->intersect(ray(point(-1, 0.5, 1), vector(1, 0, 0))).is_miss());  // above it
}

TEST_CASE("triangle: a ray leaving the triangle does not hit it again (no acne)", "[02][triangle][stability]") {
    const point a(0.3, -1.2, 4.1), b(7.7, 0.4, 3.3), c(-2.9, 5.5, -1.6);
    const auto tri = make_triangle(a, b, c);
    random_numbers random;
    int self_hits = 0;
    for (int k = 0; k < 2000; ++k) {
        double u = random.uniform(0, 1), v = random.uniform(0, 1);
        if (u + v > 1) u = 1 - u, v = 1 - v;
        const point on = a + u * (b - a) + v * (c - a);
        if (tri->intersect(ray(on, random.direction())).hit()) ++self_hits;
    }
    CHECK(self_hits == 0);
}

TEST_CASE("triangle: rays through the shared edge of two triangles never pass between them", "[02][triangle][stability][watertight]") {
    // Random quads a b c d split along b-d into a b d and b c d (the same winding). Each
    // ray is aimed at a point of the shared edge b-d. A test that compares barycentric
    // coordinates with 0 and 1 (Moeller-Trumbore) lets about one such ray in seven
    // through; a watertight test lets none.
    random_numbers random;
    int leaks = 0, tried = 0;
    for (int k = 0; k < 20000; ++k) {
        const point a = random.in_cube(1), b = random.in_cube(1), c = random.in_cube(1), d = random.in_cube(1);
        const vector n1 = (b - a) % (d - a), n2 = (c - b) % (d - b);
        if (n1 * n2 <= 0 || n1.length() < 1e-3 || n2.length() < 1e-3) continue;  // keep folds under 90 degrees
        const auto first = make_triangle(a, b, d), second = make_triangle(b, c, d);
        const point on_edge = b + random.uniform(0.01, 0.99) * (d - b);
        const point origin = on_edge + 5 * (n1 + n2).unit() + random.offset(2);
        const ray r = ray_through(origin, on_edge);
        const double c1 = r.direction() * n1.unit(), c2 = r.direction() * n2.unit();
        if (c1 * c2 <= 0 || std::fabs(c1) < 0.05 || std::fabs(c2) < 0.05) continue;  // across both, not along the fold
        ++tried;
        if (!first->intersect(r).hit() && !second->intersect(r).hit()) ++leaks;
    }
    CAPTURE(tried);
    CHECK(tried > 5000);
    CHECK(leaks == 0);
}

TEST_CASE("triangle: rays through a vertex shared by a fan of triangles never pass between them", "[02][triangle][stability][watertight]") {
    // Seven triangles around one vertex, a slightly bumpy disc; every ray through the
    // shared vertex crosses the disc there, so it must hit at least one of them.
    const point center(0.37, -0.21, 1.13);
    std::vector<point> rim;
    for (int k = 0; k < 7; ++k) {
        const double angle = 2 * std::numbers::pi * k / 7 + 0.1;
        rim.push_back(center + vector(std::cos(angle), std::sin(angle), 0.1 * std::sin(3.0 * k)));
    }
    std::vector<std::unique_ptr<primitive>> fan;
    for (std::size_t k = 0; k < rim.size(); ++k) fan.push_back(make_triangle(center, rim[k], rim[(k + 1) % rim.size()]));
    random_numbers random;
    int leaks = 0;
    for (int k = 0; k < 5000; ++k) {
        vector d = random.direction();
        if (std::fabs(d.z) < 0.5) continue;  // well across the disc
        const point origin = center + random.uniform(0.5, 20) * d;
        const ray r = ray_through(origin, center);
        bool hit = false;
        for (const auto& t : fan) hit = hit || t->intersect(r).hit();
        if (!hit) ++leaks;
    }
    CHECK(leaks == 0);
}
