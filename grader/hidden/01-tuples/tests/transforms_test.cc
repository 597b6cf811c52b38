// Hidden tests of stage 01's transform builders (grader only; students never see this
// file). Each TEST_CASE is one graded item; its tags name the rubric category. The answer
// keys are long-double formulas written here, never another function of the submission.
#include "vl/catch.hh"

#include <cmath>
#include <string>

#include "hidden_support.hh"

using namespace vl;
using namespace vl::stage01;
using namespace vl::stage01::hidden;

namespace {

/// A few units in the last place of a number of size 1.
constexpr double ulps = 8 * u;

/// The largest difference of the 16 elements, and where it is.
struct element_error {
    ld most = 0;
    int row = 0, col = 0;
};
element_error worst(const matrix& got, const mat4& want) {
    element_error e;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) {
            const ld d = std::fabs(got(r, c) - want(r, c));
            if (!(d <= e.most)) e = {d, r, c};  // a NaN element is the worst of all
        }
    return e;
}

/// True when every element of `got` is within `scale(r, c) * factor` of `want`.
bool within(const matrix& got, const mat4& want, const mat4& scale, ld factor, element_error& bad) {
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) {
            const ld d = std::fabs(got(r, c) - want(r, c));
            if (!(d <= scale(r, c) * factor + 1e-300L)) {
                bad = {d, r, c};
                return false;
            }
        }
    return true;
}

std::string element(const matrix& got, const mat4& want, const element_error& e) {
    return "element (" + std::to_string(e.row) + ", " + std::to_string(e.col) + ") is " + num(got(e.row, e.col)) +
           ", it should be " + num(static_cast<double>(want(e.row, e.col)));
}

/// The elementary rotations, in long double.
mat4 rot_x(ld a) {
    mat4 m = identity4();
    m(1, 1) = std::cos(a), m(1, 2) = -std::sin(a), m(2, 1) = std::sin(a), m(2, 2) = std::cos(a);
    return m;
}
mat4 rot_y(ld a) {
    mat4 m = identity4();
    m(0, 0) = std::cos(a), m(0, 2) = std::sin(a), m(2, 0) = -std::sin(a), m(2, 2) = std::cos(a);
    return m;
}
mat4 rot_z(ld a) {
    mat4 m = identity4();
    m(0, 0) = std::cos(a), m(0, 1) = -std::sin(a), m(1, 0) = std::sin(a), m(1, 1) = std::cos(a);
    return m;
}

/// x, y, z of a point or vector, each within `tolerance` of `want`.
bool near3(double x, double y, double z, const vec3& want, ld tolerance) {
    return std::fabs(x - want.x) <= tolerance && std::fabs(y - want.y) <= tolerance &&
           std::fabs(z - want.z) <= tolerance;
}
bool near3(const vector& v, const vec3& want, ld tolerance) { return near3(v.x, v.y, v.z, want, tolerance); }
bool near3(const point& p, const vec3& want, ld tolerance) { return near3(p.x, p.y, p.z, want, tolerance); }

/// The rotation block of a matrix: orthonormal rows and determinant +1, in long double.
bool is_rotation_block(const matrix& m, ld tolerance, std::string& why) {
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            const ld d = static_cast<ld>(m(i, 0)) * m(j, 0) + static_cast<ld>(m(i, 1)) * m(j, 1) +
                         static_cast<ld>(m(i, 2)) * m(j, 2);
            if (!(std::fabs(d - (i == j ? 1 : 0)) <= tolerance)) {
                why = "rows " + std::to_string(i) + " and " + std::to_string(j) + " have dot product " +
                      num(static_cast<double>(d)) + ", not " + (i == j ? "1" : "0");
                return false;
            }
        }
    const ld det = static_cast<ld>(m(0, 0)) * (static_cast<ld>(m(1, 1)) * m(2, 2) - static_cast<ld>(m(1, 2)) * m(2, 1)) -
                   static_cast<ld>(m(0, 1)) * (static_cast<ld>(m(1, 0)) * m(2, 2) - static_cast<ld>(m(1, 2)) * m(2, 0)) +
                   static_cast<ld>(m(0, 2)) * (static_cast<ld>(m(1, 0)) * m(2, 1) - static_cast<ld>(m(1, 1)) * m(2, 0));
    if (!(std::fabs(det - 1) <= 4 * tolerance)) {
        why = "the determinant of the upper-left 3x3 block is " + num(static_cast<double>(det)) +
              ", not +1 (a determinant of -1 is a mirror, not a rotation)";
        return false;
    }
    return true;
}

bool finite(const matrix& m) {
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c)
            if (!std::isfinite(m(r, c))) return false;
    return true;
}

bool affine_bottom_row(const matrix& m) { return m(3, 0) == 0 && m(3, 1) == 0 && m(3, 2) == 0 && m(3, 3) == 1; }

}  // namespace

// --- translate_matrix --------------------------------------------------------------------

