#pragma once
// Helpers shared by the look-at matrix and the camera: robust unit vectors and the eye's
// orthonormal frame.

#include "vl/tuples.hh"

namespace vl::stage01::geometry {

/// The x, y, z of `v` as a unit vector (w 0), safe for components near the overflow or
/// underflow limits. `v` must not be zero.
vector normalized(const vector& v);

/// True when x, y and z are all zero.
bool is_zero(const vector& v);

/// The eye's frame: right, up and forward (the view direction), all unit, with
/// right == forward % up.
struct frame {
    vector right, up, forward;
};

/// The frame looking from `eye` to `look_at` with the part of `up` perpendicular to the
/// view as its up. Throws vl::usage_error (naming `who`) when eye == look_at or when up
/// is zero or parallel to the view.
frame eye_frame(const point& eye, const point& look_at, const vector& up, const char* who);

}  // namespace vl::stage01::geometry
