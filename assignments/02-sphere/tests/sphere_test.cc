// Public tests of the sphere (stage_02.hh, sphere.cc). Run them with `ctest -L 02-sphere`.
#include "vl/catch.hh"
#include <cmath>

#include "test_support.hh"

using namespace vl;
using namespace vl::stage02;
using namespace vl::stage02::testing;

TEST_CASE("sphere: a ray from outside hits the near side at the right distance", "[02][sphere]") {
    const auto s = make_sphere(point(0, 0, -5), 1);
    const intersection i = s->intersect(ray(point(0, 0, 0), vector(0, 0, -1)));
    REQUIRE(i.hit());
    CHECK(i.object == s.get());
    CHECK(i.t == Approx(4));

    // Off the axis: the hit point must lie on the sphere, on the side facing the ray.
    const ray r = ray_through(point(3, 2, 1), point(0.3, -0.2, -4.6));
    const intersection j = s->intersect(r);
    REQUIRE(j.hit());
    CHECK(distance(r.t_point(j.t), point(0, 0, -5)) == Approx(1));
    CHECK(s->normal(r.t_point(j.t)) * r.direction() < 0);
}

TEST_CASE("sphere: rays that pass beside it or point away miss", "[02][sphere]") {
    const auto s = make_sphere(point(0, 0, -5), 1);
    CHECK(s->intersect(ray(point(0, 0, 0), vector(0, 0, 1))).is_miss());        // pointing away
    CHECK(s->intersect(ray(point(0, 1.5, 0), vector(0, 0, -1))).is_miss());     // beside it
    CHECK(s->intersect(ray(point(0, 0, -10), vector(0, 0, -1))).is_miss());     // past it, moving on
    CHECK(s->intersect(ray(point(5, 5, 5), vector(1, 1, 1))).is_miss());
}

TEST_CASE("sphere: a ray from inside hits the far side", "[02][sphere]") {
    const auto s = make_sphere(point(1, 2, 3), 2);
    const intersection from_center = s->intersect(ray(point(1, 2, 3), vector(0, 1, 0)));
    REQUIRE(from_center.hit());
    CHECK(from_center.t == Approx(2));

    const ray r(point(1.5, 2, 3), vector(-1, 0, 0));  // 0.5 off the centre, looking back past it
    const intersection i = s->intersect(r);
    REQUIRE(i.hit());
    CHECK(i.t == Approx(2.5));
    CHECK(s->contains(r.origin()));
}

TEST_CASE("sphere: the normal is unit and points outward", "[02][sphere]") {
    const auto s = make_sphere(point(1, -2, 0.5), 3);
    random_numbers random;
    for (int k = 0; k < 100; ++k) {
        const vector u = random.direction();
        const point p = point(1, -2, 0.5) + 3 * u;
        const vector n = s->normal(p);
        CHECK(n.length() == Approx(1));
        CHECK(n * u == Approx(1));
    }
}

TEST_CASE("sphere: contains is true strictly inside and false outside", "[02][sphere]") {
    const auto s = make_sphere(point(0, 1, 0), 2);
    CHECK(s->contains(point(0, 1, 0)));
    CHECK(s->contains(point(1.9, 1, 0)));
    CHECK(s->contains(point(0, -0.99, 0)));
    CHECK_FALSE(s->contains(point(2.1, 1, 0)));
    CHECK_FALSE(s->contains(point(0, 3.5, 0)));
    CHECK_FALSE(s->contains(point(100, 100, 100)));
}

TEST_CASE("sphere: min_point and max_point are the corners of its box", "[02][sphere]") {
    const auto s = make_sphere(point(1, 2, 3), 0.5);
    CHECK(s->min_point() == point(0.5, 1.5, 2.5));
    CHECK(s->max_point() == point(1.5, 2.5, 3.5));
}

TEST_CASE("sphere: a hit at or below zero_t is not a hit even when zero_t is negative", "[02][sphere]") {
    // Along -z from the origin the sphere is entered at t = 0.3 and left at t = 2.3.
    const auto s = make_sphere(point(0, 0, -1.3), 1);
    const ray r(point(0, 0, 0), vector(0, 0, -1));
    CHECK(s->intersect(r).t == Approx(0.3));
    s->set_surface(with_zero_t(0.5));
    CHECK(s->intersect(r).t == Approx(2.3));
    s->set_surface(with_zero_t(-0.5));  // negative: seen from inside; its absolute value counts
    CHECK(s->intersect(r).t == Approx(2.3));
    s->set_surface(with_zero_t(3));
    CHECK(s->intersect(r).is_miss());
}

