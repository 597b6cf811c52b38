#pragma once
/// \file
/// \brief A ray: the points `origin + t * direction` for `t > 0`.

#include <iosfwd>

#include "vl/tuples.hh"

namespace vl {

/// \brief A half-line from an origin along a unit direction.
///
/// The direction is always stored as a unit vector, so `t` is a distance along the ray.
/// The origin itself (t == 0) is not part of the ray: see rtab_component::zero_t().
class ray {
public:
    /// From the origin `(0, 0, 0)` along `-z`.
    ray() = default;
    /// The direction is normalised here; a zero direction gives a NaN direction.
    ray(const point& origin, const vector& direction)
        : origin_(origin), direction_(direction.unit()) {}

    const point& origin() const { return origin_; }        ///< where the ray starts (t == 0)
    const vector& direction() const { return direction_; }  ///< the unit direction
    /// `origin + t * direction`.
    point t_point(double t) const { return origin_ + t * direction_; }

    /// \name The point at distance t
    ///@{

    /// `t * r` and `r * t` are `r.t_point(t)`, so code can write the equation `o + t d`.
    friend point operator*(double t, const ray& r) { return r.t_point(t); }
    friend point operator*(const ray& r, double t) { return r.t_point(t); }
    ///@}

private:
    point origin_{0, 0, 0};
    vector direction_{0, 0, -1};
};

/// `ray (point (...), vector (...))`.
std::ostream& operator<<(std::ostream& s, const ray& r);

}  // namespace vl
