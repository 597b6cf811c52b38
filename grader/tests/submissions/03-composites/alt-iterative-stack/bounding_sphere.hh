// The bounding sphere's class, shared by bounding_sphere.cc and frac_sphere.cc (a fractal
// sphere is a bounding sphere that makes its own children); its shell is
// vl::shapes::bounding_sphere_base.
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
    intersection find_intersection(const ray& r) const override;
};

}  // namespace vl::stage03