TEST_CASE("transforms: translate_matrix(v) * p is p + v for any point and offset", "[01][transforms][essential]") {
    inputs in(101);
    tally t;
    for (int k = 0; k < 300; ++k) {
        const double scale = in.log_uniform(-3, 6);
        const vector v = in.in_box(scale);
        const point p = in.point_in_box(in.log_uniform(-3, 6));
        const point got = translate_matrix(v) * p;
        const vec3 want = of(p) + of(v);
        const ld tol = 2 * u * (std::fabs(want.x) + std::fabs(want.y) + std::fabs(want.z));
        VL_CHECK_EACH(t, near3(got, want, tol) && got.w == 1,
                      "translate_matrix(" << show(v) << ") * point " << show(p) << " should be the point "
                                          << show(want) << " (w = 1) ± " << num(static_cast<double>(tol))
                                          << "; yours is (" << num(got.x) << ", " << num(got.y) << ", "
                                          << num(got.z) << ", w = " << num(got.w) << ")");
    }
    t.finish("points");
}

TEST_CASE("transforms: translate_matrix leaves vectors alone - whatever the offset", "[01][transforms][essential]") {
    inputs in(102);
    tally t;
    for (int k = 0; k < 300; ++k) {
        const vector v = in.in_box(in.log_uniform(-3, 6));
        const vector d = in.in_box(in.log_uniform(-3, 3));
        const vector got = translate_matrix(v) * d;
        VL_CHECK_EACH(t, got == d,
                      "translate_matrix(" << show(v) << ") * vector " << show(d)
                                          << " should be the same vector, unchanged (a direction has no position "
                                             "to move); yours is ("
                                          << num(got.x) << ", " << num(got.y) << ", " << num(got.z)
                                          << ", w = " << num(got.w) << ")");
    }
    t.finish("vectors");
}

TEST_CASE("transforms: translate_matrix ignores the offset's w and keeps the bottom row 0 0 0 1",
          "[01][transforms]") {
    const vector plain(1.5, -2, 3), with_w(1.5, -2, 3, 7);
    const matrix m = translate_matrix(with_w);
    VL_EXPECT(m == translate_matrix(plain), "translate_matrix((1.5, -2, 3, w = 7)) should equal translate_matrix((1.5, -2, 3)) "
                                            "(the offset's w is ignored); yours is "
                                                << show(m) << " against " << show(translate_matrix(plain)));
    VL_EXPECT(affine_bottom_row(m), "translate_matrix((1.5, -2, 3, w = 7)) should have the bottom row 0 0 0 1; yours is "
                                        << show(m));
    const point p = m * point(1, 1, 1);
    VL_EXPECT(p.w == 1 && p.x == 2.5 && p.y == -1 && p.z == 4,
              "translate_matrix((1.5, -2, 3, w = 7)) * (1, 1, 1) should be (2.5, -1, 4) with w = 1; yours is ("
                  << num(p.x) << ", " << num(p.y) << ", " << num(p.z) << ", w = " << num(p.w) << ")");
    VL_EXPECT(translate_matrix(vector(0, 0, 0, 3)) == IDENTITY,
              "translate_matrix((0, 0, 0, w = 3)) should be the identity; yours is "
                  << show(translate_matrix(vector(0, 0, 0, 3))));
}

// --- scale_matrix ----------------------------------------------------------------------------

TEST_CASE("transforms: scale_matrix scales each axis by its own factor - for points and vectors",
          "[01][transforms][essential]") {
    inputs in(103);
    tally t;
    for (int k = 0; k < 300; ++k) {
        const double sx = in.uniform(-5, 5), sy = in.uniform(-5, 5), sz = in.uniform(-5, 5);
        const vector d = in.in_box(10);
        const point p = in.point_in_box(10);
        const matrix m = scale_matrix(sx, sy, sz);
        const vec3 wv{static_cast<ld>(sx) * d.x, static_cast<ld>(sy) * d.y, static_cast<ld>(sz) * d.z};
        const vec3 wp{static_cast<ld>(sx) * p.x, static_cast<ld>(sy) * p.y, static_cast<ld>(sz) * p.z};
        const vector gv = m * d;
        const point gp = m * p;
        const ld tol = 2 * u * 50;
        VL_CHECK_EACH(t, near3(gv, wv, tol) && gv.w == 0,
                      "scale_matrix(" << num(sx) << ", " << num(sy) << ", " << num(sz) << ") * vector " << show(d)
                                      << " should be " << show(wv) << " ± " << num(static_cast<double>(tol))
                                      << "; yours is " << show(gv));
        VL_CHECK_EACH(t, near3(gp, wp, tol) && gp.w == 1,
                      "scale_matrix(" << num(sx) << ", " << num(sy) << ", " << num(sz) << ") * point " << show(p)
                                      << " should be " << show(wp) << " (w = 1) ± " << num(static_cast<double>(tol))
                                      << "; yours is (" << num(gp.x) << ", " << num(gp.y) << ", " << num(gp.z)
                                      << ", w = " << num(gp.w) << ")");
    }
    t.finish("checks");
}

