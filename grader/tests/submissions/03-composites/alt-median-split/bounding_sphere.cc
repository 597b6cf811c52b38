// The bounding sphere: children inside the sphere around their box.
#include <cmath>

#include "sphere_hull.hh"
#include "vl/bounds.hh"
#include "vl/scene_reader.hh"

namespace vl::stage03 {

void sphere_hull::read(scene_reader& in) { in.read_children(*this); }

void sphere_hull::insert(std::unique_ptr<rtab_component> child) {
    if (!child) throw usage_error(type_name() + ": insert() was given a null pointer instead of an object");
    if (child.get() == this) throw usage_error(type_name() + ": a bounding sphere cannot hold itself");
    if (!box_is_known(*child))
        throw usage_error(type_name() + " refuses a " + child->type_name() +
                          ": a sphere can only hold objects whose box is known; put the " + child->type_name() +
                          " next to the " + type_name() + " in a LIST instead");
    add_child(std::move(child));
}

void sphere_hull::delete_all_children() {
    children_.clear();
    box_ = extent{};
    centre_ = NaN_point;
    radius_ = 0;
    fixed_ = false;
}

void sphere_hull::add_child(std::unique_ptr<rtab_component> child) {
    box_.add(child->min_point(), child->max_point());
    children_.push_back(std::move(child));
    if (fixed_) return;
    centre_ = box_.middle();
    radius_ = 0.5 * std::sqrt((box_.hi.x - box_.lo.x) * (box_.hi.x - box_.lo.x) +
                              (box_.hi.y - box_.lo.y) * (box_.hi.y - box_.lo.y) +
                              (box_.hi.z - box_.lo.z) * (box_.hi.z - box_.lo.z));
}

void sphere_hull::fix_sphere(const point& centre, double radius) {
    centre_ = centre;
    radius_ = radius;
    fixed_ = true;
}

intersection sphere_hull::find_intersection(const ray& r) const {
    if (children_.empty()) return intersection::none();  // nothing inside: no sphere to test
    if (!hits_sphere(r, centre_, radius_)) return intersection::none();
    intersection best = intersection::none();
    for (const auto& c : children_) {
        const intersection i = c->intersect(r);
        if (i.hit() && (!best.hit() || i.t < best.t)) best = i;
    }
    if (best.hit()) return best;
    return intersection::composite_only(this);
}

std::unique_ptr<rtab_composite> make_bounding_sphere() { return std::make_unique<sphere_hull>(); }

}  // namespace vl::stage03
