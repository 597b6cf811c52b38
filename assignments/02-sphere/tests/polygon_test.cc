// Public tests of the convex polygon (stage_02.hh, polygon.cc). Run them with `ctest -L 02-sphere`.
#include "vl/catch.hh"
#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <vector>

#include "test_support.hh"

using namespace vl;
using namespace vl::stage02;
using namespace vl::stage02::testing;

namespace {

// A regular pentagon of radius 1 around (0, 0, z), counter-clockwise seen from +z.
std::vector<point> pentagon(double z) {
    std::vector<point> v;
    for (int k = 0; k < 5; ++k) {
        const double angle = 2 * std::numbers::pi * k / 5;
        v.emplace_back(std::cos(angle), std::sin(angle), z);
    }
    return v;
}

}  // namespace

TEST_CASE("polygon: a ray through a convex pentagon hits it and rays beside it miss", "[02][polygon]") {
    const auto p = make_polygon(pentagon(-3));
    const intersection i = p->intersect(ray(point(0.2, -0.3, 0), vector(0, 0, -1)));
    REQUIRE(i.hit());
    CHECK(i.object == p.get());
    CHECK(i.t == Approx(3));
    CHECK(p->intersect(ray(point(0.2, -0.3, -6), vector(0, 0, 1))).t == Approx(3));  // from behind
    CHECK(p->intersect(ray(point(0.95, 0.3, 0), vector(0, 0, -1))).is_miss());     // outside edge 1-2
    CHECK(p->intersect(ray(point(-0.85, 0, 0), vector(0, 0, -1))).is_miss());      // outside edge 3-4
    CHECK(p->intersect(ray(point(0, 0, -4), vector(0, 0, -1))).is_miss());         // past it
    CHECK(p->intersect(ray(point(-2, 0, -3), vector(1, 0, 0))).is_miss());         // in its plane
}

TEST_CASE("polygon: the normal follows the counter-clockwise winding and the box holds the vertices", "[02][polygon]") {
    std::vector<point> v = pentagon(2);
    const auto ccw = make_polygon(v);
    CHECK(ccw->normal(point(0, 0, 2)).z == Approx(1));
    CHECK(ccw->normal(point(0, 0, 2)).length() == Approx(1));
    std::reverse(v.begin(), v.end());
    CHECK(make_polygon(v)->normal(point(0, 0, 2)).z == Approx(-1));
    CHECK_FALSE(ccw->contains(point(0, 0, 2)));
    CHECK(ccw->min_point().x == Approx(std::cos(4 * std::numbers::pi / 5)));
    CHECK(ccw->min_point().z == 2);
    CHECK(ccw->max_point().x == 1);
    CHECK(ccw->max_point().y == Approx(std::sin(2 * std::numbers::pi / 5)));
}

TEST_CASE("polygon: make_polygon refuses non-planar or non-convex or degenerate vertices", "[02][polygon]") {
    const point a(0, 0, 0), b(1, 0, 0), c(1, 1, 0), d(0, 1, 0);
    CHECK_NOTHROW(make_polygon({a, b, c, d}));
    CHECK_THROWS_AS(make_polygon({a, b}), usage_error);                                // too few
    CHECK_THROWS_AS(make_polygon({a, b, point(1, 1, 0.2), d}), usage_error);           // not planar
    CHECK_THROWS_AS(make_polygon({a, b, point(0.3, 0.3, 0), d}), usage_error);         // not convex
    CHECK_THROWS_AS(make_polygon({a, b, b, c}), usage_error);                          // a repeated vertex
    CHECK_THROWS_AS(make_polygon({a, b, point(2, 0, 0)}), usage_error);                // on one line
}

TEST_CASE("polygon: the faces of a cube leave no gap at their edges and corners", "[02][polygon][stability][watertight]") {
    // A tilted cube of six squares; rays aimed at its edges and corners from outside
    // must hit at least one face.
    const vector x = vector(0.8, 0.6, 0), y = vector(-0.48, 0.64, 0.6), z = x % y;
    const point o(0.3, -0.7, 0.2);
    const auto corner = [&](int i, int j, int k) { return o + i * x + j * y + k * z; };
    const std::vector<std::unique_ptr<primitive>> faces = box_of_polygons(o, x, y, z, true);
    const point middle = corner(0, 0, 0) + 0.5 * (x + y + z);
    random_numbers random;
    int leaks = 0;
    for (int k = 0; k < 5000; ++k) {
        // A point on a random edge (or a corner, every fifth ray).
        const int axis = k % 3;
        const double along = k % 5 == 0 ? 0 : random.uniform(0, 1);
        const int s = static_cast<int>(random.uniform(0, 2)), t = static_cast<int>(random.uniform(0, 2));
        const int i = axis == 0 ? 0 : s, j = axis == 1 ? 0 : (axis == 0 ? s : t), l = axis == 2 ? 0 : t;
        const vector along_edge = axis == 0 ? x : axis == 1 ? y : z;
        const point target = corner(i, j, l) + along * along_edge;
        // From outside, through the target, on towards a point near the middle: the ray
        // enters the cube there (it does not merely graze an edge).
        const ray r = ray_through(target - 10 * (middle + random.offset(0.3) - target).unit(), target);
        bool hit = false;
        for (const auto& f : faces) hit = hit || f->intersect(r).hit();
        if (!hit) ++leaks;
    }
    CHECK(leaks == 0);
}
