// Hidden tests of stage 01's inverse (grader only; students never see this file). Each
// TEST_CASE is one graded item; its tags name the rubric category. The matrices are built
// here, element by element or in long double, never with the submission's transforms; the
// answer key is a long-double inverse (hidden_support.hh).
#include "vl/catch.hh"

#include <cmath>
#include <string>
#include <vector>

#include "hidden_support.hh"

using namespace vl;
using namespace vl::stage01;
using namespace vl::stage01::hidden;

namespace {

/// The contract's bound ‖X − m⁻¹‖ / ‖m⁻¹‖ ≤ c · κ(m) · u, with a generous c = 64 n, so
/// that every pivoting method that is stable passes (partial or complete pivoting, LU).
constexpr ld c_bound = 64 * 4;

struct verdict {
    bool ok = false;
    ld error = 0, kappa = 0, bound = 0;
};

/// Checks inverse(m) against the long-double inverse of m, within c · κ · u.
verdict check_inverse(const matrix& m, const matrix& x) {
    const mat4 exact = exact_inverse(m);
    verdict v;
    v.kappa = norm(of(m)) * norm(exact);
    v.bound = c_bound * v.kappa * u;
    v.error = relative_error(x, exact);
    v.ok = v.error <= v.bound;  // false for NaN
    return v;
}

std::string explain(const matrix& m, const matrix& x, const verdict& v) {
    return "inverse(" + show(m) + ") should be " + show(to_matrix(exact_inverse(m))) + " with a relative error (∞-norm) of at most " +
           num(static_cast<double>(c_bound)) + " κ u = " + num(static_cast<double>(v.bound)) + " (κ = " +
           num(static_cast<double>(v.kappa)) + "); yours is " + show(x) + ", relative error " +
           num(static_cast<double>(v.error));
}

/// ‖a b − I‖∞, in long double.
ld residual(const matrix& a, const matrix& b) { return norm(of(a) * of(b) - identity4()); }

/// A random matrix with 16 entries in [-1, 1].
matrix random_general(inputs& in) {
    matrix m;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) m(r, c) = in.uniform(-1, 1);
    return m;
}

/// U diag(1, ..., 1/kappa) V with U, V orthogonal: 2-norm condition number `kappa`.
matrix with_condition(inputs& in, ld kappa) {
    const mat4 a = in.orthogonal(), b = in.orthogonal();
    mat4 d;
    const ld s[4] = {1, std::pow(kappa, -1.0L / 3), std::pow(kappa, -2.0L / 3), 1 / kappa};
    for (int i = 0; i < 4; ++i) d(i, i) = s[i];
    return to_matrix(a * d * b);
}

bool no_nan(const matrix& m) {
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c)
            if (std::isnan(m(r, c))) return false;
    return true;
}

/// The 24 permutations of (0, 1, 2, 3), in order.
std::vector<std::array<int, 4>> permutations() {
    std::vector<std::array<int, 4>> all;
    std::array<int, 4> p{0, 1, 2, 3};
    do all.push_back(p);
    while (std::next_permutation(p.begin(), p.end()));
    return all;
}

/// The permutation matrix P with P(i, p[i]) == 1.
matrix permutation_matrix(const std::array<int, 4>& p) {
    matrix m(0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0);
    for (int i = 0; i < 4; ++i) m(i, p[static_cast<std::size_t>(i)]) = 1;
    return m;
}

/// True when `p` moves every index (no 1 on the diagonal of its matrix).
bool derangement(const std::array<int, 4>& p) {
    for (int i = 0; i < 4; ++i)
        if (p[static_cast<std::size_t>(i)] == i) return false;
    return true;
}

}  // namespace

TEST_CASE("inverse: random general 4x4 matrices - projective ones too - invert within the contract's error bound", "[01][inverse][essential]") {
    inputs in(201);
    tally t;
    for (int k = 0; k < 300; ++k) {
        matrix m = random_general(in);
        if (k % 3 == 0) {
            // Affine: bottom row 0 0 0 1.
            m(3, 0) = m(3, 1) = m(3, 2) = 0;
            m(3, 3) = 1;
        } else if (k % 3 == 1) {
            // A perspective projection's kind of bottom row: 0 0 -1 0, with a scaled block.
            m(3, 0) = m(3, 1) = m(3, 3) = 0;
            m(3, 2) = -1;
            m(2, 3) = in.uniform(-3, -0.5);
        }
        const matrix x = inverse(m);
        const verdict v = check_inverse(m, x);
        VL_CHECK_EACH(t, v.ok, explain(m, x, v));
    }
    t.finish("matrices");
}

