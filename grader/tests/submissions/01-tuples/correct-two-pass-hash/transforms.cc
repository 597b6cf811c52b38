// Transform builders. Every rotation, the axis ones included, comes from one formula:
// Rodrigues' R = cos(a) I + sin(a) [k]x + (1 - cos(a)) k k^T, with 1 - cos(a) as
// 2 sin^2(a / 2). The look-at matrix is the inverse of the eye's frame: the transpose of
// its rotation, and the eye moved back.
#include <cmath>

#include "stage_01.hh"
#include "vl/error.hh"

namespace vl::stage01 {

namespace {

vector to_unit(const vector& v) {
    // Scale first so that squaring cannot overflow or underflow.
    const double ax = std::abs(v.x), ay = std::abs(v.y), az = std::abs(v.z);
    const double big = ax > ay ? (ax > az ? ax : az) : (ay > az ? ay : az);
    const vector s(v.x / big, v.y / big, v.z / big);
    const double len = std::sqrt(s.x * s.x + s.y * s.y + s.z * s.z);
    return {s.x / len, s.y / len, s.z / len};
}

}  // namespace

matrix translate_matrix(const vector& offset) {
    matrix m = IDENTITY;
    m(0, 3) = offset.x;
    m(1, 3) = offset.y;
    m(2, 3) = offset.z;
    return m;
}

matrix scale_matrix(double sx, double sy, double sz) {
    matrix m = IDENTITY;
    m(0, 0) = sx;
    m(1, 1) = sy;
    m(2, 2) = sz;
    return m;
}

matrix rotate_matrix(const vector& axis, double radians) {
    if (axis.x == 0 && axis.y == 0 && axis.z == 0)
        throw usage_error("rotate_matrix: the rotation axis is zero; pass a direction");
    const vector k = to_unit(axis);
    const double c = std::cos(radians), s = std::sin(radians);
    const double half = std::sin(radians / 2), t = 2 * half * half;
    const double kk[3] = {k.x, k.y, k.z};
    // [k]x, the matrix of the cross product with k.
    const double cross[3][3] = {{0, -k.z, k.y}, {k.z, 0, -k.x}, {-k.y, k.x, 0}};
    matrix r = IDENTITY;
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 3; ++j)
            r(static_cast<int>(i), static_cast<int>(j)) = (i == j ? c : 0.0) + s * cross[i][j] + t * kk[i] * kk[j];
    return r;
}

matrix rotate_x_matrix(double radians) { return rotate_matrix({1, 0, 0}, radians); }
matrix rotate_y_matrix(double radians) { return rotate_matrix({0, 1, 0}, radians); }
matrix rotate_z_matrix(double radians) { return rotate_matrix({0, 0, 1}, radians); }

matrix shear_matrix(double shx, double shy) {
    matrix m = IDENTITY;
    m(0, 2) = shx;
    m(1, 2) = shy;
    return m;
}

matrix look_at_matrix(const point& eye, const point& look_at, const vector& up) {
    const vector d = look_at - eye;
    if (d.x == 0 && d.y == 0 && d.z == 0) throw usage_error("look_at_matrix: the eye is at look_at");
    if (up.x == 0 && up.y == 0 && up.z == 0) throw usage_error("look_at_matrix: up is zero");
    const vector forward = to_unit(d);
    const vector up_unit = to_unit(up);
    const vector r = forward % up_unit;
    if (r * r < 1e-30) throw usage_error("look_at_matrix: up points along the view direction");
    const vector right = to_unit(r);
    const vector true_up = right % forward;
    // The eye's frame in world coordinates: columns right, up, backwards, eye.
    const matrix frame(point(right.x, right.y, right.z, 0), point(true_up.x, true_up.y, true_up.z, 0),
                       point(-forward.x, -forward.y, -forward.z, 0), eye);
    // Its inverse: the rotation transposed, and the eye's position taken back through it.
    matrix view = IDENTITY;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) view(i, j) = frame(j, i);
    const vector moved = view * vector(eye.x, eye.y, eye.z);
    view(0, 3) = -moved.x;
    view(1, 3) = -moved.y;
    view(2, 3) = -moved.z;
    return view;
}

}  // namespace vl::stage01
