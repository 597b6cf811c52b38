// Hidden tests of stage 02's plane (grader only; students never see this file). Each
// TEST_CASE is one graded item; the tag [planes] puts it in the rubric's "planes" category.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <sstream>

#include "hidden_support.hh"
#include "vl/error.hh"

using vl::intersection;
using vl::point;
using vl::ray;
using vl::vector;
using vl::stage02::make_plane;
using namespace vl::stage02::hidden;

TEST_CASE("plane: a slanted ray meets a tilted plane where the plane equation says", "[02][plane][planes][essential]") {
    const point p0(1, -2, 0.5);
    const vector n(2, 3, -1);  // not unit
    const auto pl = make_plane(p0, n);
    sampler random(11);
    int wrong = 0, off_plane = 0;
    for (int k = 0; k < 500; ++k) {
        const point origin = random.in_box(10);
        const ray r(origin, random.direction());
        const double denominator = r.direction() * n;
        if (std::fabs(denominator) < 1e-3) continue;
        const double expected = ((p0 - origin) * n) / denominator;
        const intersection i = pl->intersect(r);
        if (expected > 1e-3) {
            if (!clean_hit(i, pl.get()) || std::fabs(i.t - expected) > 1e-9 * (1 + expected)) ++wrong;
            else if (std::fabs((r.t_point(i.t) - p0) * n.unit()) > 1e-9 * (1 + expected)) ++off_plane;
        } else if (expected < -1e-3 && !clean_miss(i)) {
            ++wrong;
        }
    }
    CHECK(wrong == 0);
    CHECK(off_plane == 0);
}

TEST_CASE("plane: a plane that lies behind the ray is never reported at a negative distance", "[02][plane][planes]") {
    sampler random(12);
    int reported = 0;
    for (int k = 0; k < 1000; ++k) {
        const point p0 = random.in_box(5);
        const vector n = random.direction();
        const auto pl = make_plane(p0, n);
        // The origin on one side, the direction pointing further away from the plane.
        const double side = k % 2 == 0 ? 1 : -1;
        const point origin = p0 + side * random.uniform(0.01, 50) * n;
        vector d = random.direction();
        if ((d * n) * side < 0) d = -d;
        if (std::fabs(d * n) < 1e-3) continue;
        if (!clean_miss(pl->intersect(ray(origin, d)))) ++reported;
    }
    CHECK(reported == 0);
}

TEST_CASE("plane: rays exactly parallel to a plane miss cleanly with no NaN and no infinity", "[02][plane][planes]") {
    // Normals and directions chosen so that d . n is exactly 0 in floating point.
    struct parallel_case {
        point on;
        vector normal, direction;
    };
    const parallel_case cases[] = {
        {point(0, 0, 0), vector(0, 1, 0), vector(1, 0, 0)},
        {point(3, -2, 7), vector(0, 0, -5), vector(1, 2, 0)},
        {point(-1, 4, 2), vector(1, 1, 0), vector(1, -1, 3)},
        {point(2, 2, 2), vector(0, 2, 2), vector(4, 1, -1)},
        {point(1e6, -1e6, 5), vector(7, 0, 0), vector(0, -1, 1)},
    };
    int wrong = 0;
    std::ostringstream first;
    for (const parallel_case& c : cases) {
        const auto pl = make_plane(c.on, c.normal);
        // Above, below and inside the plane, some far from the point it was given by.
        for (const double offset : {2.0, -2.0, 1e-9, -1e-9, 0.0}) {
            const point origin = c.on + offset * c.normal.unit() + 100 * (c.direction % c.normal).unit();
            const intersection i = pl->intersect(ray(origin, c.direction));
            if (clean_miss(i)) continue;
            if (wrong++ == 0)
                first << "normal " << c.normal << " direction " << c.direction << " offset " << offset << ": t = " << i.t;
        }
    }
    INFO("the first ray that did not miss: " << first.str());
    CHECK(wrong == 0);
}

TEST_CASE("plane: a ray lying in the plane is not reported for any of its points", "[02][plane][planes]") {
    const auto floor = make_plane(point(0, -3, 0), vector(0, 4, 0));
    int wrong = 0;
    std::ostringstream first;
    for (const vector d : {vector(1, 0, 0), vector(0, 0, -1), vector(3, 0, 4), vector(-1e-3, 0, 1e3)}) {
        const intersection i = floor->intersect(ray(point(17, -3, -5), d));
        if (!clean_miss(i) && wrong++ == 0) first << "direction " << d << ": t = " << i.t;
    }
    INFO("the first ray that did not miss: " << first.str());
    CHECK(wrong == 0);
}

TEST_CASE("plane: rays leaving a plane far from its given point at grazing angles do not hit it again", "[02][plane][planes]") {
    const point p0(250, -40, 120);
    const vector n = vector(0.2, 1, 0.35).unit();
    const auto pl = make_plane(p0, n);
    vector u, v;
    plane_axes(n, u, v);
    sampler random(13);
    int self_hits = 0;
    for (int k = 0; k < 3000; ++k) {
        const point origin = p0 + random.uniform(-500, 500) * u + random.uniform(-500, 500) * v;
        const double angle = std::pow(10.0, random.uniform(-4, -1)) * (k % 2 == 0 ? 1 : -1);
        const double turn = random.uniform(0, 2 * std::numbers::pi);
        const vector along = std::cos(turn) * u + std::sin(turn) * v;
        const vector d = std::cos(angle) * along + std::sin(angle) * n;
        if (!clean_miss(pl->intersect(ray(origin, d)))) ++self_hits;
    }
    CHECK(self_hits == 0);
}