TEST_CASE("inverse: m * inverse(m) and inverse(m) * m are both the identity up to the contract's error bound", "[01][inverse][essential]") {
    inputs in(202);
    tally t;
    for (int k = 0; k < 300; ++k) {
        matrix m = random_general(in);
        for (int c = 0; c < 4; ++c) m(k % 4, c) *= in.log_uniform(-3, 3);  // rows of different sizes
        const matrix x = inverse(m);
        const mat4 exact = exact_inverse(m);
        const ld kappa = norm(of(m)) * norm(exact), bound = c_bound * kappa * u;
        const ld right = residual(m, x), left = residual(x, m);
        VL_CHECK_EACH(t, right <= bound && left <= bound,
                      "for m = " << show(m) << " (κ = " << num(static_cast<double>(kappa)) << "), ‖m X − I‖ and ‖X m − I‖ with X = inverse(m) should be at most "
                                 << num(static_cast<double>(bound)) << "; yours are " << num(static_cast<double>(right))
                                 << " and " << num(static_cast<double>(left)) << " (X = " << show(x) << ")");
    }
    t.finish("matrices");
}

TEST_CASE("inverse: tiny diagonal entries of well-conditioned matrices are pivoted away", "[01][inverse][essential]") {
    // P (I + small) with P a permutation that moves every row: κ is about 1, but every
    // diagonal entry is tiny, so elimination without pivoting divides by it.
    inputs in(204);
    tally t;
    std::vector<std::array<int, 4>> moving;
    for (const auto& p : permutations())
        if (derangement(p)) moving.push_back(p);
    for (int k = 0; k < 180; ++k) {
        const auto& p = moving[static_cast<std::size_t>(k) % moving.size()];
        matrix m = permutation_matrix(p);
        for (int r = 0; r < 4; ++r)
            for (int c = 0; c < 4; ++c)
                if (m(r, c) == 0) m(r, c) = in.log_uniform(-18, -6) * (in.uniform(0, 1) < 0.5 ? -1 : 1);
                else m(r, c) = in.uniform(0.5, 2) * (in.uniform(0, 1) < 0.5 ? -1 : 1);
        const matrix x = inverse(m);
        const verdict v = check_inverse(m, x);
        VL_CHECK_EACH(t, v.ok, explain(m, x, v));
    }
    t.finish("matrices");
}

TEST_CASE("inverse: the pivot is the entry largest in absolute value - negative ones included",
          "[01][inverse][essential]") {
    // Each column holds one large negative entry and tiny positive ones: the largest signed
    // value is a tiny pivot, the largest absolute value the right one.
    inputs in(205);
    tally t;
    const auto all = permutations();
    for (int k = 0; k < 192; ++k) {
        const auto& p = all[static_cast<std::size_t>(k) % all.size()];
        matrix m;
        for (int r = 0; r < 4; ++r)
            for (int c = 0; c < 4; ++c) m(r, c) = in.log_uniform(-14, -8);
        for (int r = 0; r < 4; ++r) m(r, p[static_cast<std::size_t>(r)]) = -in.uniform(0.5, 2);
        // And a few with mixed signs: the big entry of some columns positive.
        if (k % 4 == 3) m(0, p[0]) = -m(0, p[0]);
        const matrix x = inverse(m);
        const verdict v = check_inverse(m, x);
        VL_CHECK_EACH(t, v.ok, explain(m, x, v));
    }
    t.finish("matrices");
}

TEST_CASE("inverse: zero pivots - on the diagonal or appearing during elimination - are swapped away",
          "[01][inverse]") {
    inputs in(206);
    tally t;
    std::vector<matrix> cases = {
        // A quarter turn about each axis, and a half turn: zeros on the diagonal.
        matrix(0, -1, 0, 0, 1, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1),
        matrix(1, 0, 0, 0, 0, 0, -1, 0, 0, 1, 0, 0, 0, 0, 0, 1),
        matrix(0, 0, 1, 0, 0, 1, 0, 0, -1, 0, 0, 0, 0, 0, 0, 1),
        matrix(0, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 0),
        // Row 1 minus row 0 leaves a zero in the diagonal of column 1.
        matrix(1, 1, 0, 0, 1, 1, 1, 0, 0, 1, 1, 1, 0, 0, 1, 1),
        matrix(2, 4, 1, 3, 1, 2, 5, 0, 3, 1, 0, 2, 0, 2, 2, 1),
        // A projection with a zero in its last diagonal entry.
        matrix(1.5, 0, 0, 0, 0, 2, 0, 0, 0, 0, -1.25, -2.25, 0, 0, -1, 0),
    };
    // Random matrices with zeros all along the diagonal.
    for (int k = 0; k < 60; ++k) {
        matrix m = random_general(in);
        for (int i = 0; i < 4; ++i) m(i, i) = 0;
        cases.push_back(m);
    }
    for (const matrix& m : cases) {
        const matrix x = inverse(m);
        const verdict v = check_inverse(m, x);
        VL_CHECK_EACH(t, v.ok, explain(m, x, v));
    }
    t.finish("matrices");
}

