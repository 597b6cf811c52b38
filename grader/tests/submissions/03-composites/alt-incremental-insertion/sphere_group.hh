// A group of objects inside one sphere: BOUNDSPH, and each level of FRACSPH.
#pragma once

#include <cmath>
#include <memory>

#include "stage_03.hh"

namespace vl::stage03 {

/// True when both corners of `c`'s box are finite.
inline bool has_finite_box(const rtab_component& c) {
    const point a = c.min_point(), b = c.max_point();
    return std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z) && std::isfinite(b.x) &&
           std::isfinite(b.y) && std::isfinite(b.z);
}

class sphere_group : public rtab_composite {
public:
    std::string type_name() const override { return "BOUNDSPH"; }
    void read(scene_reader& in) override;
    void insert(std::unique_ptr<rtab_component> child) override;
    void delete_all_children() override;
    point min_point() const override { return children_.empty() ? NaN_point : low_; }
    point max_point() const override { return children_.empty() ? NaN_point : high_; }

protected:
    /// Adds a child with a finite box; the box and the sphere around it grow.
    void take(std::unique_ptr<rtab_component> child);
    /// A smaller sphere that still holds every child.
    void tighten(const point& centre, double radius) {
        middle_ = centre;
        reach_ = radius;
    }

private:
    intersection find_intersection(const ray& r) const override;

    point low_ = NaN_point, high_ = NaN_point;
    point middle_ = NaN_point;
    double reach_ = 0;
};

}  // namespace vl::stage03
