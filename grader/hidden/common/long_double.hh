#pragma once
/// \file
/// \brief Long-double 3-vectors for the hidden tests' answer keys: computed apart from the
/// submission's tuples, and with 11 more bits, so that a key's own rounding never decides
/// a check.

#include <cmath>

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

}  // namespace vl::grading
