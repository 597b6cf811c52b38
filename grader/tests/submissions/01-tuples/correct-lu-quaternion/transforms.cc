// Transform builders. The general rotation goes through a unit quaternion
// q = (cos(a/2), sin(a/2) * axis): its matrix needs no 1 - cos(a), so tiny angles keep
// their digits.
#include <algorithm>
#include <cmath>

#include "stage_01.hh"
#include "vl/error.hh"

namespace vl::stage01 {

namespace {

/// `v`'s x, y, z made length 1 without squaring huge or tiny components: scale by the
/// largest magnitude first.
vector unit_xyz(const vector& v) {
    const double big = std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
    const vector s(v.x / big, v.y / big, v.z / big);
    return s / s.length();
}

bool is_zero(const vector& v) { return v.x == 0 && v.y == 0 && v.z == 0; }

}  // namespace

matrix translate_matrix(const vector& offset) {
    return {1, 0, 0, offset.x,
            0, 1, 0, offset.y,
            0, 0, 1, offset.z,
            0, 0, 0, 1};
}

matrix scale_matrix(double sx, double sy, double sz) {
    return {sx, 0, 0, 0,
            0, sy, 0, 0,
            0, 0, sz, 0,
            0, 0, 0, 1};
}

matrix rotate_x_matrix(double radians) {
    const double c = std::cos(radians), s = std::sin(radians);
    return {1, 0, 0, 0,
            0, c, -s, 0,
            0, s, c, 0,
            0, 0, 0, 1};
}

matrix rotate_y_matrix(double radians) {
    const double c = std::cos(radians), s = std::sin(radians);
    return {c, 0, s, 0,
            0, 1, 0, 0,
            -s, 0, c, 0,
            0, 0, 0, 1};
}

matrix rotate_z_matrix(double radians) {
    const double c = std::cos(radians), s = std::sin(radians);
    return {c, -s, 0, 0,
            s, c, 0, 0,
            0, 0, 1, 0,
            0, 0, 0, 1};
}

matrix rotate_matrix(const vector& axis, double radians) {
    if (is_zero(axis)) throw usage_error("rotate_matrix: the axis is the zero vector, which has no direction; "
                                         "give a nonzero axis");
    const vector k = unit_xyz(axis);
    const double half = radians / 2;
    const double w = std::cos(half), s = std::sin(half);
    const double x = k.x * s, y = k.y * s, z = k.z * s;
    // The rotation matrix of the unit quaternion (w, x, y, z), acting on column vectors.
    return {1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y), 0,
            2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x), 0,
            2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y), 0,
            0, 0, 0, 1};
}

matrix shear_matrix(double shx, double shy) {
    return {1, 0, shx, 0,
            0, 1, shy, 0,
            0, 0, 1, 0,
            0, 0, 0, 1};
}

matrix look_at_matrix(const point& eye, const point& look_at, const vector& up) {
    const vector view = look_at - eye;
    if (is_zero(view)) throw usage_error("look_at_matrix: eye and look_at are the same point; move one of them");
    if (is_zero(up)) throw usage_error("look_at_matrix: up is the zero vector; give a direction");
    const vector forward = unit_xyz(view);
    const vector side = forward % unit_xyz(up);
    if (side.length() <= 4 * std::numeric_limits<double>::epsilon())
        throw usage_error("look_at_matrix: up is parallel to the view direction; choose another up");
    const vector right = unit_xyz(side);
    const vector true_up = right % forward;
    const vector back = -forward;
    const vector e(eye.x, eye.y, eye.z);
    // Rows: the eye's axes in world coordinates (the inverse of a rotation is its
    // transpose); the last column moves the eye to the origin after the turn.
    return {right.x, right.y, right.z, -(right * e),
            true_up.x, true_up.y, true_up.z, -(true_up * e),
            back.x, back.y, back.z, -(back * e),
            0, 0, 0, 1};
}

}  // namespace vl::stage01
