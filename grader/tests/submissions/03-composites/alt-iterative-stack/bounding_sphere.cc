// The bounding sphere (stage_03.hh): its children inside the sphere around their box.
#include "bounding_sphere.hh"

#include "vl/bounds.hh"

namespace vl::stage03 {

void bounding_sphere::insert(std::unique_ptr<rtab_component> child) {
    if (child && child.get() != this && !shapes::finite_box(*child))
        throw usage_error(type_name() + " refuses " + child->type_name() + ": the " + child->type_name() +
                          " has no finite box, so no sphere holds it; put it next to the " + type_name() +
                          " in a LIST");
    rtab_composite::insert(std::move(child));  // null pointer and self refused here
    std::unique_ptr<rtab_component> added = std::move(children_.back());
    children_.pop_back();
    adopt(std::move(added));
}

void bounding_sphere::adopt(std::unique_ptr<rtab_component> child) {
    const point a = child->min_point(), b = child->max_point();
    const double lo[3] = {a.x, a.y, a.z}, hi[3] = {b.x, b.y, b.z};
    double now_lo[3] = {lo_.x, lo_.y, lo_.z}, now_hi[3] = {hi_.x, hi_.y, hi_.z};
    for (int k = 0; k < 3; ++k) {
        // NaN (no child yet) never wins a comparison, so the first child sets the box.
        if (!(now_lo[k] <= lo[k])) now_lo[k] = lo[k];
        if (!(now_hi[k] >= hi[k])) now_hi[k] = hi[k];
    }
    lo_ = point(now_lo[0], now_lo[1], now_lo[2]);
    hi_ = point(now_hi[0], now_hi[1], now_hi[2]);
    children_.push_back(std::move(child));
    const vector diagonal = hi_ - lo_;
    set_sphere(lo_ + diagonal / 2, diagonal.length() / 2);
}

intersection bounding_sphere::find_intersection(const ray& r) const {
    if (children_.empty()) return intersection::none();
    if (!hits_sphere(r, bound_center_, bound_radius_)) return intersection::none();
    intersection nearest = nearest_child_hit(r);
    if (!nearest.hit()) nearest = intersection::composite_only(this);
    return nearest;
}

std::unique_ptr<rtab_composite> make_bounding_sphere() { return std::make_unique<bounding_sphere>(); }

}  // namespace vl::stage03
