// Small geometric helpers shared by this stage's files.
#pragma once

#include <array>
#include <cmath>
#include <ostream>

#include "vl/rt_base_objects.hh"

namespace vl::stage03::geom3 {

using triple = std::array<double, 3>;

inline triple xyz(const point& p) { return {p.x, p.y, p.z}; }
inline point as_point(const triple& t) { return point(t[0], t[1], t[2]); }

inline bool all_finite(const triple& t) {
    return std::isfinite(t[0]) && std::isfinite(t[1]) && std::isfinite(t[2]);
}

/// True when `c` has a box of finite corners.
inline bool bounded(const rtab_component& c) { return all_finite(xyz(c.min_point())) && all_finite(xyz(c.max_point())); }

/// Writes `x` so that reading it back gives the same double.
inline void number(std::ostream& out, double x) {
    const auto old = out.precision(17);
    out << x;
    out.precision(old);
}

}  // namespace vl::stage03::geom3
