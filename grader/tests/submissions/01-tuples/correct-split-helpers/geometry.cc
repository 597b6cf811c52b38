#include "geometry.hh"

#include <algorithm>
#include <cmath>
#include <string>

#include "vl/error.hh"

namespace vl::stage01::geometry {

vector normalized(const vector& v) {
    const double scale = std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
    vector s(v.x / scale, v.y / scale, v.z / scale);
    return s / std::sqrt(s * s);
}

bool is_zero(const vector& v) { return v.x == 0 && v.y == 0 && v.z == 0; }

frame eye_frame(const point& eye, const point& look_at, const vector& up, const char* who) {
    const vector view = look_at - eye;
    if (is_zero(view)) throw usage_error(std::string(who) + ": eye and look_at are the same point");
    if (is_zero(up)) throw usage_error(std::string(who) + ": up is the zero vector");
    frame f;
    f.forward = normalized(view);
    // Gram-Schmidt: the part of up perpendicular to forward.
    const vector u = normalized(up);
    const vector perpendicular = u - f.forward * (u * f.forward);
    if (perpendicular.length() < 1e-14) throw usage_error(std::string(who) + ": up is parallel to the view direction");
    f.up = normalized(perpendicular);
    f.right = normalized(f.forward % f.up);
    f.up = f.right % f.forward;  // exactly perpendicular to both, up to rounding
    return f;
}

}  // namespace vl::stage01::geometry
