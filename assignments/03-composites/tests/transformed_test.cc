// Public tests of the transformed instance (stage_03.hh, transformed.cc). Run them with
// `build/student/stage_03_public_test "[transformed]"`. The matrices are written out
// element by element, and the answer keys (an ellipsoid, a moved sphere) are solved in
// world space in this file, without any matrix.
#include "vl/catch.hh"

#include <cmath>
#include <numbers>
#include <vector>

#include "test_support.hh"
#include "vl/object_list.hh"

using namespace vl;
using namespace vl::stage03;
using namespace vl::stage03::testing;

namespace {

/// Scale by (sx, sy, sz), then move by (tx, ty, tz): T S.
matrix scale_then_move(double sx, double sy, double sz, double tx = 0, double ty = 0, double tz = 0) {
    return matrix(sx, 0, 0, tx, 0, sy, 0, ty, 0, 0, sz, tz, 0, 0, 0, 1);
}

/// Rotate by `degrees` about the z axis (counter-clockwise seen from +z), then move.
matrix turn_z_then_move(double degrees, double tx = 0, double ty = 0, double tz = 0) {
    const double a = degrees * std::numbers::pi / 180, c = std::cos(a), s = std::sin(a);
    return matrix(c, -s, 0, tx, s, c, 0, ty, 0, 0, 1, tz, 0, 0, 0, 1);
}

/// A unit test sphere at the origin, the child of most tests here.
std::unique_ptr<test_sphere> unit_sphere() { return std::make_unique<test_sphere>(point(0, 0, 0), 1); }

/// The answer key for the unit sphere scaled by s and moved by m: the ellipsoid
/// sum(((p - m) / s)^2) = 1, solved along the ray in long double. 0 when missed.
double ellipsoid_t(const ray& r, const vector& s, const vector& m) {
    using ld = long double;
    const ld o[3] = {ld(r.origin().x) - m.x, ld(r.origin().y) - m.y, ld(r.origin().z) - m.z};
    const ld d[3] = {r.direction().x, r.direction().y, r.direction().z};
    const ld k[3] = {s.x, s.y, s.z};
    ld a = 0, b = 0, c = -1;
    for (int i = 0; i < 3; ++i) {
        a += d[i] * d[i] / (k[i] * k[i]);
        b += o[i] * d[i] / (k[i] * k[i]);
        c += o[i] * o[i] / (k[i] * k[i]);
    }
    const ld disc = b * b - a * c;
    if (disc < 0) return 0;
    const ld t1 = (-b - std::sqrt(disc)) / a, t2 = (-b + std::sqrt(disc)) / a;
    return static_cast<double>(t1 > 1e-9 ? t1 : t2 > 1e-9 ? t2 : 0);
}

/// The ellipsoid's outward unit normal at p: its gradient, ((p - m) / s^2).
vector ellipsoid_normal(const point& p, const vector& s, const vector& m) {
    return vector((p.x - m.x) / (s.x * s.x), (p.y - m.y) / (s.y * s.y), (p.z - m.z) / (s.z * s.z)).unit();
}

}  // namespace

TEST_CASE("transformed: a scaled sphere is hit at the world distance - not the object-space one",
          "[03][transformed][essential]") {
    // Scale 2: the unit sphere becomes radius 2, so the ray from z = 10 hits at t = 8.
    // In object space the same ray starts at z = 5 and hits at 4: dividing the child's t
    // by |M^-1 d| (here 0.5) gives the world distance back.
    const auto doubled = make_transformed(unit_sphere(), scale_then_move(2, 2, 2));
    const ray r(point(0, 0, 10), vector(0, 0, -1));
    const intersection i = doubled->intersect(r);
    INFO("the unit sphere scaled by 2, " << show(r) << ": " << show(i));
    REQUIRE(i.hit());
    CHECK(i.t == Approx(8).epsilon(1e-12));
    CHECK(i.object == doubled.get());  // the transform itself is the object of the hit

    // An ellipsoid: scale (3, 1, 0.5), moved to (1, -2, 0.5); rays from all sides.
    const vector s(3, 1, 0.5), m(1, -2, 0.5);
    const auto e = make_transformed(unit_sphere(), scale_then_move(s.x, s.y, s.z, m.x, m.y, m.z));
    random_numbers random(51);
    int wrong = 0;
    std::string first;
    for (int k = 0; k < 500; ++k) {
        const vector u = random.direction(), v = random.direction();
        const point target =
            point(m.x, m.y, m.z) + 0.95 * random.uniform(0, 1) * vector(s.x * v.x, s.y * v.y, s.z * v.z);
        const ray q = ray_through(point(m.x, m.y, m.z) + 8 * u, target);
        const double want = ellipsoid_t(q, s, m);
        const intersection got = e->intersect(q);
        const bool same = got.hit() && std::fabs(got.t - want) <= 1e-9 * (1 + want) && got.object == e.get();
        if (!same && wrong++ == 0) first = show(q) + " should hit at t = " + num(want) + "; yours gave " + show(got);
    }
    INFO(wrong
         << " of 500 rays at the unit sphere scaled by (3, 1, 0.5) and moved to (1, -2, 0.5) were wrong; the first: "
         << first);
    CHECK(wrong == 0);
}

