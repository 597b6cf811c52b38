// Transform builders. rotate_matrix uses Rodrigues' formula element by element:
// R = cos(a) I + sin(a) [k]x + (1 - cos(a)) k k^T (Wikipedia, "Rodrigues' rotation
// formula"), with 1 - cos(a) computed as 2 sin^2(a / 2).
#include <cmath>

#include "geometry.hh"
#include "stage_01.hh"
#include "vl/error.hh"

namespace vl::stage01 {

matrix translate_matrix(const vector& offset) {
    return {point(1, 0, 0, 0), point(0, 1, 0, 0), point(0, 0, 1, 0), point(offset.x, offset.y, offset.z, 1)};
}

matrix scale_matrix(double sx, double sy, double sz) {
    return {vector(sx, 0, 0, 0), vector(0, sy, 0, 0), vector(0, 0, sz, 0), vector(0, 0, 0, 1)};
}

matrix rotate_x_matrix(double radians) {
    const double c = std::cos(radians), s = std::sin(radians);
    // Columns: the images of x, y, z and of the origin.
    return {point(1, 0, 0, 0), point(0, c, s, 0), point(0, -s, c, 0), point(0, 0, 0, 1)};
}

matrix rotate_y_matrix(double radians) {
    const double c = std::cos(radians), s = std::sin(radians);
    return {point(c, 0, -s, 0), point(0, 1, 0, 0), point(s, 0, c, 0), point(0, 0, 0, 1)};
}

matrix rotate_z_matrix(double radians) {
    const double c = std::cos(radians), s = std::sin(radians);
    return {point(c, s, 0, 0), point(-s, c, 0, 0), point(0, 0, 1, 0), point(0, 0, 0, 1)};
}

matrix rotate_matrix(const vector& axis, double radians) {
    if (geometry::is_zero(axis)) throw usage_error("rotate_matrix: the axis must not be the zero vector");
    const vector k = geometry::normalized(axis);
    const double c = std::cos(radians), s = std::sin(radians), h = std::sin(radians / 2), t = 2 * h * h;
    return {c + t * k.x * k.x, t * k.x * k.y - s * k.z, t * k.x * k.z + s * k.y, 0,
            t * k.y * k.x + s * k.z, c + t * k.y * k.y, t * k.y * k.z - s * k.x, 0,
            t * k.z * k.x - s * k.y, t * k.z * k.y + s * k.x, c + t * k.z * k.z, 0,
            0, 0, 0, 1};
}

matrix shear_matrix(double shx, double shy) {
    return {point(1, 0, 0, 0), point(0, 1, 0, 0), point(shx, shy, 1, 0), point(0, 0, 0, 1)};
}

matrix look_at_matrix(const point& eye, const point& look_at, const vector& up) {
    const geometry::frame f = geometry::eye_frame(eye, look_at, up, "look_at_matrix");
    const vector& r = f.right;
    const vector& u = f.up;
    const vector b = -f.forward;
    const double ex = eye.x, ey = eye.y, ez = eye.z;
    return {r.x, r.y, r.z, -(r.x * ex + r.y * ey + r.z * ez),
            u.x, u.y, u.z, -(u.x * ex + u.y * ey + u.z * ez),
            b.x, b.y, b.z, -(b.x * ex + b.y * ey + b.z * ez),
            0, 0, 0, 1};
}

}  // namespace vl::stage01
