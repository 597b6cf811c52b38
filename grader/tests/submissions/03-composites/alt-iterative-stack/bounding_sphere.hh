// The bounding sphere's class, shared by bounding_sphere.cc and frac_sphere.cc (a fractal
// sphere is a bounding sphere that makes its own children). See stage_03.hh for what each
// function must do. You may change this file: add members and helpers as you need.
#pragma once

#include <memory>

#include "stage_03.hh"

namespace vl::stage03 {

/// True when `c`'s box is known: both corners finite (bounding_sphere.cc; bvh.cc uses it too).
bool finite_box(const rtab_component& c);

/// \brief The thesis's container: children inside one sphere, which every ray tests first.
class bounding_sphere : public rtab_composite {
public:
    std::string type_name() const override { return "BOUNDSPH"; }
    void read(scene_reader& in) override;
    /// Refuses a child with an unknown box; then the sphere grows around the new child.
    void insert(std::unique_ptr<rtab_component> child) override;
    void delete_all_children() override;
    point min_point() const override { return lo_; }
    point max_point() const override { return hi_; }

protected:
    /// Adds `child` (whose box is known) and grows the box and the sphere around it.
    void adopt(std::unique_ptr<rtab_component> child);
    /// Replaces the sphere around the children's boxes by a tighter one that still holds
    /// every child (a fractal sphere knows its own).
    void set_sphere(const point& center, double radius) {
        bound_center_ = center;
        bound_radius_ = radius;
    }

private:
    intersection find_intersection(const ray& r) const override;

    point lo_ = NaN_point, hi_ = NaN_point;  // the union of the children's boxes
    point bound_center_ = NaN_point;         // the sphere every ray tests first
    double bound_radius_ = 0;
};

}  // namespace vl::stage03
