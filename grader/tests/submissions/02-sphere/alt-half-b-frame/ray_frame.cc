#include "ray_frame.hh"

#include <cmath>

namespace vl::stage02 {

ray_frame::ray_frame(const ray& r) : origin_(r.origin()), w_(r.direction()) {
    const vector& d = w_;
    const double sign = std::copysign(1.0, d.z);
    const double a = -1 / (sign + d.z);
    const double b = d.x * d.y * a;
    u_ = vector(1 + sign * d.x * d.x * a, sign * b, -sign * d.x);
    v_ = vector(b, sign + d.y * d.y * a, -d.y);
}

}  // namespace vl::stage02