TEST_CASE("transforms: scale_matrix mirrors with a negative factor and flattens with a zero factor",
          "[01][transforms]") {
    const point p(3, -4, 5);
    const point mirrored = scale_matrix(-1, 1, 1) * p;
    VL_EXPECT(mirrored.x == -3 && mirrored.y == -4 && mirrored.z == 5 && mirrored.w == 1,
              "scale_matrix(-1, 1, 1) * (3, -4, 5) should be (-3, -4, 5); yours is " << show(mirrored));
    const vector flat = scale_matrix(2, 0, -0.5) * vector(3, -4, 5);
    VL_EXPECT(flat.x == 6 && flat.y == 0 && flat.z == -2.5 && flat.w == 0,
              "scale_matrix(2, 0, -0.5) * vector (3, -4, 5) should be (6, 0, -2.5); yours is " << show(flat));
    const matrix z = scale_matrix(1, 1, 0);
    VL_EXPECT(z.determinant() == 0, "scale_matrix(1, 1, 0) flattens z, so its determinant should be 0; yours is "
                                        << num(z.determinant()) << " for " << show(z));
    const matrix m = scale_matrix(-2, 3, -4);
    VL_EXPECT(m.determinant() == 24 && affine_bottom_row(m),
              "scale_matrix(-2, 3, -4) should have determinant 24 and bottom row 0 0 0 1; yours is " << show(m));
    const point origin = m * point(0, 0, 0);
    VL_EXPECT(origin.x == 0 && origin.y == 0 && origin.z == 0 && origin.w == 1,
              "scale_matrix(-2, 3, -4) scales about the origin, so the origin should stay put; yours moves it to "
                  << show(origin));
}

TEST_CASE("transforms: a uniform scale_matrix of s on every axis scales vectors too and keeps a point's w at 1",
          "[01][transforms]") {
    tally t;
    for (const double f : {2.0, -1.0, 0.5, 1e-3, 3e5, 0.0}) {
        const matrix m = scale_matrix(f, f, f);
        const vector v = m * vector(1, -2, 3);
        const point p = m * point(1, -2, 3);
        VL_CHECK_EACH(t, v.x == f && v.y == -2 * f && v.z == 3 * f && v.w == 0,
                      "scale_matrix(" << num(f) << ", " << num(f) << ", " << num(f) << ") * vector (1, -2, 3) should be "
                                      << show(vector(f, -2 * f, 3 * f)) << "; yours is " << show(v)
                                      << " (a scale acts on vectors and points alike)");
        VL_CHECK_EACH(t, p.x == f && p.y == -2 * f && p.z == 3 * f && p.w == 1,
                      "scale_matrix(" << num(f) << ", " << num(f) << ", " << num(f) << ") * point (1, -2, 3) should be ("
                                      << num(f) << ", " << num(-2 * f) << ", " << num(3 * f)
                                      << ") with w = 1, without homogenizing; yours is (" << num(p.x) << ", "
                                      << num(p.y) << ", " << num(p.z) << ", w = " << num(p.w) << ")");
    }
    t.finish("scales");
}

TEST_CASE("transforms: every builder returns an affine matrix - bottom row exactly 0 0 0 1", "[01][transforms]") {
    inputs in(119);
    tally t;
    for (int k = 0; k < 40; ++k) {
        const double a = in.uniform(-7, 7), f = in.uniform(-3, 3);
        const vector v = in.in_box(5);
        const point eye = in.point_in_box(5);
        const struct {
            std::string name;
            matrix m;
        } built[] = {
            {"translate_matrix(" + show(v) + ")", translate_matrix(v)},
            {"scale_matrix(" + num(f) + ", " + num(f) + ", " + num(f) + ")", scale_matrix(f, f, f)},
            {"scale_matrix(" + num(f) + ", " + num(a) + ", 2)", scale_matrix(f, a, 2)},
            {"rotate_x_matrix(" + num(a) + ")", rotate_x_matrix(a)},
            {"rotate_y_matrix(" + num(a) + ")", rotate_y_matrix(a)},
            {"rotate_z_matrix(" + num(a) + ")", rotate_z_matrix(a)},
            {"rotate_matrix(" + show(v) + ", " + num(a) + ")", rotate_matrix(v, a)},
            {"shear_matrix(" + num(f) + ", " + num(a) + ")", shear_matrix(f, a)},
            {"look_at_matrix(" + show(eye) + ", (0, 0, 0), (0, 1, 0.5))",
             look_at_matrix(eye, point(0, 0, 0), vector(0, 1, 0.5))},
        };
        for (const auto& b : built)
            VL_CHECK_EACH(t, affine_bottom_row(b.m),
                          b.name << " should have the bottom row 0 0 0 1 exactly, so that a point keeps w == 1 and a "
                                    "vector w == 0; yours is "
                                 << show(b.m));
    }
    t.finish("matrices");
}

// --- rotate_x/y/z_matrix ----------------------------------------------------------------------

TEST_CASE("transforms: quarter turns of rotate_x/y/z_matrix are right-handed", "[01][transforms][essential]") {
    struct turn {
        const char* name;
        matrix (*f)(double);
        vector from, to;
    };
    const turn turns[] = {
        {"rotate_z_matrix", rotate_z_matrix, {1, 0, 0}, {0, 1, 0}},
        {"rotate_z_matrix", rotate_z_matrix, {0, 1, 0}, {-1, 0, 0}},
        {"rotate_z_matrix", rotate_z_matrix, {0, 0, 1}, {0, 0, 1}},
        {"rotate_x_matrix", rotate_x_matrix, {0, 1, 0}, {0, 0, 1}},
        {"rotate_x_matrix", rotate_x_matrix, {0, 0, 1}, {0, -1, 0}},
        {"rotate_x_matrix", rotate_x_matrix, {1, 0, 0}, {1, 0, 0}},
        {"rotate_y_matrix", rotate_y_matrix, {0, 0, 1}, {1, 0, 0}},
        {"rotate_y_matrix", rotate_y_matrix, {1, 0, 0}, {0, 0, -1}},
        {"rotate_y_matrix", rotate_y_matrix, {0, 1, 0}, {0, 1, 0}},
    };
    tally t;
    for (const turn& q : turns)
        for (const double sign : {1.0, -1.0}) {
            // A negative quarter turn undoes the positive one: it takes `to` back to `from`.
            const vector in = sign > 0 ? q.from : q.to, want = sign > 0 ? q.to : q.from;
            const double angle = sign * pi / 2;
            const vector got = q.f(angle) * in;
            VL_CHECK_EACH(t, near3(got, of(want), ulps),
                          q.name << "(" << (sign > 0 ? "pi/2" : "-pi/2") << ") * " << show(in) << " should be "
                                 << show(want) << " ± " << num(ulps) << "; yours is " << show(got));
        }
    t.finish("quarter turns");
}

