// Transform builders. The look-at matrix undoes the eye's placement (turn the axes onto
// the eye's frame, then move to the eye): move back, then turn back with the transpose.
#include <cmath>

#include "stage_01.hh"
#include "vl/error.hh"

namespace vl::stage01 {

namespace {

vector normalize(const vector& v) {
    const double len = std::hypot(v.x, v.y, v.z);
    return vector(v.x / len, v.y / len, v.z / len);
}

bool zero(const vector& v) { return v.x == 0 && v.y == 0 && v.z == 0; }

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
    const double c = std::cos(radians), s = std::sin(radians);
    matrix m;
    m(1, 1) = c;
    m(1, 2) = -s;
    m(2, 1) = s;
    m(2, 2) = c;
    return m;
}

matrix rotate_y_matrix(double radians) {
    const double c = std::cos(radians), s = std::sin(radians);
    matrix m;
    m(2, 2) = c;
    m(2, 0) = -s;
    m(0, 2) = s;
    m(0, 0) = c;
    return m;
}

matrix rotate_z_matrix(double radians) {
    const double c = std::cos(radians), s = std::sin(radians);
    matrix m;
    m(0, 0) = c;
    m(0, 1) = -s;
    m(1, 0) = s;
    m(1, 1) = c;
    return m;
}

matrix rotate_matrix(const vector& axis, double radians) {
    if (zero(axis)) throw usage_error("rotate_matrix: axis (0, 0, 0) has no direction");
    const vector k = normalize(axis);
    const double c = std::cos(radians), s = std::sin(radians);
    const double versine = 2 * std::sin(radians / 2) * std::sin(radians / 2);  // 1 - cos, without the subtraction
    matrix m;
    m(0, 0) = c + k.x * k.x * versine;
    m(0, 1) = k.x * k.y * versine - k.z * s;
    m(0, 2) = k.x * k.z * versine + k.y * s;
    m(1, 0) = k.y * k.x * versine + k.z * s;
    m(1, 1) = c + k.y * k.y * versine;
    m(1, 2) = k.y * k.z * versine - k.x * s;
    m(2, 0) = k.z * k.x * versine - k.y * s;
    m(2, 1) = k.z * k.y * versine + k.x * s;
    m(2, 2) = c + k.z * k.z * versine;
    return m;
}

matrix shear_matrix(double shx, double shy) {
    matrix m;
    m(0, 2) = shx;
    m(1, 2) = shy;
    return m;
}

matrix look_at_matrix(const point& eye, const point& look_at, const vector& up) {
    if (zero(look_at - eye)) throw usage_error("look_at_matrix: eye == look_at");
    if (zero(up)) throw usage_error("look_at_matrix: up is zero");
    const vector f = normalize(look_at - eye);
    const vector side = f % normalize(up);
    if (side.length() < 1e-15) throw usage_error("look_at_matrix: up is parallel to the view direction");
    const vector r = normalize(side), u = r % f;
    // The eye's placement: columns r, u, -f (where the eye's axes point) and the eye.
    const matrix turn(point(r.x, r.y, r.z, 0), point(u.x, u.y, u.z, 0), point(-f.x, -f.y, -f.z, 0), point(0, 0, 0, 1));
    // Undoing it: undo the move, then the turn (a rotation's inverse is its transpose).
    return turn.transpose() * translate_matrix(point(0, 0, 0) - eye);
}

}  // namespace vl::stage01
