#pragma once
/// \file
/// \brief Helpers for stage 01's public tests: distances between tuples and matrices,
/// and how the tests of every stage print numbers, tuples and rays in their messages.
/// You need not read this file to do the assignment.

#include <algorithm>
#include <charconv>
#include <cmath>
#include <string>

#include "stage_01.hh"
#include "vl/ray.hh"

namespace vl::test01 {

/// The largest absolute difference of the x, y, z components (w is compared by `==`
/// where a test cares about it).
inline double distance(const vector& a, const vector& b) {
    return std::max({std::abs(a.x - b.x), std::abs(a.y - b.y), std::abs(a.z - b.z)});
}
/// The largest absolute difference of the homogenized x, y, z.
inline double distance(const point& a, const point& b) {
    const point p = a.homogenized(), q = b.homogenized();
    return std::max({std::abs(p.x - q.x), std::abs(p.y - q.y), std::abs(p.z - q.z)});
}
/// The largest absolute difference of the 16 elements.
inline double distance(const matrix& a, const matrix& b) {
    double d = 0;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) d = std::max(d, std::abs(a(r, c) - b(r, c)));
    return d;
}

/// The infinity norm: the largest sum of absolute values along a row.
inline double norm(const matrix& m) {
    double n = 0;
    for (int r = 0; r < 4; ++r)
        n = std::max(n, std::abs(m(r, 0)) + std::abs(m(r, 1)) + std::abs(m(r, 2)) + std::abs(m(r, 3)));
    return n;
}

/// True when every element of `m` is NaN.
inline bool all_nan(const matrix& m) {
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c)
            if (!std::isnan(m(r, c))) return false;
    return true;
}

/// The angle between two directions, in degrees.
inline double degrees_between(const vector& a, const vector& b) {
    const double c = (a * b) / (a.length() * b.length());
    return std::acos(std::clamp(c, -1.0, 1.0)) * 180 / 3.14159265358979323846;
}

/// The unit round-off of double, 2^-53.
inline constexpr double unit_roundoff = 0x1p-53;

// ---------------------------------------------------------------------------------------
// Printing values in messages (the later stages' tests print through these too)
// ---------------------------------------------------------------------------------------

/// `x` in the shortest form that reads back as exactly `x` (so a tolerance such as 1e-12
/// is never printed as 0.0, and two different numbers never print alike).
inline std::string num(double x) {
    if (std::isnan(x)) return "NaN";
    if (std::isinf(x)) return x > 0 ? "infinity" : "-infinity";
    char buf[64];
    const auto r = std::to_chars(buf, buf + sizeof buf, x);
    return std::string(buf, r.ptr);
}
/// `(x, y, z)` of a point (homogenized) or a vector, each at full precision.
inline std::string show(const point& p) {
    const point h = p.w == 1 ? p : p.homogenized();
    return "(" + num(h.x) + ", " + num(h.y) + ", " + num(h.z) + ")";
}
inline std::string show(const vector& v) { return "(" + num(v.x) + ", " + num(v.y) + ", " + num(v.z) + ")"; }
/// The ray in words: "the ray from (..) towards (..)".
inline std::string show(const ray& r) { return "the ray from " + show(r.origin()) + " towards " + show(r.direction()); }
/// A matrix row by row: "[a b c d; e f g h; ...]".
inline std::string show(const matrix& m) {
    std::string s = "[";
    for (int r = 0; r < 4; ++r) {
        for (int c = 0; c < 4; ++c) s += num(m(r, c)) + (c < 3 ? " " : "");
        s += r < 3 ? "; " : "]";
    }
    return s;
}

/// The camera settings of a view: from `eye` towards `look_at`, `up` up, a vertical field
/// of view of `fov` degrees.
inline camera_settings settings(const point& eye, const point& look_at, const vector& up, double fov) {
    camera_settings s;
    s.eye = eye;
    s.look_at = look_at;
    s.up = up;
    s.fov_degrees = fov;
    return s;
}

}  // namespace vl::test01