TEST_CASE("transforms: rotate_x/y/z_matrix at any angle are the cos/sin rotation matrices",
          "[01][transforms][essential]") {
    inputs in(104);
    struct axis {
        const char* name;
        matrix (*f)(double);
        mat4 (*want)(ld);
    };
    const axis axes[] = {{"rotate_x_matrix", rotate_x_matrix, rot_x},
                         {"rotate_y_matrix", rotate_y_matrix, rot_y},
                         {"rotate_z_matrix", rotate_z_matrix, rot_z}};
    tally t;
    for (const axis& a : axes)
        for (int k = 0; k < 100; ++k) {
            const double angle = k < 8 ? (k - 4) * pi / 3 : in.uniform(-20, 20);
            const matrix got = a.f(angle);
            const mat4 want = a.want(angle);
            const element_error e = worst(got, want);
            VL_CHECK_EACH(t, e.most <= ulps,
                          a.name << "(" << num(angle) << ") should be " << show(to_matrix(want)) << " ± " << num(ulps)
                                 << " in each element; yours is " << show(got) << ": "
                                 << element(got, want, e));
        }
    t.finish("rotations");
}

TEST_CASE("transforms: rotations keep lengths and angles: orthonormal - determinant +1 - affine",
          "[01][transforms]") {
    inputs in(105);
    tally t;
    for (int k = 0; k < 200; ++k) {
        const double angle = in.uniform(-7, 7);
        const vector axis = in.direction() * in.log_uniform(-2, 2);
        const int which = k % 4;
        const matrix m = which == 0   ? rotate_x_matrix(angle)
                         : which == 1 ? rotate_y_matrix(angle)
                         : which == 2 ? rotate_z_matrix(angle)
                                      : rotate_matrix(axis, angle);
        const std::string name = which == 0   ? "rotate_x_matrix(" + num(angle) + ")"
                                 : which == 1 ? "rotate_y_matrix(" + num(angle) + ")"
                                 : which == 2 ? "rotate_z_matrix(" + num(angle) + ")"
                                              : "rotate_matrix(" + show(axis) + ", " + num(angle) + ")";
        std::string why;
        VL_CHECK_EACH(t, is_rotation_block(m, 16 * u, why),
                      name << " should be a rotation; yours is " << show(m) << ": " << why);
        VL_CHECK_EACH(t, affine_bottom_row(m) && m(0, 3) == 0 && m(1, 3) == 0 && m(2, 3) == 0,
                      name << " should have the bottom row 0 0 0 1 and no translation; yours is " << show(m));
        // Lengths are kept: a unit vector stays unit.
        const vector d = in.direction();
        const vector r = m * d;
        const ld len = length(of(r));
        VL_CHECK_EACH(t, std::fabs(len - 1) <= 16 * u,
                      name << " * " << show(d) << " (length 1) should have length 1 ± " << num(16 * u)
                           << "; yours is " << show(r) << ", length " << num(static_cast<double>(len)));
    }
    t.finish("checks");
}

TEST_CASE("transforms: the origin and every point on the rotation axis stay where they are", "[01][transforms]") {
    inputs in(106);
    tally t;
    for (int k = 0; k < 150; ++k) {
        const double angle = in.uniform(-7, 7), s = in.uniform(-100, 100);
        const int which = k % 4;
        const vector axis = which == 0 ? vector(1, 0, 0)
                            : which == 1 ? vector(0, 1, 0)
                            : which == 2 ? vector(0, 0, 1)
                                         : in.direction() * in.log_uniform(-2, 2);
        const matrix m = which == 0   ? rotate_x_matrix(angle)
                         : which == 1 ? rotate_y_matrix(angle)
                         : which == 2 ? rotate_z_matrix(angle)
                                      : rotate_matrix(axis, angle);
        const std::string name = which == 0   ? "rotate_x_matrix(" + num(angle) + ")"
                                 : which == 1 ? "rotate_y_matrix(" + num(angle) + ")"
                                 : which == 2 ? "rotate_z_matrix(" + num(angle) + ")"
                                              : "rotate_matrix(" + show(axis) + ", " + num(angle) + ")";
        const vec3 on = s * unit(of(axis));
        const point p = to_point(on);
        const point got = m * p;
        const ld tol = 32 * u * std::fabs(s);
        VL_CHECK_EACH(t, near3(got, of(p), tol) && got.w == 1,
                      name << " * " << show(p) << " (a point on the axis) should stay " << show(p) << " ± "
                           << num(static_cast<double>(tol)) << "; yours is " << show(got));
        const point o = m * point(0, 0, 0);
        VL_CHECK_EACH(t, o.x == 0 && o.y == 0 && o.z == 0 && o.w == 1,
                      name << " should keep the origin; yours moves it to " << show(o));
    }
    t.finish("checks");
}

