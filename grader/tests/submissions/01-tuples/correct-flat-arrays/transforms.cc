// Transform builders, each filling a flat array of 16 elements row by row. The general
// rotation is the matrix of the unit quaternion (w, x, y, z) in its homogeneous form
// (w^2 + x^2 - y^2 - z^2 on the diagonal, ...), which needs no 1 - cos(a).
#include <algorithm>
#include <array>
#include <cmath>

#include "stage_01.hh"
#include "vl/error.hh"

namespace vl::stage01 {

namespace {

using elements = std::array<double, 16>;

matrix from(const elements& e) {
    return {e[0], e[1], e[2], e[3], e[4], e[5], e[6], e[7], e[8], e[9], e[10], e[11], e[12], e[13], e[14], e[15]};
}

elements identity() { return {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}; }

std::array<double, 3> unit3(double x, double y, double z) {
    const double big = std::max({std::fabs(x), std::fabs(y), std::fabs(z)});
    x /= big;
    y /= big;
    z /= big;
    const double len = std::sqrt(x * x + y * y + z * z);
    return {x / len, y / len, z / len};
}

std::array<double, 3> cross(const std::array<double, 3>& a, const std::array<double, 3>& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

}  // namespace

matrix translate_matrix(const vector& offset) {
    elements e = identity();
    e[3] = offset.x;
    e[7] = offset.y;
    e[11] = offset.z;
    return from(e);
}

matrix scale_matrix(double sx, double sy, double sz) {
    elements e = identity();
    e[0] = sx;
    e[5] = sy;
    e[10] = sz;
    return from(e);
}

namespace {

/// The rotation by `radians` in the plane of axes a and b (a quarter turn takes a to b).
matrix plane_rotation(std::size_t a, std::size_t b, double radians) {
    elements e = identity();
    const double c = std::cos(radians), s = std::sin(radians);
    e[4 * a + a] = c;
    e[4 * b + b] = c;
    e[4 * b + a] = s;
    e[4 * a + b] = -s;
    return from(e);
}

}  // namespace

matrix rotate_x_matrix(double radians) { return plane_rotation(1, 2, radians); }
matrix rotate_y_matrix(double radians) { return plane_rotation(2, 0, radians); }
matrix rotate_z_matrix(double radians) { return plane_rotation(0, 1, radians); }

matrix rotate_matrix(const vector& axis, double radians) {
    if (axis.x == 0 && axis.y == 0 && axis.z == 0) throw usage_error("rotate_matrix: the axis is zero");
    const auto k = unit3(axis.x, axis.y, axis.z);
    const double w = std::cos(radians / 2), s = std::sin(radians / 2);
    const double x = k[0] * s, y = k[1] * s, z = k[2] * s;
    const double ww = w * w, xx = x * x, yy = y * y, zz = z * z;
    elements e = identity();
    e[0] = ww + xx - yy - zz;
    e[1] = 2 * (x * y - w * z);
    e[2] = 2 * (x * z + w * y);
    e[4] = 2 * (x * y + w * z);
    e[5] = ww - xx + yy - zz;
    e[6] = 2 * (y * z - w * x);
    e[8] = 2 * (x * z - w * y);
    e[9] = 2 * (y * z + w * x);
    e[10] = ww - xx - yy + zz;
    return from(e);
}

matrix shear_matrix(double shx, double shy) {
    elements e = identity();
    e[2] = shx;
    e[6] = shy;
    return from(e);
}

matrix look_at_matrix(const point& eye, const point& look_at, const vector& up) {
    const double dx = look_at.x - eye.x, dy = look_at.y - eye.y, dz = look_at.z - eye.z;
    if (dx == 0 && dy == 0 && dz == 0) throw usage_error("look_at_matrix: eye and look_at are equal");
    if (up.x == 0 && up.y == 0 && up.z == 0) throw usage_error("look_at_matrix: up is zero");
    const auto f = unit3(dx, dy, dz);
    const auto side = cross(f, unit3(up.x, up.y, up.z));
    if (std::sqrt(side[0] * side[0] + side[1] * side[1] + side[2] * side[2]) <= 1e-15)
        throw usage_error("look_at_matrix: up is parallel to the view direction");
    const auto r = unit3(side[0], side[1], side[2]);
    const auto u = cross(r, f);
    const std::array<double, 3> rows[3] = {r, u, {-f[0], -f[1], -f[2]}};
    elements e = identity();
    for (std::size_t i = 0; i < 3; ++i) {
        for (std::size_t j = 0; j < 3; ++j) e[4 * i + j] = rows[i][j];
        e[4 * i + 3] = -(rows[i][0] * eye.x + rows[i][1] * eye.y + rows[i][2] * eye.z);
    }
    return from(e);
}

}  // namespace vl::stage01
