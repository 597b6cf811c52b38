// Reference: the transform builders (see assignments/01-tuples/stage_01.hh).
//
// Column vectors, so each matrix is the textbook one (J. D. Foley, A. van Dam, S. K. Feiner
// and J. F. Hughes, *Computer Graphics: Principles and Practice*, 2nd ed., ch. 5), not its
// transpose as in the thesis's row-vector notation.
#include <cmath>

#include "stage_01.hh"
#include "vl/error.hh"

namespace vl::stage01 {

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

// Rodrigues' rotation formula, R = c I + s [a]x + (1 - c) a a^T for the unit axis a
// (T. Akenine-Möller et al., *Real-Time Rendering*, 4th ed., §4.2.4).
matrix rotate_matrix(const vector& axis, double radians) {
    // std::hypot neither overflows for an axis of length 1e200 nor underflows for 1e-200,
    // where sqrt(x*x + y*y + z*z) would give infinity or zero.
    const double length = std::hypot(axis.x, axis.y, axis.z);
    if (length == 0) throw usage_error("rotate_matrix: the axis is the zero vector, which has no direction");
    const double x = axis.x / length, y = axis.y / length, z = axis.z / length;
    const double c = std::cos(radians), s = std::sin(radians);
    // 1 - cos(a) cancels catastrophically for small a (1 - 0.99999999 keeps few digits);
    // 2 sin^2(a / 2) is the same number computed without the cancellation.
    const double half = std::sin(radians / 2), t = 2 * half * half;
    return {t * x * x + c, t * x * y - s * z, t * x * z + s * y, 0,
            t * x * y + s * z, t * y * y + c, t * y * z - s * x, 0,
            t * x * z - s * y, t * y * z + s * x, t * z * z + c, 0,
            0, 0, 0, 1};
}

// The thesis's shear_matrix: x and y sheared in proportion to z, as the shear SH_par
// that Foley et al. (§6.5) use to normalise an oblique view volume.
matrix shear_matrix(double shx, double shy) {
    return {1, 0, shx, 0,
            0, 1, shy, 0,
            0, 0, 1, 0,
            0, 0, 0, 1};
}

// The matrix of gluLookAt (OpenGL Utility Library, GLU 1.3 specification, §4.1): the rows
// of its rotation are the eye's right, up and backward directions in world coordinates,
// and the translation takes the eye to the origin.
matrix look_at_matrix(const point& eye, const point& look_at, const vector& up) {
    const point e = eye.homogenized();
    const vector view = look_at.homogenized() - e;
    if (view.x == 0 && view.y == 0 && view.z == 0)
        throw usage_error("look_at_matrix: eye and look_at are the same point, so there is no view direction");
    const vector side = view % up;
    if (side.x == 0 && side.y == 0 && side.z == 0)
        throw usage_error("look_at_matrix: up is zero or parallel to the view direction; choose an up that is not");
    const vector f = view.unit(), r = side.unit();
    const vector u = r % f;  // unit already, up to rounding: r and f are perpendicular unit vectors
    const vector o = e - point(0, 0, 0);
    return {r.x, r.y, r.z, -(r * o),
            u.x, u.y, u.z, -(u * o),
            -f.x, -f.y, -f.z, f * o,
            0, 0, 0, 1};
}

}  // namespace vl::stage01
