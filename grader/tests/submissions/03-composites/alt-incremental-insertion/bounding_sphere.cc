// BOUNDSPH.
#include <algorithm>
#include <cmath>

#include "sphere_group.hh"
#include "vl/bounds.hh"
#include "vl/scene_reader.hh"

namespace vl::stage03 {

void sphere_group::read(scene_reader& in) { in.read_children(*this); }

void sphere_group::insert(std::unique_ptr<rtab_component> child) {
    if (!child) throw usage_error("BOUNDSPH: cannot insert a null pointer");
    if (child.get() == this) throw usage_error("BOUNDSPH: cannot insert a bounding sphere into itself");
    if (!has_finite_box(*child))
        throw usage_error("BOUNDSPH cannot hold " + child->type_name() + ", whose box is unknown (" +
                          child->type_name() + " is unbounded or empty): put it beside the BOUNDSPH in a LIST");
    take(std::move(child));
}

void sphere_group::delete_all_children() {
    children_.clear();
    low_ = high_ = middle_ = NaN_point;
    reach_ = 0;
}

void sphere_group::take(std::unique_ptr<rtab_component> child) {
    const point a = child->min_point(), b = child->max_point();
    const bool first = children_.empty();
    low_ = first ? a : point(std::min(low_.x, a.x), std::min(low_.y, a.y), std::min(low_.z, a.z));
    high_ = first ? b : point(std::max(high_.x, b.x), std::max(high_.y, b.y), std::max(high_.z, b.z));
    children_.push_back(std::move(child));
    const vector half = 0.5 * (high_ - low_);
    middle_ = low_ + half;
    reach_ = half.length();
}

intersection sphere_group::find_intersection(const ray& r) const {
    if (children_.empty() || !hits_sphere(r, middle_, reach_)) return intersection::none();
    intersection nearest = intersection::none();
    for (const auto& c : children_)
        if (const intersection i = c->intersect(r); i.nearer_than(nearest)) nearest = i;
    return nearest.hit() ? nearest : intersection::composite_only(this);
}

std::unique_ptr<rtab_composite> make_bounding_sphere() { return std::make_unique<sphere_group>(); }

}  // namespace vl::stage03
