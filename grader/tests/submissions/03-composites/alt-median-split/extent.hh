// Axis-aligned boxes as the composites of this stage use them: grown child by child.
#pragma once

#include <cmath>

#include "vl/rt_base_objects.hh"

namespace vl::stage03 {

/// True when every coordinate of `p` is a finite number.
inline bool finite_point(const point& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

/// True when the box of `c` is known (both corners finite): only then can a bounding
/// volume be built around it.
inline bool box_is_known(const rtab_component& c) { return finite_point(c.min_point()) && finite_point(c.max_point()); }

/// \brief A box that starts empty and grows around what is added to it.
struct extent {
    point lo{INFINITY, INFINITY, INFINITY};
    point hi{-INFINITY, -INFINITY, -INFINITY};

    bool empty() const { return !(lo.x <= hi.x); }
    void add(const point& a, const point& b) {
        lo = point(std::fmin(lo.x, a.x), std::fmin(lo.y, a.y), std::fmin(lo.z, a.z));
        hi = point(std::fmax(hi.x, b.x), std::fmax(hi.y, b.y), std::fmax(hi.z, b.z));
    }
    void add(const point& p) { add(p, p); }
    void add(const extent& e) { add(e.lo, e.hi); }
    point middle() const { return point(0.5 * (lo.x + hi.x), 0.5 * (lo.y + hi.y), 0.5 * (lo.z + hi.z)); }
    /// Coordinate `axis` (0: x, 1: y, 2: z) of a point.
    static double along(const point& p, int axis) { return axis == 0 ? p.x : axis == 1 ? p.y : p.z; }
    /// The axis along which the box is longest.
    int longest_axis() const {
        const vector e = hi - lo;
        if (e.x >= e.y && e.x >= e.z) return 0;
        return e.y >= e.z ? 1 : 2;
    }
};

}  // namespace vl::stage03