TEST_CASE("inverse: permutation matrices and signed scaled ones invert exactly", "[01][inverse]") {
    tally t;
    int k = 0;
    for (const auto& p : permutations()) {
        const matrix m = permutation_matrix(p);
        const matrix x = inverse(m);
        VL_CHECK_EACH(t, x == m.transpose(),
                      "inverse(" << show(m) << ") should be its transpose " << show(m.transpose())
                                 << " exactly (every step is exact); yours is " << show(x));
        // Entries ±2^j: their inverse has entries ±2^-j, also exact.
        matrix s = m, want = m.transpose();
        for (int r = 0; r < 4; ++r) {
            const int c = p[static_cast<std::size_t>(r)];
            const double f = std::ldexp((r + k) % 2 ? -1.0 : 1.0, (r * 7 + k) % 9 - 4);
            s(r, c) = f;
            want(c, r) = 1 / f;
        }
        ++k;
        const matrix y = inverse(s);
        VL_CHECK_EACH(t, y == want,
                      "inverse(" << show(s) << ") should be " << show(want) << " exactly; yours is " << show(y));
    }
    t.finish("matrices");
}

TEST_CASE("inverse: exactly singular matrices give a matrix of 16 NaN", "[01][inverse][essential]") {
    const matrix regular(2, 0, 1, 0, 0, 1, 0, 0, 1, 0, 1, 0, 0, 0, 0, 4);
    // A regular matrix first: its inverse has no NaN (how accurate it is, other tests say).
    const matrix rx = inverse(regular);
    VL_EXPECT(no_nan(rx), "inverse(" << show(regular) << ") is regular, so its inverse should have no NaN; yours is "
                                     << show(rx));
    const matrix singular[] = {
        matrix(0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0),                 // zero
        matrix(1, 2, 3, 4, 0, 1, 5, 6, 0, 0, 0, 0, 7, 8, 9, 1),                 // rank 3: a zero row
        matrix(1, 0, 2, 3, 4, 0, 5, 6, 7, 0, 8, 9, 1, 0, 2, 1),                 // rank 3: a zero column
        matrix(1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0),                 // rank 3: flattens w
        matrix(2, 1, 0, 3, 4, 2, 1, 0, 0, 0, 1, 1, 8, 4, 0, 12),                // rank 3: row 3 is 4 times row 0
        matrix(1, 2, 0, 0, 2, 4, 0, 0, 0, 0, 3, 1, 0, 0, 6, 2),                 // rank 2: two dependent blocks
        matrix(1, -2, 4, 8, -2, 4, -8, -16, 4, -8, 16, 32, 0.5, -1, 2, 4),      // rank 1
        matrix(0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1),                 // rank 1: only w
        matrix(1e-150, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1e150, 0, 0, 0, 0, 1),        // rank 3, extreme sizes
    };
    tally t;
    for (const matrix& m : singular) {
        const matrix x = inverse(m);
        VL_CHECK_EACH(t, all_nan(x),
                      "inverse(" << show(m) << "): the matrix is singular, so all 16 elements should be NaN; yours is "
                                 << show(x));
    }
    t.finish("singular matrices");
}

TEST_CASE("inverse: a column that becomes zero only during elimination means singular", "[01][inverse]") {
    // One column is a multiple of another (twice, minus once, three times); no element,
    // row or column is zero at the start, but eliminating the first of the two leaves the
    // other exactly zero below the diagonal.
    const matrix regular(4, 1, 0, 0, 2, 4, 1, 0, 1, 2, 4, 1, 0, 1, 2, 4);
    // A regular matrix first: its inverse has no NaN (how accurate it is, other tests say).
    const matrix rx = inverse(regular);
    VL_EXPECT(no_nan(rx), "inverse(" << show(regular) << ") is regular, so its inverse should have no NaN; yours is "
                                     << show(rx));
    const matrix singular[] = {
        matrix(1, 2, 3, 1, 2, 4, -1, 5, 4, 8, 2, -3, -2, -4, 1, 2),
        matrix(-4, -8, 1, 3, 2, 4, 5, -2, 1, 2, -3, 1, 0.5, 1, 2, 6),
        matrix(8, 1, 3, -8, -4, 2, 5, 4, 2, -3, 1, -2, 1, 6, 2, -1),
        matrix(1, 4, 2, 3, 2, 1, 4, 6, 1, 3, 2, 3, 0.5, 2, 1, 1.5),
    };
    tally t;
    for (const matrix& m : singular) {
        const matrix x = inverse(m);
        VL_CHECK_EACH(t, all_nan(x),
                      "inverse(" << show(m) << "): the matrix is singular (its columns are dependent), so all 16 "
                                    "elements should be NaN; yours is "
                                 << show(x));
    }
    t.finish("singular matrices");
}