TEST_CASE("transformed: the normals of a stretched sphere use the inverse transpose", "[03][transformed][essential]") {
    // M n (the matrix itself) tilts the normal of an ellipsoid the wrong way; (M^-1)^T n
    // is perpendicular to the surface.
    const vector s(3, 1, 0.5), m(1, -2, 0.5);
    const auto e = make_transformed(unit_sphere(), scale_then_move(s.x, s.y, s.z, m.x, m.y, m.z));
    random_numbers random(52);
    int wrong = 0;
    std::string first;
    for (int k = 0; k < 300; ++k) {
        const ray q = ray_through(point(m.x, m.y, m.z) + 8 * random.direction(), point(m.x, m.y, m.z));
        const intersection i = e->intersect(q);
        if (!i.hit()) {
            if (wrong++ == 0) first = show(q) + " missed: " + show(i);
            continue;
        }
        const double t = ellipsoid_t(q, s, m);
        const point p = q.t_point(t);
        const vector got = e->normal(p), want = ellipsoid_normal(p, s, m);
        if ((got - want).length() > 1e-9 && wrong++ == 0)
            first = "the normal at " + show(p) + " should be " + show(want) + "; yours is " + show(got);
    }
    INFO(wrong << " of 300 points on the ellipsoid (unit sphere scaled by (3, 1, 0.5)) were wrong; the first: "
               << first);
    CHECK(wrong == 0);
}

TEST_CASE("transformed: a rotated and moved child is hit where the matrix takes it", "[03][transformed]") {
    // The child is a sphere of radius 0.5 at (2, 0, 0); turning 90 degrees about z takes
    // it to (0, 2, 0), moving by (0, 0, -5) to (0, 2, -5).
    const auto quarter =
        make_transformed(std::make_unique<test_sphere>(point(2, 0, 0), 0.5), turn_z_then_move(90, 0, 0, -5));
    const ray there(point(0, 2, 0), vector(0, 0, -1)), not_there(point(2, 0, 0), vector(0, 0, -1));
    const intersection i = quarter->intersect(there), j = quarter->intersect(not_there);
    INFO("turned 90 degrees about z and moved by (0, 0, -5): " << show(there) << " gave " << show(i) << "; "
                                                               << show(not_there) << " gave " << show(j));
    CHECK(i.t == Approx(4.5).epsilon(1e-12));
    CHECK(j.is_miss());

    // 30 degrees, from all sides: the answer key is the sphere where the matrix puts it.
    const double a = std::numbers::pi / 6;
    const auto turned =
        make_transformed(std::make_unique<test_sphere>(point(2, 0, 0), 0.5), turn_z_then_move(30, 1, 0, -3));
    const test_sphere key(point(1 + 2 * std::cos(a), 2 * std::sin(a), -3), 0.5);
    random_numbers random(53);
    int wrong = 0;
    std::string first;
    for (int k = 0; k < 400; ++k) {
        const ray q(key.center() + (random.in_box(-3, 3) - point(0, 0, 0)), random.direction());
        const intersection got = turned->intersect(q), want = key.intersect(q);
        const bool same = got.hit() == want.hit() && (!want.hit() || std::fabs(got.t - want.t) <= 1e-9 * (1 + want.t));
        if (!same && wrong++ == 0) first = show(q) + " should give " + show(want) + "; yours gave " + show(got);
    }
    INFO(wrong << " of 400 rays at the sphere of radius 0.5 at (2, 0, 0), turned 30 degrees about z and moved by "
                  "(1, 0, -3), were wrong; the first: "
               << first);
    CHECK(wrong == 0);
}

