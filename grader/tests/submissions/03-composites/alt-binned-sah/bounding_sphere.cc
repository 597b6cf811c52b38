// BOUNDSPH: its children, inside the sphere around the union of their boxes.
#include <algorithm>
#include <cmath>

#include "bsphere.hh"
#include "vl/bounds.hh"
#include "vl/scene_reader.hh"

namespace vl::stage03 {

void bsphere::read(scene_reader& in) { in.read_children(*this); }

void bsphere::insert(std::unique_ptr<rtab_component> child) {
    if (child != nullptr && child.get() != this && !geom3::bounded(*child))
        throw usage_error("a " + type_name() + " cannot hold a " + child->type_name() +
                          " (its box is unknown: no sphere can hold it); put the " + child->type_name() +
                          " beside the " + type_name() + " in a LIST");
    if (child == nullptr) throw usage_error(type_name() + ": insert() needs an object, not a null pointer");
    if (child.get() == this) throw usage_error(type_name() + ": cannot hold itself");
    append(std::move(child));
}

void bsphere::delete_all_children() {
    children_.clear();
    centre_ = NaN_point;
    radius_ = 0;
}

point bsphere::min_point() const { return children_.empty() ? NaN_point : geom3::as_point(lo_); }
point bsphere::max_point() const { return children_.empty() ? NaN_point : geom3::as_point(hi_); }

void bsphere::append(std::unique_ptr<rtab_component> child) {
    const geom3::triple a = geom3::xyz(child->min_point()), b = geom3::xyz(child->max_point());
    for (int k = 0; k < 3; ++k) {
        lo_[k] = children_.empty() ? a[k] : std::min(lo_[k], a[k]);
        hi_[k] = children_.empty() ? b[k] : std::max(hi_[k], b[k]);
    }
    children_.push_back(std::move(child));
    centre_ = point(lo_[0] + (hi_[0] - lo_[0]) / 2, lo_[1] + (hi_[1] - lo_[1]) / 2, lo_[2] + (hi_[2] - lo_[2]) / 2);
    radius_ = std::hypot(hi_[0] - lo_[0], hi_[1] - lo_[1], hi_[2] - lo_[2]) / 2;
}

intersection bsphere::find_intersection(const ray& r) const {
    if (children_.empty()) return intersection::none();
    if (!hits_sphere(r, centre_, radius_)) return intersection::none();
    const intersection nearest = nearest_child_hit(r);
    return nearest.hit() ? nearest : intersection::composite_only(this);
}

std::unique_ptr<rtab_composite> make_bounding_sphere() { return std::make_unique<bsphere>(); }

}  // namespace vl::stage03