// --- rotate_matrix -------------------------------------------------------------------------------

TEST_CASE("transforms: rotate_matrix about random axes matches Rodrigues' formula", "[01][transforms][essential]") {
    inputs in(107);
    tally t;
    for (int k = 0; k < 400; ++k) {
        const vector axis = in.direction() * in.log_uniform(-3, 3);
        // Away from 0 and from whole turns, where 1 - cos(angle) is tiny (another test).
        double angle = in.uniform(0.1, 2 * pi - 0.1) * (k % 2 ? 1 : -1);
        const matrix got = rotate_matrix(axis, angle);
        const vec3 a = unit(of(axis));
        const mat4 want = rodrigues(a, angle);
        mat4 scale = rodrigues_scale(a, angle);
        scale(3, 3) = 0;  // the affine parts are exact
        element_error e;
        VL_CHECK_EACH(t, within(got, want, scale, 32 * u, e),
                      "rotate_matrix(" << show(axis) << ", " << num(angle) << ") should be " << show(to_matrix(want))
                                       << " within a few units in the last place; yours is " << show(got) << ": "
                                       << element(got, want, e));
    }
    t.finish("rotations");
}

TEST_CASE("transforms: rotate_matrix turns right-handed about the direction its axis points in",
          "[01][transforms][essential]") {
    // Quarter and third turns with answers known exactly.
    struct known {
        vector axis;
        double angle;
        vector in, out;
    };
    const known cases[] = {
        {{0, 0, 3}, pi / 2, {1, 0, 0}, {0, 1, 0}},     {{2, 0, 0}, pi / 2, {0, 1, 0}, {0, 0, 1}},
        {{0, 0.5, 0}, pi / 2, {0, 0, 1}, {1, 0, 0}},   {{0, 0, -1}, pi / 2, {1, 0, 0}, {0, -1, 0}},
        {{-4, 0, 0}, pi / 2, {0, 1, 0}, {0, 0, -1}},   {{0, -2, 0}, pi / 2, {0, 0, 1}, {-1, 0, 0}},
        {{1, 1, 1}, 2 * pi / 3, {1, 0, 0}, {0, 1, 0}}, {{1, 1, 1}, 2 * pi / 3, {0, 0, 1}, {1, 0, 0}},
        {{-1, -1, -1}, 2 * pi / 3, {1, 0, 0}, {0, 0, 1}}, {{1, 1, 0}, pi, {1, 0, 0}, {0, 1, 0}},
        {{1, 0, 1}, pi / 2, {0, 1, 0}, {-1 / std::sqrt(2.0), 0, 1 / std::sqrt(2.0)}},
    };
    tally t;
    for (const known& c : cases) {
        const vector got = rotate_matrix(c.axis, c.angle) * c.in;
        VL_CHECK_EACH(t, near3(got, of(c.out), 4 * ulps),
                      "rotate_matrix(" << show(c.axis) << ", " << num(c.angle) << ") * " << show(c.in) << " should be "
                                       << show(c.out) << " ± " << num(4 * ulps) << "; yours is " << show(got));
    }
    t.finish("turns");
}

TEST_CASE("transforms: rotate_matrix about a negated axis turns by the negated angle", "[01][transforms]") {
    inputs in(108);
    tally t;
    for (int k = 0; k < 200; ++k) {
        const vector axis = in.direction() * in.log_uniform(-2, 2);
        const double angle = in.uniform(-7, 7);
        const matrix a = rotate_matrix(-axis, angle);
        const matrix b = rotate_matrix(axis, -angle);
        const mat4 want = rodrigues(unit(of(axis)), -static_cast<ld>(angle));
        const element_error ea = worst(a, want), eb = worst(b, want);
        VL_CHECK_EACH(t, ea.most <= 32 * u && eb.most <= 32 * u,
                      "rotate_matrix(" << show(-axis) << ", " << num(angle) << ") and rotate_matrix(" << show(axis)
                                       << ", " << num(-angle) << ") should both be " << show(to_matrix(want)) << " ± "
                                       << num(32 * u) << "; yours are " << show(a) << " and " << show(b));
    }
    t.finish("axes");
    const matrix z = rotate_matrix(vector(0, 0, -2.5), 0.6);
    const element_error e = worst(z, rot_z(-0.6L));
    VL_EXPECT(e.most <= ulps, "rotate_matrix((0, 0, -2.5), 0.6) should be rotate_z by -0.6, "
                                  << show(to_matrix(rot_z(-0.6L))) << " ± " << num(ulps) << "; yours is " << show(z));
}