TEST_CASE("transformed: a transform of a transform applies both matrices", "[03][transformed]") {
    // Inside: moved by (0, 0, -3); outside: scaled by 2. The sphere ends up with radius 2
    // at (0, 0, -6): the ray from the origin along -z hits it at t = 4.
    auto inner = make_transformed(unit_sphere(), scale_then_move(1, 1, 1, 0, 0, -3));
    const auto outer = make_transformed(std::move(inner), scale_then_move(2, 2, 2));
    const ray r(point(0, 0, 0), vector(0, 0, -1));
    const intersection i = outer->intersect(r);
    INFO("scale 2 of (translate (0, 0, -3) of the unit sphere), " << show(r) << ": " << show(i));
    REQUIRE(i.hit());
    CHECK(i.t == Approx(4).epsilon(1e-12));
    CHECK(i.object == outer.get());
    const vector n = outer->normal(r.t_point(i.t));
    INFO("its normal at " << show(r.t_point(i.t)) << " is " << show(n));
    CHECK(n.z == Approx(1).epsilon(1e-12));
}

TEST_CASE("transformed: min_point and max_point bound the child's box taken to world space", "[03][transformed]") {
    // The child's box is [2, 4] x [-1, 1] x [-1, 1]; turned 30 degrees about z and moved
    // by (0, 0, 1), its eight corners span the box computed here.
    const auto turned =
        make_transformed(std::make_unique<test_sphere>(point(3, 0, 0), 1), turn_z_then_move(30, 0, 0, 1));
    const long double a = std::numbers::pi_v<long double> / 6;
    long double lo[3] = {1e9L, 1e9L, 1e9L}, hi[3] = {-1e9L, -1e9L, -1e9L};
    for (const long double x : {2.0L, 4.0L})
        for (const long double y : {-1.0L, 1.0L})
            for (const long double z : {-1.0L, 1.0L}) {
                const long double p[3] = {std::cos(a) * x - std::sin(a) * y, std::sin(a) * x + std::cos(a) * y, z + 1};
                for (int i = 0; i < 3; ++i) lo[i] = std::fmin(lo[i], p[i]), hi[i] = std::fmax(hi[i], p[i]);
            }
    const point got_lo = turned->min_point(), got_hi = turned->max_point();
    INFO("the box of [2, 4] x [-1, 1] x [-1, 1] turned 30 degrees about z and moved by (0, 0, 1) should be "
         << show(point(double(lo[0]), double(lo[1]), double(lo[2]))) << " to "
         << show(point(double(hi[0]), double(hi[1]), double(hi[2]))) << "; yours is " << show(got_lo) << " to "
         << show(got_hi));
    CHECK(got_lo.x == Approx(double(lo[0])).margin(1e-12));
    CHECK(got_lo.y == Approx(double(lo[1])).margin(1e-12));
    CHECK(got_lo.z == Approx(double(lo[2])).margin(1e-12));
    CHECK(got_hi.x == Approx(double(hi[0])).margin(1e-12));
    CHECK(got_hi.y == Approx(double(hi[1])).margin(1e-12));
    CHECK(got_hi.z == Approx(double(hi[2])).margin(1e-12));

    // A child whose box is unknown (an empty LIST) gives an unknown box.
    const auto unknown = make_transformed(std::make_unique<object_list>(), scale_then_move(2, 2, 2));
    CHECK(is_nan(unknown->min_point()));
    CHECK(is_nan(unknown->max_point()));
}

TEST_CASE("transformed: contains takes the point to object space", "[03][transformed]") {
    const auto stretched = make_transformed(unit_sphere(), scale_then_move(3, 1, 1, 0, 0, -2));
    CHECK(stretched->contains(point(2.5, 0, -2)));
    CHECK(stretched->contains(point(1, 0.5, -2)));
    CHECK_FALSE(stretched->contains(point(0, 1.5, -2)));
    CHECK_FALSE(stretched->contains(point(0, 0, 0)));  // the child's own place, before the matrix
}

TEST_CASE("transformed: tests its child once per ray and passes on a miss or the child's composite_only",
          "[03][transformed]") {
    const auto doubled = make_transformed(unit_sphere(), scale_then_move(2, 2, 2));
    const ray away(point(0, 3, 10), vector(0, 0, -1));  // passes 3 from the centre: a miss
    intersection i;
    const intersection_counts cost = cost_of([&] { i = doubled->intersect(away); });
    INFO(show(away) << " misses the sphere of radius 2; it gave " << show(i) << " and cost " << show(cost));
    CHECK(i.is_miss());
    CHECK(cost.primitive_tests == 1);
    CHECK(cost.composite_tests == 1);

    // The child is a composite that answers composite_only for rays within 1 of the
    // origin in object space, 2 in world space after the scale.
    const auto shell = make_transformed(std::make_unique<test_shell>(point(0, 0, 0), 1), scale_then_move(2, 2, 2));
    const intersection near = shell->intersect(ray(point(0, 1.5, 10), vector(0, 0, -1)));
    const intersection far = shell->intersect(ray(point(0, 2.5, 10), vector(0, 0, -1)));
    INFO("a composite child that answers composite_only: the near ray gave " << show(near) << ", the far one "
                                                                             << show(far));
    CHECK(near.is_composite_only());
    CHECK(near.object == shell.get());  // the transform's composite_only, not the child's
    CHECK(far.is_miss());
}

