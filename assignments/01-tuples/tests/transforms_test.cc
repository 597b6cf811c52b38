// Public tests of the transform builders (transforms.cc). The contract is stage_01.hh.
#include "vl/catch.hh"

#include <cmath>
#include <numbers>

#include "test_support.hh"
#include "vl/error.hh"

using namespace vl;
using namespace vl::stage01;
using vl::test01::distance;

namespace {
constexpr double pi = std::numbers::pi;
constexpr double tol = 1e-15;
}  // namespace

TEST_CASE("transforms: translate_matrix moves points and leaves vectors alone", "[01][transforms]") {
    const matrix t = translate_matrix({1, -2, 3});
    CHECK(distance(t * point(4, 5, 6), point(5, 3, 9)) == 0);
    CHECK((t * point(4, 5, 6)).w == 1);
    CHECK(t * vector(4, 5, 6) == vector(4, 5, 6));
    CHECK(translate_matrix({0, 0, 0}) == IDENTITY);
}

TEST_CASE("transforms: scale_matrix scales each axis of points and vectors - and mirrors for a negative factor",
          "[01][transforms]") {
    const matrix s = scale_matrix(2, 3, -1);
    CHECK(distance(s * point(1, 1, 1), point(2, 3, -1)) == 0);
    CHECK(s * vector(1, -1, 2) == vector(2, -3, -2));
    CHECK(distance(s * point(0, 0, 0), point(0, 0, 0)) == 0);
    CHECK(s.determinant() == Approx(-6));
}

TEST_CASE("transforms: quarter turns are right-handed (x to y about z and y to z about x and z to x about y)",
          "[01][transforms]") {
    CHECK(distance(rotate_z_matrix(pi / 2) * vector(1, 0, 0), vector(0, 1, 0)) < tol);
    CHECK(distance(rotate_x_matrix(pi / 2) * vector(0, 1, 0), vector(0, 0, 1)) < tol);
    CHECK(distance(rotate_y_matrix(pi / 2) * vector(0, 0, 1), vector(1, 0, 0)) < tol);
    // The axis itself does not move, and neither does the origin.
    CHECK(distance(rotate_z_matrix(1.0) * vector(0, 0, 2), vector(0, 0, 2)) < tol);
    CHECK(distance(rotate_x_matrix(1.0) * point(3, 0, 0), point(3, 0, 0)) < tol);
    CHECK(distance(rotate_y_matrix(1.0) * point(0, 0, 0), point(0, 0, 0)) == 0);
}

TEST_CASE("transforms: rotations keep lengths and angles (orthonormal with determinant 1)", "[01][transforms]") {
    for (const matrix& r : {rotate_x_matrix(0.7), rotate_y_matrix(-2.1), rotate_z_matrix(3.0),
                            rotate_matrix({1, 2, 3}, 1.3)}) {
        CAPTURE(r);
        CHECK(distance(r.transpose() * r, IDENTITY) < 4 * tol);
        CHECK(r.determinant() == Approx(1).margin(4 * tol));
        CHECK(r(3, 0) == 0);
        CHECK(r(3, 3) == 1);
    }
}

TEST_CASE("transforms: rotate_matrix about a coordinate axis is rotate_x/y/z_matrix - whatever the axis length",
          "[01][transforms]") {
    const double a = 0.83;
    CHECK(distance(rotate_matrix({1, 0, 0}, a), rotate_x_matrix(a)) < tol);
    CHECK(distance(rotate_matrix({0, 3, 0}, a), rotate_y_matrix(a)) < tol);
    CHECK(distance(rotate_matrix({0, 0, 0.25}, a), rotate_z_matrix(a)) < tol);
    CHECK(distance(rotate_matrix({0, 0, -1}, a), rotate_z_matrix(-a)) < tol);
    CHECK(distance(rotate_matrix({0, 0, 1, 7}, a), rotate_z_matrix(a)) < tol);  // w is ignored
}

TEST_CASE("transforms: rotate_matrix turns about its axis and keeps the points on it", "[01][transforms]") {
    // A third of a turn about (1, 1, 1) cycles the axes: x to y, y to z, z to x.
    const matrix r = rotate_matrix({1, 1, 1}, 2 * pi / 3);
    CHECK(distance(r * vector(1, 0, 0), vector(0, 1, 0)) < 4 * tol);
    CHECK(distance(r * vector(0, 1, 0), vector(0, 0, 1)) < 4 * tol);
    CHECK(distance(r * point(2, 2, 2), point(2, 2, 2)) < 8 * tol);
    CHECK(distance(rotate_matrix({1, -2, 0.5}, 2 * pi), IDENTITY) < 4 * tol);
}