TEST_CASE("transforms: rotate_matrix keeps full relative precision for tiny angles", "[01][transforms]") {
    // 1 - cos(1e-6) is 5e-13, but computed as 1 - std::cos(1e-6) it keeps only 4 digits.
    inputs in(109);
    tally t;
    for (int k = 0; k < 200; ++k) {
        const vector axis = in.direction() * in.log_uniform(-1, 1);
        const double angle = in.log_uniform(-9, -2) * (k % 2 ? 1 : -1) + (k % 5 == 0 ? 2 * pi : 0);
        const matrix got = rotate_matrix(axis, angle);
        const vec3 a = unit(of(axis));
        const mat4 want = rodrigues(a, angle);
        mat4 scale = rodrigues_scale(a, angle);
        scale(3, 3) = 0;
        element_error e;
        VL_CHECK_EACH(t, within(got, want, scale, 32 * u, e),
                      "rotate_matrix(" << show(axis) << ", " << num(angle) << ") should be " << show(to_matrix(want))
                                       << " to a few units in the last place of each product in Rodrigues' formula; "
                                          "yours is "
                                       << show(got) << ": " << element(got, want, e));
    }
    t.finish("rotations");
}

TEST_CASE("transforms: rotate_matrix works for axes from 1e-200 to 1e200 long", "[01][transforms][detail]") {
    inputs in(110);
    tally t;
    for (int e10 = -200; e10 <= 200; e10 += 10) {
        const vector dir = in.direction();
        const double angle = in.uniform(0.3, 3);
        const vector axis = dir * std::pow(10.0, e10);
        const matrix got = rotate_matrix(axis, angle);
        const mat4 want = rodrigues(unit(of(dir)), angle);
        const element_error e = worst(got, want);
        VL_CHECK_EACH(t, e.most <= 32 * u,
                      "rotate_matrix(" << show(axis) << ", " << num(angle) << ") should be " << show(to_matrix(want))
                                       << " ± " << num(32 * u) << " (the axis's length does not matter); yours is "
                                       << show(got));
    }
    // An axis along a coordinate axis, and one whose w is not 0 (w is ignored).
    const matrix big = rotate_matrix(vector(0, 1e200, 0), 0.8), small = rotate_matrix(vector(0, 0, 1e-200, 5), 0.8);
    VL_CHECK_EACH(t, worst(big, rot_y(0.8L)).most <= ulps,
                  "rotate_matrix((0, 1e200, 0), 0.8) should be rotate_y by 0.8, " << show(to_matrix(rot_y(0.8L)))
                                                                                   << "; yours is " << show(big));
    VL_CHECK_EACH(t, worst(small, rot_z(0.8L)).most <= ulps,
                  "rotate_matrix((0, 0, 1e-200, w = 5), 0.8) should be rotate_z by 0.8, "
                      << show(to_matrix(rot_z(0.8L))) << "; yours is " << show(small));
    t.finish("axes");
}

TEST_CASE("transforms: rotate_matrix refuses the zero axis with usage_error", "[01][transforms][detail]") {
    // A valid axis gives a matrix (whether it is the right one is for the other tests).
    const matrix ok = rotate_matrix(vector(0, 0, 1), 0.5);
    VL_EXPECT(finite(ok), "rotate_matrix((0, 0, 1), 0.5) should be a rotation; yours is " << show(ok));
    for (const vector& zero : {vector(0, 0, 0), vector(0, 0, 0, 1), vector(-0.0, 0, -0.0)}) {
        bool refused = false;
        std::string other;
        try {
            (void)rotate_matrix(zero, 1.0);
        } catch (const usage_error&) {
            refused = true;
        } catch (const std::exception& e) {
            other = e.what();
        }
        VL_EXPECT(refused, "rotate_matrix(" << show(zero) << " (w = " << num(zero.w)
                                            << "), 1) should throw vl::usage_error (the zero axis has no direction); "
                                            << (other.empty() ? "yours returned a matrix" : "yours threw: " + other));
    }
}

// --- shear_matrix ----------------------------------------------------------------------------------

TEST_CASE("transforms: shear_matrix gives x + shx z and y + shy z and keeps z - for points and vectors", "[01][transforms]") {
    inputs in(111);
    tally t;
    for (int k = 0; k < 300; ++k) {
        const double shx = in.uniform(-3, 3), shy = in.uniform(-3, 3);
        const vector d = in.in_box(10);
        const matrix m = shear_matrix(shx, shy);
        const vec3 want{d.x + static_cast<ld>(shx) * d.z, d.y + static_cast<ld>(shy) * d.z, d.z};
        const ld tol = 4 * u * (std::fabs(d.x) + std::fabs(d.y) + 3 * std::fabs(d.z));
        const vector gv = m * d;
        const point gp = m * point(d.x, d.y, d.z);
        VL_CHECK_EACH(t, near3(gv, want, tol) && gv.w == 0,
                      "shear_matrix(" << num(shx) << ", " << num(shy) << ") * vector " << show(d) << " should be "
                                      << show(want) << " ± " << num(static_cast<double>(tol)) << "; yours is "
                                      << show(gv));
        VL_CHECK_EACH(t, near3(gp, want, tol) && gp.w == 1,
                      "shear_matrix(" << num(shx) << ", " << num(shy) << ") * point " << show(d) << " should be "
                                      << show(want) << " ± " << num(static_cast<double>(tol)) << "; yours is "
                                      << show(gp));
        const point flat(d.x, d.y, 0);
        const point gf = m * flat;
        VL_CHECK_EACH(t, gf.x == flat.x && gf.y == flat.y && gf.z == 0 && gf.w == 1,
                      "shear_matrix(" << num(shx) << ", " << num(shy) << ") should leave " << show(flat)
                                      << " (in the plane z == 0) where it is; yours moves it to " << show(gf));
    }
    t.finish("checks");
}