TEST_CASE("transformed: an empty transform misses every ray and takes exactly one child", "[03][transformed][detail]") {
    const auto t = make_transformed(nullptr, scale_then_move(2, 2, 2));
    const ray r(point(0, 0, 10), vector(0, 0, -1));
    CHECK(t->intersect(r).is_miss());
    t->insert(unit_sphere());
    CHECK(t->intersect(r).t == Approx(8).epsilon(1e-12));
    const std::string second = usage_error_of([&] { t->insert(unit_sphere()); });
    INFO("a second child: " << second);
    CHECK_THAT(second, Catch::Contains("LIST"));
    CHECK(t->intersect(r).t == Approx(8).epsilon(1e-12));
}

TEST_CASE("transformed: refuses a matrix that is singular - not affine or not finite", "[03][transformed][detail]") {
    // A good one first (the refusals are done for you; the intersection is not).
    CHECK(make_transformed(unit_sphere(), scale_then_move(1, 1, 1, 0, 0, -4))->intersect(ray()).t ==
          Approx(3).epsilon(1e-12));
    CHECK_THROWS_AS(make_transformed(unit_sphere(), scale_then_move(1, 0, 1)), usage_error);
    CHECK_THROWS_AS(make_transformed(unit_sphere(), matrix(1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 1, 1)),
                    usage_error);
    CHECK_THROWS_AS(make_transformed(unit_sphere(), scale_then_move(1, 1, 1, NaN, 0, 0)), usage_error);
}

TEST_CASE("scene: TRANSFORM applies its steps in the order written and writes a matrix that reads back",
          "[03][transformed][scene]") {
    // scale, then translate: a sphere of radius 2 at (0, 0, -5) (the other order would
    // put it at (0, 0, -10)); the ray from the origin along -z hits it at t = 3.
    const std::string text = "TRANSFORM { scale 2 2 2  translate 0 0 -5  SPHERE { } }";
    const auto first = read_object(text);
    const std::string out = written(*first);
    INFO("read: " << text << "\nwritten: " << out);
    CHECK(first->intersect(ray()).t == Approx(3).epsilon(1e-12));
    const auto second = read_object(out);
    CHECK(written(*second) == out);
    const std::string diff = different_hits(*first, *second, 300, -8, 8);
    INFO(diff);
    CHECK(diff.empty());

    // rotate about z by 90 degrees after moving to x = 2: the sphere goes to (0, 2, 0).
    const auto turned = read_object("TRANSFORM { translate 2 0 0  rotate 0 0 1 90  SPHERE { radius 0.5 } }");
    CHECK(turned->intersect(ray(point(0, 2, 5), vector(0, 0, -1))).t == Approx(4.5).epsilon(1e-9));
    // matrix: 16 numbers, row by row.
    const auto moved = read_object("TRANSFORM { matrix 1 0 0 0  0 1 0 3  0 0 1 0  0 0 0 1  SPHERE { } }");
    CHECK(moved->intersect(ray(point(0, 3, 5), vector(0, 0, -1))).t == Approx(4).epsilon(1e-12));
}

TEST_CASE("scene: a TRANSFORM is refused at the step at fault - and a good one is hit",
          "[03][transformed][scene][detail]") {
    const std::string singular = read_error("TRANSFORM { scale 1 0 1  SPHERE { } }");
    INFO(singular);
    CHECK_THAT(singular, Catch::Contains("test.ray_trace:1:13") && Catch::Contains("singular"));
    CHECK_THAT(read_error("TRANSFORM { translate 1 2 3 }"), Catch::Contains("test.ray_trace:1:"));
    CHECK_THAT(read_error("TRANSFORM { SPHERE { } SPHERE { } }"), Catch::Contains("test.ray_trace:1:"));
    const auto good = read_object("TRANSFORM { scale 1 1 1  SPHERE { center 0 0 -3 } }");
    CHECK(good->intersect(ray()).t == Approx(2).epsilon(1e-12));
}
