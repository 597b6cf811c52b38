#pragma once
// Geometry in long double: points and vectors with the extra bits of the x87 format,
// for the intermediate results of the intersection tests.

#include "vl/tuples.hh"

namespace vl::stage02::wide {

struct vec {
    long double x = 0, y = 0, z = 0;
};

inline vec from(const point& p) { return {p.x, p.y, p.z}; }
inline vec from(const vector& v) { return {v.x, v.y, v.z}; }
inline vec operator-(const vec& a, const vec& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline vec operator*(long double s, const vec& a) { return {s * a.x, s * a.y, s * a.z}; }
inline long double dot(const vec& a, const vec& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

}  // namespace vl::stage02::wide