// --- products ------------------------------------------------------------------------------------

TEST_CASE("transforms: in a product of transforms the right-hand one acts first (column vectors)",
          "[01][transforms][essential]") {
    inputs in(112);
    tally t;
    for (int k = 0; k < 100; ++k) {
        const vector offset = in.in_box(5);
        const double sx = in.uniform(0.5, 2), sy = in.uniform(-2, -0.5), sz = in.uniform(0.5, 2);
        const double az = in.uniform(-3, 3), ax = in.uniform(-3, 3), shx = in.uniform(-1, 1), shy = in.uniform(-1, 1);
        const point p = in.point_in_box(3);
        // translate * rotate_z * scale * shear * rotate_x, built here in long double.
        mat4 tr = identity4();
        tr(0, 3) = offset.x, tr(1, 3) = offset.y, tr(2, 3) = offset.z;
        mat4 sc = identity4();
        sc(0, 0) = sx, sc(1, 1) = sy, sc(2, 2) = sz;
        mat4 sh = identity4();
        sh(0, 2) = shx, sh(1, 2) = shy;
        const mat4 want = tr * rot_z(az) * sc * sh * rot_x(ax);
        const matrix got = translate_matrix(offset) * rotate_z_matrix(az) * scale_matrix(sx, sy, sz) *
                           shear_matrix(shx, shy) * rotate_x_matrix(ax);
        const auto wp = apply(want, of(p), 1);
        const point gp = got * p;
        const ld tol = 1e-13L;
        VL_CHECK_EACH(t, near3(gp, vec3{wp[0], wp[1], wp[2]}, tol),
                      "translate_matrix(" << show(offset) << ") * rotate_z_matrix(" << num(az) << ") * scale_matrix("
                                          << num(sx) << ", " << num(sy) << ", " << num(sz) << ") * shear_matrix("
                                          << num(shx) << ", " << num(shy) << ") * rotate_x_matrix(" << num(ax)
                                          << ") * " << show(p) << " should be "
                                          << show(vec3{wp[0], wp[1], wp[2]}) << " ± " << num(static_cast<double>(tol))
                                          << " (rotate about x first, translate last); yours is " << show(gp));
    }
    t.finish("products");
}

// --- look_at_matrix ------------------------------------------------------------------------------

namespace {

struct view_case {
    point eye, at;
    vector up;
};

/// Random views: eyes and targets anywhere in a box, ups at least 10 degrees off the view.
std::vector<view_case> random_views(std::uint64_t seed, int count) {
    inputs in(seed);
    std::vector<view_case> v;
    while (static_cast<int>(v.size()) < count) {
        const double s = in.log_uniform(-1, 3);
        view_case c{in.point_in_box(s), in.point_in_box(s), in.direction() * in.log_uniform(-2, 2)};
        if ((c.at - c.eye).length() < 1e-3 * s) continue;
        if (sine_up_view(c.eye, c.at, c.up) < 0.17) continue;
        v.push_back(c);
    }
    // And a few fixed ones: straight down, straight up, along each axis, ups not perpendicular.
    v.push_back({{0, 10, 0}, {0, 0, 0}, {0, 0, -1}});
    v.push_back({{0, -3, 0}, {0, 4, 0}, {1, 0, 0}});
    v.push_back({{5, 0, 0}, {-5, 0, 0}, {0, 1, 1}});
    v.push_back({{0, 0, -5}, {0, 0, 5}, {0, -1, 0}});
    v.push_back({{1, 2, 3}, {1, 2, 2}, {0.3, 1, 40}});
    v.push_back({{1e6, -2e6, 3e6}, {0, 0, 0}, {0, 0, 1}});
    return v;
}

std::string view_name(const view_case& c) {
    return "look_at_matrix(" + show(c.eye) + ", " + show(c.at) + ", " + show(c.up) + ")";
}

}  // namespace

TEST_CASE("transforms: look_at_matrix takes the eye to the origin and look_at to -d on the z axis",
          "[01][transforms][essential]") {
    tally t;
    for (const view_case& c : random_views(113, 200)) {
        const matrix m = look_at_matrix(c.eye, c.at, c.up);
        const ld scale = length(of(c.eye)) + length(of(c.at)) + 1;
        const ld tol = 64 * u * scale;
        const point e = m * c.eye, a = m * c.at;
        const ld d = length(of(c.at) - of(c.eye));
        VL_CHECK_EACH(t, near3(e, vec3{}, tol) && e.w == 1,
                      view_name(c) << " * eye should be the origin ± " << num(static_cast<double>(tol))
                                   << "; yours is " << show(e) << " with w = " << num(e.w));
        VL_CHECK_EACH(t, near3(a, vec3{0, 0, -d}, tol) && a.w == 1,
                      view_name(c) << " * look_at should be (0, 0, " << num(static_cast<double>(-d)) << ") ± "
                                   << num(static_cast<double>(tol)) << " (the eye looks down -z); yours is "
                                   << show(a));
    }
    t.finish("checks");
}