TEST_CASE("sphere: a ray leaving the surface does not hit it again (no acne)", "[02][sphere][stability]") {
    // The origins are computed points on the surface, so each is off by round-off: a
    // test against t > 0 instead of t > zero_t() finds the sphere again at t ~ 1e-16.
    const point c(0.3, -7.1, 2.2);
    const double radius = 4.7;
    const auto s = make_sphere(c, radius);
    random_numbers random;
    int self_hits = 0, wrong_far_side = 0;
    for (int k = 0; k < 2000; ++k) {
        const vector u = random.direction();
        const point on_surface = c + radius * u;
        vector d = random.direction();
        if (d * u > 0) {  // outward: nothing left to hit
            if (s->intersect(ray(on_surface, d)).hit()) ++self_hits;
        } else if (d * u < -0.01) {  // inward: the far side, at the chord's length
            const intersection i = s->intersect(ray(on_surface, d));
            const double chord = -2 * radius * (d * u);
            if (!i.hit() || std::fabs(i.t - chord) > 1e-9 * radius) ++wrong_far_side;
        }
    }
    CHECK(self_hits == 0);
    CHECK(wrong_far_side == 0);
}

TEST_CASE("sphere: a small sphere far away is hit exactly even near its rim", "[02][sphere][stability]") {
    // Radius 1 at a distance of 1e6: the textbook discriminant b^2 - 4ac subtracts two
    // numbers near 4e12 and keeps only a few correct digits. Rays aimed just inside and
    // just outside the rim must hit and miss, and a hit must lie on the sphere.
    const point c(6e5, 8e5, 0.3);
    const auto s = make_sphere(c, 1);
    const point eye(0, 0, 0);
    const vector towards = (c - eye).unit();
    const vector side = (towards % vector(0, 0, 1)).unit();
    random_numbers random;
    int wrong_hit_or_miss = 0, off_surface = 0;
    for (int k = 0; k < 1000; ++k) {
        const double offset = k % 2 == 0 ? random.uniform(0.998, 0.9999) : random.uniform(1.0001, 1.002);
        const ray r = ray_through(eye, c + offset * side);
        const intersection i = s->intersect(r);
        if (i.hit() != (offset < 1)) ++wrong_hit_or_miss;
        else if (i.hit() && std::fabs(distance(r.t_point(i.t), c) - 1) > 1e-6) ++off_surface;
    }
    CHECK(wrong_hit_or_miss == 0);
    CHECK(off_surface == 0);
}

TEST_CASE("sphere: grazing rays hit just inside the silhouette and miss just outside", "[02][sphere][stability]") {
    const auto s = make_sphere(point(0, 0, -10), 2);
    for (const double margin : {1e-3, 1e-6, 1e-9}) {
        CAPTURE(margin);
        const intersection inside = s->intersect(ray(point(0, 2 - margin, 0), vector(0, 0, -1)));
        REQUIRE(inside.hit());
        const double half_chord = std::sqrt(margin * (4 - margin));  // sqrt(r^2 - y^2), y = 2 - margin
        CHECK(inside.t == Approx(10 - half_chord).epsilon(1e-11));
        CHECK(s->intersect(ray(point(0, 2 + margin, 0), vector(0, 0, -1))).is_miss());
    }
    // Exactly tangent: a hit or a miss are both right, but a hit must be a number.
    const intersection tangent = s->intersect(ray(point(0, 2, 0), vector(0, 0, -1)));
    if (tangent.hit()) CHECK(tangent.t == Approx(10).margin(1e-3));
}

TEST_CASE("sphere: make_sphere refuses a radius that is not positive", "[02][sphere]") {
    CHECK_THROWS_AS(make_sphere(point(0, 0, 0), 0), usage_error);
    CHECK_THROWS_AS(make_sphere(point(0, 0, 0), -1), usage_error);
}
