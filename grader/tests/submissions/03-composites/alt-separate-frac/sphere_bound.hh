// BOUNDSPH's class.
#pragma once

#include <memory>

#include "stage_03.hh"

namespace vl::stage03 {

/// True when min_point() and max_point() of `c` are finite (a bounding volume can hold it).
bool box_known(const rtab_component& c);

class sphere_bound final : public rtab_composite {
public:
    std::string type_name() const override { return "BOUNDSPH"; }
    void read(scene_reader& in) override;
    void insert(std::unique_ptr<rtab_component> child) override;
    void delete_all_children() override;
    point min_point() const override { return min_; }
    point max_point() const override { return max_; }

private:
    intersection find_intersection(const ray& r) const override;

    point min_ = NaN_point, max_ = NaN_point;
    point centre_ = NaN_point;
    double radius_ = 0;
};

}  // namespace vl::stage03