TEST_CASE("plane: a plane a million units away is met with full relative precision", "[02][plane][planes]") {
    const vector n = vector(-0.3, 0.2, 1).unit();
    const point p0 = point(0, 0, 0) + 1e6 * vector(0.1, -0.05, -1).unit();
    const auto pl = make_plane(p0, n);
    sampler random(14);
    int wrong = 0;
    for (int k = 0; k < 200; ++k) {
        const point target = p0 + random.uniform(-1e4, 1e4) * (n % vector(1, 0, 0)).unit() +
                             random.uniform(-1e4, 1e4) * (n % vector(0, 1, 0)).unit();
        const ray r = through(point(0, 0, 0), target);
        const double expected = (target - point(0, 0, 0)).length();
        const intersection i = pl->intersect(r);
        if (!clean_hit(i, pl.get()) || std::fabs(i.t - expected) > 1e-10 * expected) ++wrong;
    }
    CHECK(wrong == 0);
}

TEST_CASE("plane: a ray a hair below the horizon hits far away and a hair above it misses", "[02][plane][planes]") {
    const auto ground = make_plane(point(0, 0, 0), vector(0, 1, 0));
    int wrong = 0;
    std::ostringstream first;
    for (const double slope : {1e-5, 1e-8, 1e-11}) {
        const intersection down = ground->intersect(ray(point(0, 2, 0), vector(1, -slope, 0)));
        const intersection up = ground->intersect(ray(point(0, 2, 0), vector(1, slope, 0)));
        const bool right = clean_hit(down, ground.get()) && std::fabs(down.t - 2 / slope) <= 1e-6 * (2 / slope) &&
                           clean_miss(up);
        if (!right && wrong++ == 0)
            first << "slope " << slope << ": below t = " << down.t << " (should be " << 2 / slope << "), above t = " << up.t
                  << " (should miss)";
    }
    INFO("the first wrong answer: " << first.str());
    CHECK(wrong == 0);
}

TEST_CASE("plane: its normal is the given direction scaled to length one at every point", "[02][plane][planes]") {
    const auto tiny = make_plane(point(0, 0, 0), vector(0, 1e-3, 0));
    const auto big = make_plane(point(5, 5, 5), vector(3e4, -4e4, 0));
    sampler random(15);
    int wrong = 0, inside = 0;
    for (int k = 0; k < 20; ++k) {
        const point p = random.in_box(100);
        const vector a = tiny->normal(p), b = big->normal(p);
        if ((a - vector(0, 1, 0)).length() > 1e-15 || (b - vector(0.6, -0.8, 0)).length() > 1e-14) ++wrong;
        if (big->contains(p) || tiny->contains(p)) ++inside;
    }
    INFO("normals at the origin: " << tiny->normal(point(0, 0, 0)) << " (should be (0, 1, 0)) and "
                                    << big->normal(point(0, 0, 0)) << " (should be (0.6, -0.8, 0))");
    CHECK(wrong == 0);
    CHECK(inside == 0);
}

TEST_CASE("plane: an unbounded plane reports NaN for every coordinate of its box", "[02][plane][planes]") {
    const auto pl = make_plane(point(1, 2, 3), vector(0, 0, 1));
    const point lo = pl->min_point(), hi = pl->max_point();
    CHECK(std::isnan(lo.x));
    CHECK(std::isnan(lo.y));
    CHECK(std::isnan(lo.z));
    CHECK(std::isnan(hi.x));
    CHECK(std::isnan(hi.y));
    CHECK(std::isnan(hi.z));
}

TEST_CASE("plane: make_plane refuses a normal or a point that is not finite", "[02][plane][planes]") {
    const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
    CHECK_THROWS_AS(make_plane(point(0, 0, 0), vector(nan, 1, 0)), vl::usage_error);
    CHECK_THROWS_AS(make_plane(point(0, 0, 0), vector(0, inf, 0)), vl::usage_error);
    CHECK_THROWS_AS(make_plane(point(inf, 0, 0), vector(0, 1, 0)), vl::usage_error);
    CHECK_THROWS_AS(make_plane(point(0, nan, 0), vector(0, 1, 0)), vl::usage_error);
    CHECK_NOTHROW(make_plane(point(0, 0, 0), vector(1e-5, 0, 0)));
}

TEST_CASE("plane: an empty PLANE in a scene file is the floor through the origin facing up", "[02][plane][planes][detail]") {
    const auto pl = read_one("PLANE { }");
    const intersection i = pl->intersect(ray(point(3, 1.5, -2), vector(0, -1, 0)));
    REQUIRE(clean_hit(i, pl.get()));
    CHECK(i.t == Approx(1.5).epsilon(1e-12));
    CHECK(pl->normal(point(3, 0, -2)) == vector(0, 1, 0));
}

TEST_CASE("plane: a PLANE written by write reads back with the same point and normal and surface", "[02][plane][planes]") {
    const auto first = read_one("PLANE { point 0.1 -2.7 1e3 normal 1 -3 0.25 color 0.2 0.4 0.6 zero_t 1e-5 }");
    const std::string out = text_of(*first);
    INFO("write() gave: " << out);
    const auto second = read_one(out);
    CHECK(second->type_name() == "PLANE");
    CHECK(text_of(*second) == out);
    CHECK(second->clr() == first->clr());
    CHECK(second->zero_t() == first->zero_t());
    CHECK(second->normal(point(0, 0, 0)) == first->normal(point(0, 0, 0)));
    sampler random(16);
    int differ = 0, hits = 0;
    for (int k = 0; k < 100; ++k) {
        const ray r(random.in_box(50), random.direction());
        const intersection a = first->intersect(r), b = second->intersect(r);
        if (a.hit() != b.hit() || a.t != b.t) ++differ;
        if (a.hit()) ++hits;
    }
    CHECK(differ == 0);
    CHECK(hits > 10);
}
