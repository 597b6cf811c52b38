// The bounding sphere, used by BOUNDSPH and by every level of FRACSPH.
#pragma once

#include <memory>

#include "geom3.hh"
#include "stage_03.hh"

namespace vl::stage03 {

class bsphere : public rtab_composite {
public:
    std::string type_name() const override { return "BOUNDSPH"; }
    void read(scene_reader& in) override;
    void insert(std::unique_ptr<rtab_component> child) override;
    void delete_all_children() override;
    point min_point() const override;
    point max_point() const override;

protected:
    /// Appends a child whose box is known and recomputes the sphere around the box.
    void append(std::unique_ptr<rtab_component> child);
    /// Sets a sphere of one's own (it must hold every child).
    void set_bound(const point& centre, double radius) {
        centre_ = centre;
        radius_ = radius;
    }

private:
    intersection find_intersection(const ray& r) const override;

    geom3::triple lo_{}, hi_{};
    point centre_ = NaN_point;
    double radius_ = 0;
};

}  // namespace vl::stage03
