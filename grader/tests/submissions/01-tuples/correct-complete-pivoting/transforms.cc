// Transform builders. rotate_matrix is Rodrigues' rotation formula in matrix form,
// R = I + sin(a) K + (1 - cos(a)) K^2, with K the cross-product matrix of the unit axis
// (see e.g. https://en.wikipedia.org/wiki/Rodrigues%27_rotation_formula), and
// 1 - cos(a) written as 2 sin^2(a / 2). The look-at matrix is a turn after a move.
#include <cmath>

#include "stage_01.hh"
#include "vl/error.hh"

namespace vl::stage01 {

namespace {

/// x, y, z of `v` scaled to length 1; std::hypot does not overflow or underflow.
vector direction_of(const vector& v) {
    const double len = std::hypot(v.x, v.y, v.z);
    return {v.x / len, v.y / len, v.z / len};
}

}  // namespace

matrix translate_matrix(const vector& offset) {
    matrix m;
    m(0, 3) = offset.x;
    m(1, 3) = offset.y;
    m(2, 3) = offset.z;
    return m;
}

matrix scale_matrix(double sx, double sy, double sz) {
    matrix m;
    m(0, 0) = sx;
    m(1, 1) = sy;
    m(2, 2) = sz;
    return m;
}

matrix rotate_x_matrix(double radians) {
    matrix m;
    m(1, 1) = std::cos(radians);
    m(1, 2) = -std::sin(radians);
    m(2, 1) = std::sin(radians);
    m(2, 2) = std::cos(radians);
    return m;
}

matrix rotate_y_matrix(double radians) {
    matrix m;
    m(0, 0) = std::cos(radians);
    m(0, 2) = std::sin(radians);
    m(2, 0) = -std::sin(radians);
    m(2, 2) = std::cos(radians);
    return m;
}

matrix rotate_z_matrix(double radians) {
    matrix m;
    m(0, 0) = std::cos(radians);
    m(0, 1) = -std::sin(radians);
    m(1, 0) = std::sin(radians);
    m(1, 1) = std::cos(radians);
    return m;
}

matrix rotate_matrix(const vector& axis, double radians) {
    if (axis.x == 0 && axis.y == 0 && axis.z == 0)
        throw usage_error("rotate_matrix: a zero axis has no direction to turn about");
    const vector k = direction_of(axis);
    const double s = std::sin(radians), h = std::sin(radians / 2), one_minus_c = 2 * h * h;
    // K (the cross product with k) and K^2 = k k^T - I.
    const double K[3][3] = {{0, -k.z, k.y}, {k.z, 0, -k.x}, {-k.y, k.x, 0}};
    const double kv[3] = {k.x, k.y, k.z};
    matrix r;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            const auto ui = static_cast<std::size_t>(i), uj = static_cast<std::size_t>(j);
            const double k2 = kv[ui] * kv[uj] - (i == j ? 1.0 : 0.0);
            r(i, j) = (i == j ? 1.0 : 0.0) + s * K[ui][uj] + one_minus_c * k2;
        }
    return r;
}

matrix shear_matrix(double shx, double shy) {
    matrix m;
    m(0, 2) = shx;
    m(1, 2) = shy;
    return m;
}

matrix look_at_matrix(const point& eye, const point& look_at, const vector& up) {
    const vector view = look_at - eye;
    if (view.x == 0 && view.y == 0 && view.z == 0)
        throw usage_error("look_at_matrix: eye == look_at, so there is no view direction");
    if (up.x == 0 && up.y == 0 && up.z == 0) throw usage_error("look_at_matrix: up is the zero vector");
    const vector f = direction_of(view);
    const vector cross = f % direction_of(up);
    if (cross.length() < 1e-15) throw usage_error("look_at_matrix: up is parallel to the view direction");
    const vector right = direction_of(cross);
    const vector up_true = right % f;
    // The turn takes right, up and -f to x, y and z; its rows are those vectors.
    const matrix turn(vector(right.x, right.y, right.z, 0), vector(up_true.x, up_true.y, up_true.z, 0),
                      vector(-f.x, -f.y, -f.z, 0), vector(0, 0, 0, 1));
    return turn * translate_matrix({-eye.x, -eye.y, -eye.z});
}

}  // namespace vl::stage01