TEST_CASE("transforms: rotate_matrix works with an axis of length 1e200 or 1e-200", "[01][transforms]") {
    // Squaring the components to find the length overflows to infinity, or underflows to 0.
    const double a = 0.4;
    CHECK(distance(rotate_matrix({0, 0, 1e200}, a), rotate_z_matrix(a)) < tol);
    CHECK(distance(rotate_matrix({1e-200, 0, 0}, a), rotate_x_matrix(a)) < tol);
    CHECK(distance(rotate_matrix({1e200, 1e200, 1e200}, a), rotate_matrix({1, 1, 1}, a)) < 4 * tol);
}

TEST_CASE("transforms: rotate_matrix with a zero axis throws usage_error", "[01][transforms]") {
    CHECK_THROWS_AS(rotate_matrix({0, 0, 0}, 1.0), usage_error);
}

TEST_CASE("transforms: shear_matrix shears x and y in proportion to z", "[01][transforms]") {
    const matrix s = shear_matrix(0.5, -2);
    CHECK(distance(s * point(1, 2, 4), point(3, -6, 4)) == 0);
    CHECK(s * vector(1, 2, 4) == vector(3, -6, 4));
    CHECK(distance(s * point(7, -3, 0), point(7, -3, 0)) == 0);  // the plane z == 0 stays put
    CHECK(s.determinant() == Approx(1));
}

TEST_CASE("transforms: in a product the right-hand matrix acts first (column vectors)", "[01][transforms]") {
    const matrix t = translate_matrix({1, 0, 0}), r = rotate_z_matrix(pi / 2);
    // Rotate, then move: (1, 0, 0) -> (0, 1, 0) -> (1, 1, 0).
    CHECK(distance((t * r) * point(1, 0, 0), point(1, 1, 0)) < tol);
    // Move, then rotate: (1, 0, 0) -> (2, 0, 0) -> (0, 2, 0).
    CHECK(distance((r * t) * point(1, 0, 0), point(0, 2, 0)) < 2 * tol);
}

TEST_CASE("transforms: look_at_matrix takes the eye to the origin and look_at onto -z", "[01][transforms]") {
    const point eye(3, 4, 5), at(-1, 2, 0);
    const matrix v = look_at_matrix(eye, at, {0, 1, 0});
    const double d = (at - eye).length();
    CHECK(distance(v * eye, point(0, 0, 0)) < 8 * tol);
    CHECK(distance(v * at, point(0, 0, -d)) < 8 * tol);
    CHECK(v(3, 0) == 0);
    CHECK(v(3, 3) == 1);
    // Looking from (0, 0, 5) at the origin with up +y is a plain move by -5 along z.
    CHECK(distance(look_at_matrix({0, 0, 5}, {0, 0, 0}, {0, 1, 0}), translate_matrix({0, 0, -5})) < tol);
}

TEST_CASE("transforms: look_at_matrix keeps lengths and uses only the part of up perpendicular to the view",
          "[01][transforms]") {
    const point eye(1, 1, 1), at(0, 0, -3);
    const vector up(0.3, 1, 0.8);  // not perpendicular to the view
    const matrix v = look_at_matrix(eye, at, up);
    matrix rotation = v;  // the upper-left 3x3 block
    for (int r = 0; r < 3; ++r) rotation(r, 3) = 0;
    CHECK(distance(rotation.transpose() * rotation, IDENTITY) < 8 * tol);
    CHECK(rotation.determinant() == Approx(1).margin(8 * tol));
    const vector up_seen = v * up;
    CHECK(std::abs(up_seen.x) < 8 * tol);  // no sideways part: up is not tilted
    CHECK(up_seen.y > 0);                  // and it points up, not down
    // Any up in the same plane through the view direction gives the same matrix.
    CHECK(distance(look_at_matrix(eye, at, up * 3 + (at - eye) * 0.5), v) < 16 * tol);
}

TEST_CASE("transforms: look_at_matrix rejects eye == look_at and an up parallel to the view", "[01][transforms]") {
    CHECK_THROWS_AS(look_at_matrix({1, 2, 3}, {1, 2, 3}, {0, 1, 0}), usage_error);
    CHECK_THROWS_AS(look_at_matrix({0, 0, 5}, {0, 0, 0}, {0, 0, 2}), usage_error);
    CHECK_THROWS_AS(look_at_matrix({0, 0, 5}, {0, 0, 0}, {0, 0, 0}), usage_error);
}
