// The bounding sphere, shared by bounding_sphere.cc and frac_sphere.cc: children inside
// one sphere that every ray tests first. The union of the children's boxes is kept as six
// numbers (the low and high end of each axis), the sphere as a centre and a radius.
#pragma once

#include <array>
#include <memory>
#include <string>

#include "stage_03.hh"

namespace vl::stage03 {

/// True when both corners of `c`'s box are finite numbers (a box that can be bounded).
bool box_is_finite(const rtab_component& c);

class sphere_bound : public rtab_composite {
public:
    std::string type_name() const override { return "BOUNDSPH"; }
    void read(scene_reader& in) override;
    void insert(std::unique_ptr<rtab_component> child) override;
    void delete_all_children() override;
    point min_point() const override;
    point max_point() const override;

protected:
    /// Appends a child whose box is known, widens the six numbers around its box and puts
    /// the sphere around the widened box.
    void take(std::unique_ptr<rtab_component> child);
    /// Replaces the sphere by another that still holds every child.
    void use_sphere(const point& center, double radius) {
        center_ = center;
        radius_ = radius;
    }

private:
    intersection find_intersection(const ray& r) const override;

    // extent_[2 * a] and extent_[2 * a + 1]: the low and high end of axis a (x, y, z).
    std::array<double, 6> extent_{NaN, NaN, NaN, NaN, NaN, NaN};
    point center_ = NaN_point;
    double radius_ = 0;
};

}  // namespace vl::stage03
