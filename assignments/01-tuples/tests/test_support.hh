#pragma once
/// \file
/// \brief Helpers for stage 01's public tests: distances between tuples and matrices.
/// You need not read this file to do the assignment.

#include <algorithm>
#include <cmath>

#include "stage_01.hh"

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

}  // namespace vl::test01
