#pragma once
/// \file
/// \brief The abstract bases of everything a ray can hit: the *Composite* pattern.
///
/// A **leaf** (sphere, polygon, ...) derives from rtab_component; a **composite** (a list,
/// a bounding sphere, a BVH, ...) derives from rtab_composite. **Clients** (tracers) use
/// both only through rtab_component, so a tracer never asks what kind of object it hit.

#include <iosfwd>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "vl/intersection.hh"
#include "vl/ray.hh"
#include "vl/stats.hh"
#include "vl/tuples_based.hh"

namespace vl {

class scene_reader;

/// \brief Anything a ray can be intersected with, primitive or composite.
///
/// **Counted intersection.** intersect() is public and non-virtual: it counts the call
/// (vl/stats.hh), then calls the private virtual find_intersection() that each concrete
/// class overrides. A composite reaches a child only through the child's intersect(),
/// so every test is counted once, and the grader can hold an acceleration structure to
/// a number of tests per ray instead of a wall-clock time.
///
/// **Defaults** (the thesis's): bounds unknown (NaN points), no interior (`contains` is
/// false), `insert` and `delete_all_children` refuse, and every surface-physics member
/// says "absent", so an object that does not define one can still be used by a tracer
/// that reads it.
class rtab_component {
public:
    virtual ~rtab_component() = default;
    rtab_component(const rtab_component&) = delete;
    rtab_component& operator=(const rtab_component&) = delete;

    /// The first hit of `r` with this object, following the rules written at
    /// vl::intersection. Counts one test in this thread's counters.
    intersection intersect(const ray& r) const {
        const intersection i = find_intersection(r);
        const int outcome = i.object == nullptr ? detail::miss_outcome
                            : i.t == 0          ? detail::composite_only_outcome
                                                : detail::hit_outcome;
        ++detail::thread_tallies.calls[composite_][outcome];
        return i;
    }

    /// True for rtab_composite and its descendants.
    bool is_composite() const { return composite_; }

    /// The scene-file name of this object's type (`SPHERE`, `LIST`, ...).
    virtual std::string type_name() const = 0;

    /// The outward unit normal at `p`, a point on the surface. "Outward" assumes the
    /// viewer is outside; a tracer negates it when contains() says it is inside.
    /// Composites need not define it (default: NaN_vector).
    virtual vector normal(const point& p) const;

    /// Lower-left-back corner of an axis-aligned box around the object (default NaN_point:
    /// unknown, so a bounding volume cannot use this object's extent).
    virtual point min_point() const { return NaN_point; }
    /// Upper-right-front corner of the box (default NaN_point).
    virtual point max_point() const { return NaN_point; }
    /// True when `p` lies inside the object. Objects without an interior: false.
    virtual bool contains(const point& p) const;

    /// \brief A ball that holds every point where a ray can hit the object.
    struct ball {
        point center = NaN_point;  ///< its centre
        double radius = NaN;       ///< NaN: the object gives none
    };
    /// A ball around the object, for an object that a ball fits more tightly than its box
    /// (a sphere: itself). A composite may test a ray against it before calling
    /// intersect(), as part of that child's bounding-volume test: a ray whose line misses
    /// the ball cannot hit the object. Default: none (radius NaN), so only the box is used.
    virtual ball bounding_ball() const { return {}; }

    /// Distances `t` at or below zero_t() are not hits: the ray starts there. Compare
    /// `t > zero_t()`, never `t > 0`, so a ray leaving a surface does not hit that surface
    /// again through round-off ("acne"). A negative zero_t() marks an object meant to be
    /// seen from inside; intersect() then compares with its absolute value.
    virtual double zero_t() const { return default_zero_t; }
    static constexpr double default_zero_t = 1e-6;  ///< zero_t() of an object that does not override it

    /// Reads the object's description (what follows its type name in a scene file).
    /// Default: nothing to read.
    virtual void read(scene_reader& in);
    /// Writes the object in the scene format, starting with its type name, so that
    /// read() of what write() wrote gives the same object.
    virtual void write(std::ostream& s) const;

    /// Adds a child. Leaves refuse: this default throws vl::usage_error naming the type.
    virtual void insert(std::unique_ptr<rtab_component> child);
    /// Removes and destroys every child. Leaves refuse: this default throws.
    virtual void delete_all_children();

    /// \name Surface physics (the Hall shading model)
    /// Each default means "this object does not have it": no diffuse or specular
    /// reflection, no transmission. A tracer that reads a member an object does not
    /// define therefore adds nothing for it.
    ///@{
    virtual color clr() const { return WHITE; }  ///< surface colour (a filter on light)
    virtual double kdr() const { return 0; }     ///< diffuse reflection coefficient
    virtual double ksr() const { return 0; }     ///< specular reflection coefficient
    virtual double kdt() const { return 0; }     ///< diffuse transmission coefficient
    virtual double kst() const { return 0; }     ///< specular transmission coefficient
    virtual double n() const { return 1; }       ///< specular (Phong) exponent
    virtual double ior() const { return 1; }     ///< index of refraction (1: like the air)
    ///@}

protected:
    /// `composite` is set only by rtab_composite.
    explicit rtab_component(bool composite = false) : composite_(composite) {}

private:
    /// The uncounted intersection test each concrete class defines.
    virtual intersection find_intersection(const ray& r) const = 0;

    const bool composite_;
};

/// \brief A component made of components; owns its children.
///
/// The default insert() appends and delete_all_children() clears. A composite for which
/// insertion makes no sense (a box built of six polygons) overrides insert() to refuse.
/// Children are reachable only through their counted intersect().
class rtab_composite : public rtab_component {
public:
    void insert(std::unique_ptr<rtab_component> child) override;
    void delete_all_children() override { children_.clear(); }
    void write(std::ostream& s) const override;

    /// The children, in insertion order.
    std::span<const std::unique_ptr<rtab_component>> children() const { return children_; }
    std::size_t num_children() const { return children_.size(); }  ///< how many children

    /// The union of the children's boxes; NaN_point if any child's box is unknown.
    point min_point() const override;
    point max_point() const override;
    /// True when any child contains `p`.
    bool contains(const point& p) const override;

protected:
    rtab_composite() : rtab_component(true) {}
    /// The nearest primitive hit among all children (no bound: a miss is a miss).
    intersection nearest_child_hit(const ray& r) const;
    /// The refusals every composite's insert() shares: throws vl::usage_error for no
    /// object (a null pointer) and for this composite itself. The default insert() calls
    /// it and appends; a composite whose insert() keeps its children its own way (a
    /// bounding sphere that grows around each) calls it first, adds its own refusals,
    /// then keeps the child.
    void check_insertable(const rtab_component* child) const;

    std::vector<std::unique_ptr<rtab_component>> children_;  ///< the owned children, in insertion order
};

/// Writes `c` in the scene format (the thesis's `<<` for components).
std::ostream& operator<<(std::ostream& s, const rtab_component& c);

}  // namespace vl
