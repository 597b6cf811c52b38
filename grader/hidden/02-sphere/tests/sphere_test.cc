// Hidden tests of stage 02's sphere (grader only; students never see this file). Each
// TEST_CASE is one graded item; its tags name the rubric category (rubric.toml).
#include <catch2/catch.hpp>

#include <cmath>
#include <sstream>

#include "stage_02.hh"
#include "vl/error.hh"
#include "vl/registry.hh"
#include "vl/scene.hh"

using vl::point;
using vl::ray;
using vl::vector;
using vl::stage02::make_sphere;

namespace {

double hit_t(const vl::rtab_component& s, const ray& r) {
    const vl::intersection i = s.intersect(r);
    return i.hit() ? i.t : -1;
}

}  // namespace

// --- hits: rays from outside ------------------------------------------------------------

TEST_CASE("sphere: a ray towards the centre hits the near side", "[02][sphere][hits][essential]") {
    const auto s = make_sphere(point(0, 0, -5), 1);
    const vl::intersection i = s->intersect(ray(point(0, 0, 0), vector(0, 0, -1)));
    REQUIRE(i.hit());
    CHECK(i.t == Approx(4).epsilon(1e-12));
    CHECK(i.object == s.get());
}

TEST_CASE("sphere: an off-centre ray hits where the geometry says", "[02][sphere][hits][essential]") {
    const auto s = make_sphere(point(1, 2, 3), 2);
    // Through (1, 3, 3 + sqrt(3)) on the sphere, from straight above the hit along -z.
    const double t = hit_t(*s, ray(point(1, 3, 10), vector(0, 0, -1)));
    CHECK(t == Approx(10 - (3 + std::sqrt(3.0))).epsilon(1e-12));
}

TEST_CASE("sphere: rays that pass beside it miss", "[02][sphere][hits][essential]") {
    const auto s = make_sphere(point(0, 0, 0), 1);
    CHECK_FALSE(s->intersect(ray(point(0, 1.0001, 5), vector(0, 0, -1))).hit());
    CHECK_FALSE(s->intersect(ray(point(2, 2, 2), vector(1, 1, 0))).hit());
}

TEST_CASE("sphere: a sphere behind the ray is not hit", "[02][sphere][hits][essential]") {
    const auto s = make_sphere(point(0, 0, 5), 1);
    CHECK_FALSE(s->intersect(ray(point(0, 0, 0), vector(0, 0, -1))).hit());
}

TEST_CASE("sphere: the hit distance does not depend on the ray's direction's length", "[02][sphere][hits][essential]") {
    const auto s = make_sphere(point(0, 0, -10), 2);
    CHECK(hit_t(*s, ray(point(0, 0, 0), vector(0, 0, -1e-3))) == Approx(8).epsilon(1e-12));
    CHECK(hit_t(*s, ray(point(0, 0, 0), vector(0, 0, -1e3))) == Approx(8).epsilon(1e-12));
}

// --- inside: rays that start inside or on the sphere ----------------------------------

TEST_CASE("sphere: a ray from the centre hits the far side", "[02][sphere][inside]") {
    const auto s = make_sphere(point(0, 0, 0), 2);
    CHECK(hit_t(*s, ray(point(0, 0, 0), vector(1, 0, 0))) == Approx(2).epsilon(1e-12));
}

TEST_CASE("sphere: a ray from inside, off centre, hits the far side ahead", "[02][sphere][inside]") {
    const auto s = make_sphere(point(0, 0, 0), 1);
    CHECK(hit_t(*s, ray(point(0.5, 0, 0), vector(-1, 0, 0))) == Approx(1.5).epsilon(1e-12));
    CHECK(hit_t(*s, ray(point(0.5, 0, 0), vector(1, 0, 0))) == Approx(0.5).epsilon(1e-12));
}

TEST_CASE("sphere: a ray leaving the surface outwards does not hit it again", "[02][sphere][inside]") {
    const auto s = make_sphere(point(0.1, 0.2, 0.3), 0.7);
    for (int k = 0; k < 50; ++k) {
        const double a = 0.3 * k, b = 0.17 * k;
        const vector n(std::cos(a) * std::cos(b), std::sin(a) * std::cos(b), std::sin(b));
        const point p = point(0.1, 0.2, 0.3) + 0.7 * n;
        INFO("leaving at " << p);
        CHECK_FALSE(s->intersect(ray(p, n + vector(0.1, -0.05, 0.02))).hit());
    }
}

TEST_CASE("sphere: a ray entering at the surface hits the far side, not its origin", "[02][sphere][inside]") {
    const auto s = make_sphere(point(0, 0, 0), 3);
    CHECK(hit_t(*s, ray(point(3, 0, 0), vector(-1, 0, 0))) == Approx(6).epsilon(1e-9));
    CHECK(hit_t(*s, ray(point(0, -3, 0), vector(0, 1, 0))) == Approx(6).epsilon(1e-9));
}