TEST_CASE("inverse: diagonal matrices of any sizes and scaled rotations invert to nearly full precision",
          "[01][inverse]") {
    inputs in(207);
    tally t;
    for (int k = 0; k < 100; ++k) {
        // A diagonal matrix with entries from 1e-150 to 1e150, of either sign.
        matrix d;
        matrix want;
        for (int i = 0; i < 4; ++i) {
            d(i, i) = in.log_uniform(-150, 150) * (in.uniform(0, 1) < 0.5 ? -1 : 1);
            want(i, i) = 1 / d(i, i);
        }
        const matrix x = inverse(d);
        bool ok = true;
        for (int r = 0; r < 4; ++r)
            for (int c = 0; c < 4; ++c)
                ok = ok && (r == c ? std::fabs(x(r, c) - want(r, c)) <= 2 * u * std::fabs(want(r, c)) : x(r, c) == 0);
        VL_CHECK_EACH(t, ok,
                      "inverse(" << show(d) << ") should be " << show(want)
                                 << ", each element within 2 units in its last place; yours is " << show(x));
        // s times a rotation, s from 1e-150 to 1e150: κ is 1 whatever s.
        const double s = std::pow(10.0, -150 + 3 * k);
        const mat4 q = in.orthogonal();
        const matrix m = to_matrix(scaled(s, q));
        const matrix y = inverse(m);
        const verdict v = check_inverse(m, y);
        VL_CHECK_EACH(t, v.ok, explain(m, y, v));
    }
    t.finish("matrices");
}

TEST_CASE("inverse: affine transforms (rotation and scale and shear and translation) invert within the contract's error bound",
          "[01][inverse]") {
    inputs in(208);
    tally t;
    for (int k = 0; k < 200; ++k) {
        const mat4 a = rodrigues(of(in.direction()), in.uniform(-pi, pi));
        mat4 s = identity4();
        for (int i = 0; i < 3; ++i) s(i, i) = in.log_uniform(-2, 2) * (in.uniform(0, 1) < 0.3 ? -1 : 1);
        s(0, 2) = in.uniform(-1, 1);
        mat4 tr = identity4();
        for (int i = 0; i < 3; ++i) tr(i, 3) = in.uniform(-100, 100);
        const matrix m = to_matrix(tr * a * s);
        const matrix x = inverse(m);
        const verdict v = check_inverse(m, x);
        VL_CHECK_EACH(t, v.ok, explain(m, x, v));
    }
    t.finish("matrices");
}

TEST_CASE("inverse: nearly singular matrices are inverted - not called singular", "[01][inverse][detail]") {
    tally t;
    for (int e = 10; e <= 50; e += 5) {
        // [[1, 1], [1, 1 + d]] with d = 2^-e: κ about 4 / d, an exact inverse.
        const double d = std::ldexp(1.0, -e);
        const matrix m(1, 1, 0, 0, 1, 1 + d, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1);
        const matrix x = inverse(m);
        const verdict v = check_inverse(m, x);
        VL_CHECK_EACH(t, v.ok, explain(m, x, v));
    }
    const matrix small = 1e-150 * IDENTITY;
    const matrix xs = inverse(small);
    VL_CHECK_EACH(t, std::fabs(xs(0, 0) - 1e150) <= 1e150 * 4 * u && std::fabs(xs(3, 3) - 1e150) <= 1e150 * 4 * u,
                  "inverse(1e-150 * IDENTITY) should be 1e150 * IDENTITY (a tiny matrix is not a singular one); yours "
                  "is "
                      << show(xs));
    t.finish("matrices");
}

// --- stability sweeps ------------------------------------------------------------------------
// Each sweep reports, per value of its parameter, how many of its matrices came back
// outside the contract's bound (rubric.toml's [[sweep]] says where none may). The trials
// never depend on what inverse() returns, so every submission is asked the same questions.

