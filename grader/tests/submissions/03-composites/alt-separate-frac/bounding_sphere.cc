// BOUNDSPH: one sphere test, then the children.
#include <cmath>

#include "sphere_bound.hh"
#include "vl/bounds.hh"
#include "vl/scene_reader.hh"

namespace vl::stage03 {

bool box_known(const rtab_component& c) {
    const point a = c.min_point(), b = c.max_point();
    for (double x : {a.x, a.y, a.z, b.x, b.y, b.z})
        if (!std::isfinite(x)) return false;
    return true;
}

void sphere_bound::read(scene_reader& in) { in.read_children(*this); }

void sphere_bound::insert(std::unique_ptr<rtab_component> child) {
    if (child && child.get() != this && !box_known(*child))
        throw usage_error("BOUNDSPH cannot take " + child->type_name() + ": " + child->type_name() +
                          " has no finite box for the sphere to hold (unbounded or empty); place it beside the "
                          "BOUNDSPH in a LIST");
    rtab_composite::insert(std::move(child));  // refuses a null pointer and the sphere itself
    const rtab_component& added = *children_.back();
    const point a = added.min_point(), b = added.max_point();
    if (children_.size() == 1) {
        min_ = a;
        max_ = b;
    } else {
        min_ = point(std::fmin(min_.x, a.x), std::fmin(min_.y, a.y), std::fmin(min_.z, a.z));
        max_ = point(std::fmax(max_.x, b.x), std::fmax(max_.y, b.y), std::fmax(max_.z, b.z));
    }
    centre_ = point((min_.x + max_.x) * 0.5, (min_.y + max_.y) * 0.5, (min_.z + max_.z) * 0.5);
    radius_ = std::fmax((max_ - centre_).length(), (centre_ - min_).length());
}

void sphere_bound::delete_all_children() {
    rtab_composite::delete_all_children();
    min_ = max_ = centre_ = NaN_point;
    radius_ = 0;
}

intersection sphere_bound::find_intersection(const ray& r) const {
    if (children_.empty()) return intersection::none();
    if (!hits_sphere(r, centre_, radius_)) return intersection::none();
    const intersection i = nearest_child_hit(r);
    if (i.hit()) return i;
    return intersection::composite_only(this);
}

std::unique_ptr<rtab_composite> make_bounding_sphere() { return std::make_unique<sphere_bound>(); }

}  // namespace vl::stage03
