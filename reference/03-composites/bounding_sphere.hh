// Reference: the bounding sphere, whole in this header since frac_sphere.cc builds on it
// (see assignments/03-composites/stage_03.hh); its shell is vl::shapes::bounding_sphere_base.
#pragma once

#include <cmath>

#include "vl/bounds.hh"
#include "vl/composite_bases.hh"

namespace vl::stage03 {

/// \brief The thesis's container: children inside one sphere, which every ray tests first.
class bounding_sphere : public shapes::bounding_sphere_base {
public:
    /// Refuses a child with an unknown box; then the sphere grows around the new child.
    void insert(std::unique_ptr<rtab_component> child) override {
        check_insertable(child.get());  // a null pointer, the sphere itself
        if (!shapes::finite_box(*child))
            throw usage_error(type_name() + " cannot hold " + child->type_name() +
                              ": its box is unknown (it is unbounded or empty), so no sphere can hold it;"
                              " put it beside the " + type_name() + " in a LIST");
        adopt(std::move(child));  // the sphere grows around it
    }

protected:
    void adopt(std::unique_ptr<rtab_component> child) override {
        const point a = child->min_point(), b = child->max_point();
        if (children_.empty()) {
            lo_ = a;
            hi_ = b;
        } else {
            lo_ = point(std::fmin(lo_.x, a.x), std::fmin(lo_.y, a.y), std::fmin(lo_.z, a.z));
            hi_ = point(std::fmax(hi_.x, b.x), std::fmax(hi_.y, b.y), std::fmax(hi_.z, b.z));
        }
        children_.push_back(std::move(child));
        // The smallest sphere around the box: its centre, half its diagonal.
        bound_center_ = point((lo_.x + hi_.x) / 2, (lo_.y + hi_.y) / 2, (lo_.z + hi_.z) / 2);
        bound_radius_ = (hi_ - lo_).length() / 2;
    }

private:
    intersection find_intersection(const ray& r) const override {
        if (children_.empty() || !hits_sphere(r, bound_center_, bound_radius_)) return intersection::none();
        const intersection nearest = nearest_child_hit(r);
        return nearest.hit() ? nearest : intersection::composite_only(this);
    }
};

}  // namespace vl::stage03
