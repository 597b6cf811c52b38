// Transform builders. The general rotation turns each axis vector with the unit
// quaternion q = (cos(a/2), sin(a/2) k) as q v q*, and the images of x, y, z are the
// matrix's columns.
#include <cmath>

#include "stage_01.hh"
#include "vl/error.hh"

namespace vl::stage01 {

namespace {

struct quaternion {
    double w, x, y, z;
};

quaternion operator*(const quaternion& a, const quaternion& b) {
    return {a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z, a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
            a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x, a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}

point turned(const quaternion& q, double vx, double vy, double vz) {
    const quaternion conj{q.w, -q.x, -q.y, -q.z};
    const quaternion r = q * quaternion{0, vx, vy, vz} * conj;
    return {r.x, r.y, r.z, 0};
}

double largest_magnitude(const vector& v) { return std::fmax(std::fabs(v.x), std::fmax(std::fabs(v.y), std::fabs(v.z))); }

vector unit_of(const vector& v) {
    const double m = largest_magnitude(v);
    const vector s(v.x / m, v.y / m, v.z / m);
    return s / s.length();
}

}  // namespace

matrix translate_matrix(const vector& offset) {
    matrix m;
    for (int r = 0; r < 3; ++r) m(r, 3) = r == 0 ? offset.x : r == 1 ? offset.y : offset.z;
    return m;
}

matrix scale_matrix(double sx, double sy, double sz) {
    return {sx, 0, 0, 0, 0, sy, 0, 0, 0, 0, sz, 0, 0, 0, 0, 1};
}

matrix rotate_x_matrix(double radians) {
    const double c = std::cos(radians), s = std::sin(radians);
    return {1, 0, 0, 0, 0, c, -s, 0, 0, s, c, 0, 0, 0, 0, 1};
}

matrix rotate_y_matrix(double radians) {
    const double c = std::cos(radians), s = std::sin(radians);
    return {c, 0, s, 0, 0, 1, 0, 0, -s, 0, c, 0, 0, 0, 0, 1};
}

matrix rotate_z_matrix(double radians) {
    const double c = std::cos(radians), s = std::sin(radians);
    return {c, -s, 0, 0, s, c, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
}

matrix rotate_matrix(const vector& axis, double radians) {
    if (largest_magnitude(axis) == 0) throw usage_error("rotate_matrix: cannot rotate about the zero vector");
    const vector k = unit_of(axis);
    const double s = std::sin(radians / 2);
    const quaternion q{std::cos(radians / 2), k.x * s, k.y * s, k.z * s};
    return {turned(q, 1, 0, 0), turned(q, 0, 1, 0), turned(q, 0, 0, 1), point(0, 0, 0, 1)};
}

matrix shear_matrix(double shx, double shy) {
    return {1, 0, shx, 0, 0, 1, shy, 0, 0, 0, 1, 0, 0, 0, 0, 1};
}

matrix look_at_matrix(const point& eye, const point& look_at, const vector& up) {
    const vector view = look_at - eye;
    if (largest_magnitude(view) == 0) throw usage_error("look_at_matrix: eye and look_at coincide");
    if (largest_magnitude(up) == 0) throw usage_error("look_at_matrix: up must not be zero");
    const vector z = -unit_of(view);  // the eye looks down its -z
    const vector cross = unit_of(up) % z;
    if (cross.length() <= 1e-15) throw usage_error("look_at_matrix: up is parallel to the view");
    const vector x = unit_of(cross);  // up % back == view % up: the right
    const vector y = z % x;
    const vector e(eye.x, eye.y, eye.z);
    return {vector(x.x, x.y, x.z, -(x * e)), vector(y.x, y.y, y.z, -(y * e)), vector(z.x, z.y, z.z, -(z * e)),
            vector(0, 0, 0, 1)};
}

}  // namespace vl::stage01
