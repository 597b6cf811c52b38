#pragma once
/// \file
/// \brief The result of intersecting a ray with a component.

namespace vl {

class rtab_component;

/// \brief Where a ray first meets a component, and which node of the tree it met.
///
/// The thesis's rules, which every intersect() must follow:
/// 1. **Primitive hit**: `t > 0` is the distance along the (unit-direction) ray, so the
///    hit point is `r.t_point(t)`, and `object` is the *deepest* node hit: the leaf.
/// 2. **No primitive hit**: `t == 0`. Then `object` is the composite whose bounding volume
///    the ray entered when it missed all of that composite's children (so the counters
///    can tell "entered a bound for nothing", the thesis's `t0_count`), or
/// 3. **No hit at all**: `t == 0` and `object == nullptr`.
///
/// A composite returns the hit with the smallest `t` among its children.
struct intersection {
    double t = 0;                            ///< distance to the hit, 0 when no primitive was hit
    const rtab_component* object = nullptr;  ///< deepest node hit (not owned), or nullptr

    /// Nothing was hit (rule 3).
    static constexpr intersection none() { return {}; }
    /// `object` is a primitive hit at distance `t` (rule 1; `t` must be > 0).
    static constexpr intersection at(double t, const rtab_component* object) { return {t, object}; }
    /// The ray entered `composite` but hit none of its primitives (rule 2).
    static constexpr intersection composite_only(const rtab_component* composite) { return {0, composite}; }

    /// True when a primitive was hit.
    constexpr bool hit() const { return t > 0 && object != nullptr; }
    /// True for rule 2.
    constexpr bool is_composite_only() const { return t == 0 && object != nullptr; }
    /// True for rule 3.
    constexpr bool is_miss() const { return object == nullptr; }
    /// True when this is a primitive hit nearer than `other`'s (or `other` is no hit).
    constexpr bool nearer_than(const intersection& other) const { return hit() && (!other.hit() || t < other.t); }
};

}  // namespace vl
