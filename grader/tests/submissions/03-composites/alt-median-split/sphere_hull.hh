// The bounding sphere's class, which the fractal spheres build on.
#pragma once

#include <memory>

#include "extent.hh"
#include "stage_03.hh"

namespace vl::stage03 {

/// \brief Children inside one sphere that every ray tests first.
class sphere_hull : public rtab_composite {
public:
    std::string type_name() const override { return "BOUNDSPH"; }
    void read(scene_reader& in) override;
    void insert(std::unique_ptr<rtab_component> child) override;
    void delete_all_children() override;
    point min_point() const override { return box_.empty() ? NaN_point : box_.lo; }
    point max_point() const override { return box_.empty() ? NaN_point : box_.hi; }

    /// Adds a child whose box is known, with no checks; the box grows around it and, unless
    /// the sphere was fixed with fix_sphere(), so does the sphere.
    void add_child(std::unique_ptr<rtab_component> child);
    /// Uses this sphere from now on, whatever the children's box (it must hold them all).
    void fix_sphere(const point& centre, double radius);
    /// The sphere every ray tests first.
    const point& sphere_centre() const { return centre_; }
    double sphere_radius() const { return radius_; }

private:
    intersection find_intersection(const ray& r) const override;

    extent box_;
    point centre_ = NaN_point;
    double radius_ = 0;
    bool fixed_ = false;
};

}  // namespace vl::stage03