namespace {

/// One trial of a sweep: inverse(m) within c κ u of the long-double inverse, no NaN, no
/// exception. Counts the failure and keeps the first in words.
void sweep_trial(const matrix& m, long& failures, std::string& example) {
    std::string what;
    try {
        const matrix x = inverse(m);
        const verdict v = check_inverse(m, x);
        if (v.ok && no_nan(x)) return;
        what = no_nan(x) ? explain(m, x, v)
                         : "inverse(" + show(m) + ") came back with NaN, as for a singular matrix; it should be " +
                               show(to_matrix(exact_inverse(m))) + " (κ = " + num(static_cast<double>(v.kappa)) + ")";
    } catch (const std::exception& e) {
        what = "inverse(" + show(m) + ") threw: " + e.what();
    } catch (...) {
        what = "inverse(" + show(m) + ") threw something that is not a std::exception";
    }
    if (failures++ == 0) example = what;
}

/// with_condition(in, kappa) turned (a Householder reflection, which keeps the condition
/// number) so that its top-left element is `tiny` times its first column's length: the
/// first pivot in the matrix's own order is then tiny, and only pivoting keeps the
/// multipliers small.
matrix with_condition_tiny_first_pivot(inputs& in, ld kappa, ld tiny) {
    const mat4 b = of(with_condition(in, kappa));
    ld length = 0;
    for (int r = 0; r < 4; ++r) length += b(r, 0) * b(r, 0);
    length = std::sqrt(length);
    // c: the first column's new direction, length preserved, first component tiny.
    ld c[4] = {tiny * length, 0, 0, 0};
    ld rest = 0;
    for (int r = 1; r < 4; ++r) {
        c[r] = in.uniform(-1, 1);
        rest += c[r] * c[r];
    }
    const ld scale = std::sqrt(length * length - c[0] * c[0]) / std::sqrt(rest);
    for (int r = 1; r < 4; ++r) c[r] *= scale;
    // H = I - 2 v v^T / (v^T v) with v = b0 - c maps b0 to c.
    ld v[4], vv = 0;
    for (int r = 0; r < 4; ++r) {
        v[r] = b(r, 0) - c[r];
        vv += v[r] * v[r];
    }
    mat4 h = identity4();
    for (int r = 0; r < 4; ++r)
        for (int k = 0; k < 4; ++k) h(r, k) -= 2 * v[r] * v[k] / vv;
    return to_matrix(h * b);
}

}  // namespace

TEST_CASE("sweep: inverse: the error as the condition number grows from 1 to 1e16", "[01][sweep]") {
    // κ = 10^e. Each factor of 10 in κ may cost one digit (the bound grows with κ). Half
    // the matrices have a tiny first pivot in their own order (1e-12 of its column):
    // elimination without pivoting, or with the pivot chosen by its signed value, then
    // multiplies the round-off by up to 1e12 and falls outside the bound from κ = 1 on.
    inputs in(211);
    for (int e10 = 0; e10 <= 16; ++e10) {
        long failures = 0;
        std::string example;
        const int trials = 24;
        const ld kappa = std::pow(10.0L, e10);
        for (int k = 0; k < trials; ++k)
            sweep_trial(k % 2 == 0 ? with_condition(in, kappa) : with_condition_tiny_first_pivot(in, kappa, 1e-12L), failures,
                        example);
        vl::grading::sweep_point(std::pow(10.0, e10), trials, failures, example);
    }
}

TEST_CASE("sweep: inverse: well-conditioned matrices scaled by 1e-150 to 1e150", "[01][sweep]") {
    // s * m has the condition number of m: scaling never makes a matrix harder to invert.
    // A threshold on the pivot or a determinant test calls tiny ones singular; products of
    // huge entries overflow.
    inputs in(212);
    for (int e10 = -150; e10 <= 150; e10 += 15) {
        const double s = std::pow(10.0, e10);
        long failures = 0;
        std::string example;
        int trials = 0;
        // s * IDENTITY, and s * IDENTITY with the affine corner kept at 1.
        matrix corner = s * IDENTITY;
        corner(3, 3) = 1;
        for (const matrix& m : {matrix(s * IDENTITY), corner}) {
            sweep_trial(m, failures, example);
            ++trials;
        }
        for (int k = 0; k < 14; ++k, ++trials) {
            matrix m = with_condition(in, k % 2 == 0 ? 10 : 1000);
            for (int r = 0; r < 4; ++r)
                for (int c = 0; c < 4; ++c) m(r, c) *= s;
            sweep_trial(m, failures, example);
        }
        vl::grading::sweep_point(s, trials, failures, example);
    }
}
