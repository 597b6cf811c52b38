// Public tests of the 4x4 inverse (inverse.cc). The contract, with the error bound these
// tests check, is stage_01.hh.
#include "vl/catch.hh"

#include <cmath>

#include "test_support.hh"

using namespace vl;
using namespace vl::stage01;
using vl::test01::all_nan;
using vl::test01::distance;
using vl::test01::norm;
using vl::test01::unit_roundoff;

namespace {

/// ‖X − exact‖ / ‖exact‖: how many digits of the computed inverse X are right.
double relative_error(const matrix& x, const matrix& exact) { return norm(x - exact) / norm(exact); }

/// The condition number κ(m) = ‖m‖ ‖m⁻¹‖, from a known exact inverse.
double condition(const matrix& m, const matrix& exact_inverse) { return norm(m) * norm(exact_inverse); }

// These tests build their matrices element by element, not with your transform builders,
// so that they test your inverse alone.
matrix translation(double x, double y, double z) { return matrix(1, 0, 0, x, 0, 1, 0, y, 0, 0, 1, z, 0, 0, 0, 1); }
matrix scaling(double x, double y, double z) { return matrix(x, 0, 0, 0, 0, y, 0, 0, 0, 0, z, 0, 0, 0, 0, 1); }
matrix turn_x(double a) {
    return matrix(1, 0, 0, 0, 0, std::cos(a), -std::sin(a), 0, 0, std::sin(a), std::cos(a), 0, 0, 0, 0, 1);
}
matrix turn_z(double a) {
    return matrix(std::cos(a), -std::sin(a), 0, 0, std::sin(a), std::cos(a), 0, 0, 0, 0, 1, 0, 0, 0, 0, 1);
}
matrix shearing(double shx, double shy) { return matrix(1, 0, shx, 0, 0, 1, shy, 0, 0, 0, 1, 0, 0, 0, 0, 1); }

}  // namespace

TEST_CASE("inverse: the identity is its own inverse", "[01][inverse]") {
    CHECK(inverse(IDENTITY) == IDENTITY);
}

TEST_CASE("inverse: a diagonal matrix inverts element by element", "[01][inverse]") {
    const matrix d(2, 0, 0, 0, 0, -4, 0, 0, 0, 0, 0.5, 0, 0, 0, 0, 1);
    CHECK(inverse(d) == matrix(0.5, 0, 0, 0, 0, -0.25, 0, 0, 0, 0, 2, 0, 0, 0, 0, 1));
}

TEST_CASE("inverse: an integer matrix with a known integer inverse", "[01][inverse]") {
    // Determinant 1, so the inverse has integer elements too.
    const matrix m(2, 1, 0, 0,
                   1, 1, 0, 0,
                   0, 0, 3, 2,
                   0, 0, 1, 1);
    const matrix exact(1, -1, 0, 0,
                       -1, 2, 0, 0,
                       0, 0, 1, -2,
                       0, 0, -1, 3);
    CHECK(distance(inverse(m), exact) < 1e-14);
    CHECK(distance(m * inverse(m), IDENTITY) < 1e-14);
}

TEST_CASE("inverse: a 90-degree rotation about z (zero leading pivot) inverts", "[01][inverse]") {
    // m(0, 0) == 0: dividing by it gives infinities. Pivoting swaps rows 0 and 1 first.
    const matrix quarter_turn(0, -1, 0, 0,
                              1, 0, 0, 0,
                              0, 0, 1, 0,
                              0, 0, 0, 1);
    const matrix x = inverse(quarter_turn);
    CHECK(distance(x, quarter_turn.transpose()) == 0);  // a rotation's inverse is its transpose
    CHECK(distance(x * quarter_turn, IDENTITY) == 0);
}

TEST_CASE("inverse: a matrix with zeros all along its diagonal inverts", "[01][inverse]") {
    // Every diagonal element is zero; every column still has a nonzero entry below or on it.
    const matrix m(0, 0, 0, 2,
                   0, 0, 3, 0,
                   0, 5, 0, 1,
                   4, 0, 1, 0);
    const matrix x = inverse(m);
    CHECK(distance(m * x, IDENTITY) < 1e-15);
    CHECK(distance(x * m, IDENTITY) < 1e-15);
}

TEST_CASE("inverse: a tiny leading pivot (1e-20) is swapped away - not divided by", "[01][inverse]") {
    // [[e, 1], [1, 1]] with e = 1e-20. Its inverse is [[1, -1], [-1, e]] / (e - 1), which
    // is [[-1, 1], [1, -e]] to full precision. Without pivoting, 1 - 1e20 rounds to
    // -1e20 and the top-left element comes out 0 instead of -1.
    const double e = 1e-20;
    const matrix m(e, 1, 0, 0,
                   1, 1, 0, 0,
                   0, 0, 1, 0,
                   0, 0, 0, 1);
    const matrix x = inverse(m);
    CHECK(x(0, 0) == Approx(-1).epsilon(1e-15));
    CHECK(x(0, 1) == Approx(1).epsilon(1e-15));
    CHECK(x(1, 0) == Approx(1).epsilon(1e-15));
    CHECK(std::abs(x(1, 1)) < 1e-19);
    CHECK(distance(m * x, IDENTITY) < 1e-15);
}