// --- precision: where the textbook quadratic loses digits --------------------------------

TEST_CASE("sphere: a small sphere far away is hit accurately", "[02][sphere][precision]") {
    // The textbook discriminant b^2 - c subtracts two numbers of size 1e12 to find one of
    // size 1e-4: no digit survives (Ray Tracing Gems ch. 7).
    const auto s = make_sphere(point(0, 0, -1e6), 0.01);
    const double t = hit_t(*s, ray(point(0, 0, 0), vector(0, 0, -1)));
    CHECK(t == Approx(1e6 - 0.01).epsilon(1e-12));
    const double t_off = hit_t(*s, ray(point(0.006, 0, 0), vector(0, 0, -1)));
    CHECK(t_off == Approx(1e6 - 0.008).epsilon(1e-12));
}

TEST_CASE("sphere: a small sphere far away is missed just outside its edge", "[02][sphere][precision]") {
    const auto s = make_sphere(point(0, 0, -1e6), 0.01);
    CHECK_FALSE(s->intersect(ray(point(0.0101, 0, 0), vector(0, 0, -1))).hit());
    CHECK(s->intersect(ray(point(0.0099, 0, 0), vector(0, 0, -1))).hit());
}

TEST_CASE("sphere: the near hit on a huge sphere keeps its digits", "[02][sphere][precision]") {
    // A ground sphere of radius 1e6 seen from 1 unit above: t is 1, and c / q keeps it
    // accurate where (-b - sqrt(disc)) cancels.
    const auto s = make_sphere(point(0, -1e6, 0), 1e6);
    CHECK(hit_t(*s, ray(point(0, 1, 0), vector(0, -1, 0))) == Approx(1).epsilon(1e-9));
}

// --- geometry: normals, inside test, bounds ----------------------------------------------

TEST_CASE("sphere: normals are outward unit vectors", "[02][sphere][geometry]") {
    const auto s = make_sphere(point(1, -2, 3), 4);
    const vector n = s->normal(point(1, -2, 7));
    CHECK(n.x == Approx(0).margin(1e-12));
    CHECK(n.y == Approx(0).margin(1e-12));
    CHECK(n.z == Approx(1).epsilon(1e-12));
    const vector m = s->normal(point(1 - 4 / std::sqrt(2.0), -2 - 4 / std::sqrt(2.0), 3));
    CHECK(m.x == Approx(-1 / std::sqrt(2.0)).epsilon(1e-12));
    CHECK(m.y == Approx(-1 / std::sqrt(2.0)).epsilon(1e-12));
    CHECK(m.length() == Approx(1).epsilon(1e-12));
}

TEST_CASE("sphere: contains is true strictly inside only", "[02][sphere][geometry]") {
    const auto s = make_sphere(point(0, 0, 0), 2);
    CHECK(s->contains(point(0, 0, 0)));
    CHECK(s->contains(point(1.9, 0, 0)));
    CHECK_FALSE(s->contains(point(2.1, 0, 0)));
    CHECK_FALSE(s->contains(point(0, 0, 2)));
}

TEST_CASE("sphere: the box is the centre plus and minus the radius", "[02][sphere][geometry]") {
    const auto s = make_sphere(point(1, 2, 3), 0.5);
    const point lo = s->min_point(), hi = s->max_point();
    CHECK(lo.x == Approx(0.5));
    CHECK(lo.y == Approx(1.5));
    CHECK(lo.z == Approx(2.5));
    CHECK(hi.x == Approx(1.5));
    CHECK(hi.y == Approx(2.5));
    CHECK(hi.z == Approx(3.5));
}

// --- scene files -------------------------------------------------------------------------

TEST_CASE("sphere: a scene file's SPHERE is read with its centre and radius", "[02][sphere][scene_io][detail]") {
    vl::registry types;
    vl::register_framework(types);
    vl::stage02::register_stage_02(types);
    const vl::scene sc = vl::parse_scene("SPHERE { center 0 0 -5 radius 2 color 1 0 0 }", "hidden", types);
    CHECK(hit_t(*sc.root, ray(point(0, 0, 0), vector(0, 0, -1))) == Approx(3).epsilon(1e-12));
}

TEST_CASE("sphere: write() gives text that reads back as the same sphere", "[02][sphere][scene_io][detail]") {
    vl::registry types;
    vl::register_framework(types);
    vl::stage02::register_stage_02(types);
    const auto first = make_sphere(point(1, 2, -7), 0.25);
    std::ostringstream text;
    first->write(text);
    INFO("write() gave: " << text.str());
    const vl::scene again = vl::parse_scene(text.str(), "written", types);
    const ray r(point(1, 2, 0), vector(0, 0, -1));
    CHECK(hit_t(*again.root, r) == Approx(6.75).epsilon(1e-12));
}