TEST_CASE("transforms: look_at_matrix's rotation is right-handed: orthonormal rows - determinant +1",
          "[01][transforms][essential]") {
    tally t;
    for (const view_case& c : random_views(114, 200)) {
        const matrix m = look_at_matrix(c.eye, c.at, c.up);
        std::string why;
        VL_CHECK_EACH(t, is_rotation_block(m, 64 * u / sine_up_view(c.eye, c.at, c.up), why) && affine_bottom_row(m),
                      view_name(c) << "'s upper-left 3x3 block should be a rotation (orthonormal rows, determinant +1) "
                                      "and its bottom row 0 0 0 1; yours is "
                                   << show(m) << ": " << (why.empty() ? "the bottom row is wrong" : why));
    }
    t.finish("views");
}

TEST_CASE("transforms: look_at_matrix sends up into the y-z plane with a positive y", "[01][transforms][essential]") {
    tally t;
    for (const view_case& c : random_views(115, 200)) {
        const matrix m = look_at_matrix(c.eye, c.at, c.up);
        const vector up_seen = m * c.up;
        const ld tol = 64 * u * length(of(c.up)) / sine_up_view(c.eye, c.at, c.up);
        VL_CHECK_EACH(t, std::fabs(up_seen.x) <= tol && up_seen.y > 0 && up_seen.w == 0,
                      view_name(c) << " * up should lie in the y-z plane (x = 0 ± " << num(static_cast<double>(tol))
                                   << ") with a positive y; yours is " << show(up_seen));
    }
    t.finish("views");
}

TEST_CASE("transforms: look_at_matrix is the eye's frame: rows right - up - backwards - then the move",
          "[01][transforms]") {
    tally t;
    for (const view_case& c : random_views(116, 200)) {
        const matrix m = look_at_matrix(c.eye, c.at, c.up);
        const mat4 want = view_matrix(c.eye, c.at, c.up);
        mat4 scale;
        const ld rot = 64 * u / sine_up_view(c.eye, c.at, c.up);
        const ld far = rot * (length(of(c.eye)) + 1);
        for (int r = 0; r < 3; ++r) {
            for (int k = 0; k < 3; ++k) scale(r, k) = rot;
            scale(r, 3) = far;
        }
        element_error e;
        VL_CHECK_EACH(t, within(m, want, scale, 1, e),
                      view_name(c) << " should be " << show(to_matrix(want))
                                   << " (its rows the eye's right, up and backward directions); yours is " << show(m)
                                   << ": " << element(m, want, e));
    }
    t.finish("views");
}

TEST_CASE("transforms: look_at_matrix uses only the part of up perpendicular to the view - whatever its length",
          "[01][transforms]") {
    tally t;
    inputs in(117);
    for (const view_case& c : random_views(118, 150)) {
        const matrix m = look_at_matrix(c.eye, c.at, c.up);
        const vector view = (c.at - c.eye).unit();
        const vector other = c.up * in.log_uniform(-3, 3) + view * in.uniform(-5, 5) * c.up.length();
        if (sine_up_view(c.eye, c.at, other) < 0.05) continue;
        const matrix n = look_at_matrix(c.eye, c.at, other);
        const ld tol = 256 * u / sine_up_view(c.eye, c.at, other) / sine_up_view(c.eye, c.at, c.up) *
                       (length(of(c.eye)) + 1);
        const element_error e = worst(n, of(m));
        VL_CHECK_EACH(t, e.most <= tol,
                      view_name(c) << " is " << show(m) << "; with up " << show(other)
                                   << " (the same up plus a part along the view, times a factor) it should be the "
                                      "same matrix ± "
                                   << num(static_cast<double>(tol)) << "; yours is " << show(n));
    }
    t.finish("views");
}

TEST_CASE("transforms: look_at_matrix refuses eye == look_at - a zero up and an up along the view",
          "[01][transforms][detail]") {
    // A valid view gives a matrix (whether it is the right one is for the other tests).
    const matrix ok = look_at_matrix(point(0, 0, 5), point(0, 0, 0), vector(0, 1, 0));
    VL_EXPECT(finite(ok), "look_at_matrix((0, 0, 5), (0, 0, 0), (0, 1, 0)) should be a view matrix; yours is " << show(ok));
    const view_case bad[] = {
        {{1, 2, 3}, {1, 2, 3}, {0, 1, 0}},     // eye == look_at
        {{0, 0, 5}, {0, 0, 0}, {0, 0, 0}},     // zero up
        {{0, 0, 5}, {0, 0, 0}, {0, 0, -3}},    // up along the view
        {{0, 0, 5}, {0, 0, 0}, {0, 0, 2}},     // up against the view (anti-parallel)
        {{1, 1, 1}, {3, 5, 7}, {-1, -2, -3}},  // anti-parallel, off the axes
        {{1, 1, 1}, {2, 2, 2}, {4, 4, 4}},     // parallel, off the axes
    };
    for (const view_case& c : bad) {
        bool refused = false;
        std::string other;
        try {
            (void)look_at_matrix(c.eye, c.at, c.up);
        } catch (const usage_error&) {
            refused = true;
        } catch (const std::exception& e) {
            other = e.what();
        }
        VL_EXPECT(refused, view_name(c) << " should throw vl::usage_error; "
                                        << (other.empty() ? "yours returned a matrix" : "yours threw: " + other));
    }
}
