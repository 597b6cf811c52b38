// Reference: the bounding sphere (see assignments/03-composites/stage_03.hh).
#include "bounding_sphere.hh"

#include <cmath>

#include "vl/bounds.hh"
#include "vl/scene_reader.hh"

namespace vl::stage03 {

namespace {
bool finite(const point& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }
}  // namespace

bool finite_box(const rtab_component& c) { return finite(c.min_point()) && finite(c.max_point()); }

void bounding_sphere::read(scene_reader& in) { in.read_children(*this); }

void bounding_sphere::insert(std::unique_ptr<rtab_component> child) {
    if (child && child.get() != this && !finite_box(*child))
        throw usage_error(type_name() + " cannot hold " + child->type_name() +
                          ": its box is unknown (it is unbounded or empty), so no sphere can hold it;"
                          " put it beside the " + type_name() + " in a LIST");
    rtab_composite::insert(std::move(child));  // refuses a null pointer and the sphere itself
    // The child is in: grow the box and the sphere around it.
    std::unique_ptr<rtab_component> last = std::move(children_.back());
    children_.pop_back();
    adopt(std::move(last));
}

void bounding_sphere::delete_all_children() {
    rtab_composite::delete_all_children();
    lo_ = hi_ = bound_center_ = NaN_point;
    bound_radius_ = 0;
}

void bounding_sphere::adopt(std::unique_ptr<rtab_component> child) {
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

intersection bounding_sphere::find_intersection(const ray& r) const {
    if (children_.empty() || !hits_sphere(r, bound_center_, bound_radius_)) return intersection::none();
    const intersection nearest = nearest_child_hit(r);
    return nearest.hit() ? nearest : intersection::composite_only(this);
}

std::unique_ptr<rtab_composite> make_bounding_sphere() { return std::make_unique<bounding_sphere>(); }

}  // namespace vl::stage03
