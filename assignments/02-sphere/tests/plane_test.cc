// Public tests of the plane (stage_02.hh, plane.cc). Run them with `ctest -L 02-sphere`.
#include "vl/catch.hh"
#include <cmath>

#include "test_support.hh"

using namespace vl;
using namespace vl::stage02;
using namespace vl::stage02::testing;

TEST_CASE("plane: a ray towards the plane hits it at the right distance from either side", "[02][plane]") {
    const auto p = make_plane(point(0, -1, 0), vector(0, 2, 0));  // y = -1; the normal need not be unit
    const intersection from_above = p->intersect(ray(point(0, 3, 0), vector(0, -1, 0)));
    REQUIRE(from_above.hit());
    CHECK(from_above.object == p.get());
    CHECK(from_above.t == Approx(4));

    const intersection from_below = p->intersect(ray(point(5, -3, 2), vector(0, 1, 0)));
    REQUIRE(from_below.hit());
    CHECK(from_below.t == Approx(2));

    const ray slanted = ray_through(point(1, 1, 1), point(2, -1, 3));
    const intersection i = p->intersect(slanted);
    REQUIRE(i.hit());
    CHECK(slanted.t_point(i.t).y == Approx(-1));
    CHECK(p->intersect(ray(point(0, 3, 0), vector(0, 1, 0))).is_miss());  // moving away
}

TEST_CASE("plane: a ray parallel to the plane or lying in it misses", "[02][plane][stability]") {
    const auto p = make_plane(point(1, 2, 3), vector(1, 1, 1));
    const vector along = vector(1, -1, 0).unit();  // perpendicular to the normal
    CHECK(p->intersect(ray(point(0, 0, 0), along)).is_miss());  // beside the plane
    CHECK(p->intersect(ray(point(1, 2, 3), along)).is_miss());  // in the plane
    CHECK(p->intersect(ray(point(1, 2, 3), vector(0, 0, 1) % vector(1, 1, 1))).is_miss());
}

TEST_CASE("plane: a nearly parallel ray hits far away at a finite distance", "[02][plane][stability]") {
    const auto p = make_plane(point(0, 0, 0), vector(0, 1, 0));
    const intersection i = p->intersect(ray(point(0, 1, 0), vector(1, -1e-9, 0)));
    REQUIRE(i.hit());
    CHECK(std::isfinite(i.t));
    CHECK(i.t == Approx(1e9).epsilon(1e-6));
}

TEST_CASE("plane: a ray starting on the plane does not hit it again (no acne)", "[02][plane][stability]") {
    const point on(0.1, 0.7, -0.3);
    const vector n = vector(0.3, 1, -0.2);
    const auto p = make_plane(on, n);
    const vector u = (n % vector(1, 0, 0)).unit(), v = (n % u).unit();  // in the plane
    random_numbers random;
    int self_hits = 0;
    for (int k = 0; k < 2000; ++k) {
        const point origin = on + random.uniform(-100, 100) * u + random.uniform(-100, 100) * v;
        if (p->intersect(ray(origin, random.direction())).hit()) ++self_hits;
    }
    CHECK(self_hits == 0);
}

TEST_CASE("plane: the normal is the given one made unit and a plane has no inside and no box", "[02][plane]") {
    const auto p = make_plane(point(0, 0, 0), vector(0, 0, -3));
    CHECK(p->normal(point(7, -2, 0)) == vector(0, 0, -1));
    CHECK(p->normal(point(0, 0, 0)) == vector(0, 0, -1));
    CHECK_FALSE(p->contains(point(0, 0, 1)));
    CHECK_FALSE(p->contains(point(0, 0, -1)));
    CHECK(std::isnan(p->min_point().x));
    CHECK(std::isnan(p->max_point().x));
    CHECK_THROWS_AS(make_plane(point(0, 0, 0), vector(0, 0, 0)), usage_error);
}
