#pragma once
/// \file
/// \brief Long-double 3-vectors for the hidden tests' answer keys: computed apart from the
/// submission's tuples, and with 11 more bits, so that a key's own rounding never decides
/// a check.

#include <cmath>
#include <utility>

#include "vl/tuples.hh"

namespace vl::grading {

using real = long double;

/// A point or direction in long double.
struct rvec {
    real x = 0, y = 0, z = 0;
};
/// A point (homogenized) or a vector in long double.
inline rvec to_r(const point& p) {
    const point h = p.homogenized();
    return {h.x, h.y, h.z};
}
inline rvec to_r(const vector& v) { return {v.x, v.y, v.z}; }
inline rvec operator-(const rvec& a, const rvec& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline rvec operator+(const rvec& a, const rvec& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline rvec operator-(const rvec& a) { return {-a.x, -a.y, -a.z}; }
inline rvec operator*(real s, const rvec& a) { return {s * a.x, s * a.y, s * a.z}; }
inline real dot(const rvec& a, const rvec& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline rvec cross(const rvec& a, const rvec& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline real len(const rvec& a) { return std::sqrt(dot(a, a)); }
inline rvec unit(const rvec& a) { return (1 / len(a)) * a; }
/// Rounded back to double.
inline point to_point(const rvec& a) {
    return point(static_cast<double>(a.x), static_cast<double>(a.y), static_cast<double>(a.z));
}
inline vector to_vector(const rvec& a) {
    return vector(static_cast<double>(a.x), static_cast<double>(a.y), static_cast<double>(a.z));
}

/// The long-double roots t0 <= t1 of a line with a sphere; `meets` is false when the line
/// passes beside it.
struct roots {
    bool meets = false;
    real t0 = 0, t1 = 0;
};
/// The roots of the line o + t d (d unit) with the sphere of centre `c` and `radius`.
inline roots sphere_roots(const rvec& o, const rvec& d, const rvec& c, real radius) {
    const rvec f = o - c;
    const real b = dot(f, d);
    const rvec l = f - b * d;
    const real disc = (radius - len(l)) * (radius + len(l));
    roots out;
    if (disc < 0) return out;
    const real q = -(b + std::copysign(std::sqrt(disc), b));
    const real cc = (len(f) - radius) * (len(f) + radius);
    real t0 = q == 0 ? 0 : cc / q, t1 = q;
    if (t0 > t1) std::swap(t0, t1);
    out.meets = true;
    out.t0 = t0;
    out.t1 = t1;
    return out;
}

}  // namespace vl::grading
