// The bounding sphere's class, shared by bounding_sphere.cc and frac_sphere.cc (a fractal
// sphere is a bounding sphere that makes its own children). See stage_03.hh for what each
// function must do. You may change this file: add members and helpers as you need.
//
// What is done is in the base class, vl::shapes::bounding_sphere_base
// (framework/include/vl/composite_bases.hh): the type name, reading the children,
// delete_all_children(), min_point() and max_point() (the box lo_ to hi_), set_sphere(),
// and the members lo_, hi_, bound_center_ and bound_radius_ that your functions keep.
#pragma once

#include "vl/composite_bases.hh"

namespace vl::stage03 {

/// \brief The thesis's container: children inside one sphere, which every ray tests first.
class bounding_sphere : public shapes::bounding_sphere_base {
public:
    /// Refuses a child with an unknown box; then the sphere grows around the new child.
    void insert(std::unique_ptr<rtab_component> child) override;

protected:
    /// Adds `child` (whose box is known) and grows the box and the sphere around it.
    void adopt(std::unique_ptr<rtab_component> child) override;

private:
    /// The sphere first, then the children (bounding_sphere.cc).
    intersection find_intersection(const ray& r) const override;
};

}  // namespace vl::stage03
