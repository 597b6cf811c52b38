#pragma once
/// \file
/// \brief Bounding-volume tests for composites: an axis-aligned box and a sphere.
///
/// Both count one bounding-volume test in this thread's counters (vl/stats.hh), so an
/// acceleration structure's cost per ray is a number, not a time.

#include "vl/ray.hh"
#include "vl/tuples.hh"

namespace vl {

/// \brief The part of a ray inside a volume: `t` from `t_near` to `t_far`.
struct ray_span {
    double t_near = 0;  ///< where the ray enters (0 when it starts inside)
    double t_far = 0;   ///< where it leaves
};

/// Does `r` pass through the axis-aligned box [lo, hi] at some t in (0, t_max)? On a hit
/// fills `span` when given. Slab method (Kay and Kajiya 1986), written so that a ray
/// parallel to a slab, or starting on its plane, still gives the right answer: 1/0 is
/// +-infinity and the NaN of 0 * infinity is never used by a comparison.
bool hits_box(const ray& r, const point& lo, const point& hi, double t_max = 1e300, ray_span* span = nullptr);

/// Does `r` pass through the sphere at `center` with `radius` at some t > 0?
bool hits_sphere(const ray& r, const point& center, double radius);

}  // namespace vl