TEST_CASE("inverse: a singular matrix gives all NaN", "[01][inverse]") {
    CHECK(all_nan(inverse(matrix(0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0))));
    CHECK(all_nan(inverse(matrix(1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1))));  // flattens y
    // Rows 1 and 3 are equal: elimination turns one of them into zeros, exactly.
    CHECK(all_nan(inverse(matrix(1, 2, 3, 4,
                                 2, 7, 1, 8,
                                 3, 1, 4, 1,
                                 2, 7, 1, 8))));
}

TEST_CASE("inverse: uniform scales of 1e-150 and 1e150 are not singular", "[01][inverse]") {
    // A fixed threshold for "too small a pivot" would call the first singular. Scaling a
    // matrix does not change its condition number, so it must not change the answer.
    const matrix tiny = 1e-150 * IDENTITY, huge = 1e150 * IDENTITY;
    CHECK(distance(inverse(tiny) * tiny, IDENTITY) < 1e-15);
    CHECK(distance(inverse(huge) * huge, IDENTITY) < 1e-15);
    CHECK(inverse(tiny)(2, 2) == Approx(1e150));
}

TEST_CASE("inverse: a general matrix with a projective bottom row inverts", "[01][inverse]") {
    // A perspective projection (its bottom row is not 0 0 0 1), then a move.
    const matrix projection(1, 0, 0, 0,
                            0, 1, 0, 0,
                            0, 0, -1.2, -2.2,
                            0, 0, -1, 0);
    const matrix m = projection * translation(0.5, -1, -3);
    const matrix x = inverse(m);
    CHECK(distance(m * x, IDENTITY) < 1e-14);
    CHECK(distance(x * m, IDENTITY) < 1e-14);
    CHECK(distance(inverse(x), m) < 1e-14);
}

TEST_CASE("inverse: undoes a chain of scale - rotations - shear and translation", "[01][inverse]") {
    const matrix m = translation(4, -2, 7) * turn_z(0.9) * shearing(0.3, -0.7) * scaling(2, 0.5, 3) * turn_x(-1.2);
    const matrix x = inverse(m);
    CHECK(distance(x * m, IDENTITY) < 1e-14);
    CHECK(distance(x * (m * point(1, 2, 3)), point(1, 2, 3)) < 1e-14);
    // The inverse of a product is the product of the inverses in the opposite order.
    const matrix undo = turn_x(1.2) * scaling(0.5, 2, 1.0 / 3) * shearing(-0.3, 0.7) * turn_z(-0.9) *
                        translation(-4, 2, -7);
    CHECK(distance(x, undo) < 1e-14);
}

TEST_CASE("inverse: the 4x4 Hilbert matrix (condition number 28375) inverts to about 12 digits", "[01][inverse]") {
    // H(i, j) = 1 / (i + j + 1); its exact inverse has integer elements. 1/3, 1/5, 1/6 and
    // 1/7 are not exact in binary, so even a perfect method is off by about κ · u ≈ 3e-12.
    const matrix h(1, 1.0 / 2, 1.0 / 3, 1.0 / 4,
                   1.0 / 2, 1.0 / 3, 1.0 / 4, 1.0 / 5,
                   1.0 / 3, 1.0 / 4, 1.0 / 5, 1.0 / 6,
                   1.0 / 4, 1.0 / 5, 1.0 / 6, 1.0 / 7);
    const matrix exact(16, -120, 240, -140,
                       -120, 1200, -2700, 1680,
                       240, -2700, 6480, -4200,
                       -140, 1680, -4200, 2800);
    const double kappa = condition(h, exact);
    CHECK(kappa == Approx(28375));
    CHECK(relative_error(inverse(h), exact) < 16 * kappa * unit_roundoff);
}

TEST_CASE("inverse: a nearly singular matrix (condition number 4e10) stays within the condition-number bound",
          "[01][inverse]") {
    // [[1, 1], [1, 1 + d]] has inverse [[1 + d, -1], [-1, 1]] / d and κ about 4 / d. Here
    // d is 1e-10 as stored in binary: (1 + 1e-10) - 1, which is exact.
    const double one_plus_d = 1 + 1e-10, d = one_plus_d - 1;
    const matrix m(1, 1, 0, 0,
                   1, one_plus_d, 0, 0,
                   0, 0, 1, 0,
                   0, 0, 0, 1);
    const matrix exact(one_plus_d / d, -1 / d, 0, 0,
                       -1 / d, 1 / d, 0, 0,
                       0, 0, 1, 0,
                       0, 0, 0, 1);
    const double kappa = condition(m, exact);
    CHECK(kappa > 1e10);
    const double error = relative_error(inverse(m), exact);
    CAPTURE(kappa, error, kappa * unit_roundoff);
    CHECK(error < 16 * kappa * unit_roundoff);  // at worst about 6 digits right of 16
}
