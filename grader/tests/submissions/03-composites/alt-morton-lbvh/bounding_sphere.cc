// The bounding sphere: one vl::hits_sphere() test, then every child.
#include <algorithm>
#include <cmath>

#include "sphere_bound.hh"
#include "vl/bounds.hh"
#include "vl/error.hh"
#include "vl/scene_reader.hh"

namespace vl::stage03 {

namespace {
double coordinate(const point& p, int axis) { return axis == 0 ? p.x : axis == 1 ? p.y : p.z; }
}  // namespace

bool box_is_finite(const rtab_component& c) {
    const point lo = c.min_point(), hi = c.max_point();
    for (int a = 0; a < 3; ++a)
        if (!std::isfinite(coordinate(lo, a)) || !std::isfinite(coordinate(hi, a))) return false;
    return true;
}

void sphere_bound::read(scene_reader& in) { in.read_children(*this); }

void sphere_bound::insert(std::unique_ptr<rtab_component> child) {
    if (!child) throw usage_error("BOUNDSPH: insert() was given a null pointer, not an object");
    if (child.get() == this) throw usage_error("BOUNDSPH: a bounding sphere cannot hold itself");
    if (!box_is_finite(*child)) {
        const std::string kind = child->type_name();
        throw usage_error("BOUNDSPH cannot hold a " + kind + ": the " + kind +
                          " has no finite box (it is unbounded or empty), so no sphere holds it; put the " + kind +
                          " beside the BOUNDSPH in a LIST");
    }
    take(std::move(child));
}

void sphere_bound::delete_all_children() {
    children_.clear();
    extent_.fill(NaN);
    center_ = NaN_point;
    radius_ = 0;
}

point sphere_bound::min_point() const {
    return children_.empty() ? NaN_point : point(extent_[0], extent_[2], extent_[4]);
}

point sphere_bound::max_point() const {
    return children_.empty() ? NaN_point : point(extent_[1], extent_[3], extent_[5]);
}

void sphere_bound::take(std::unique_ptr<rtab_component> child) {
    const point lo = child->min_point(), hi = child->max_point();
    const bool first = children_.empty();
    children_.push_back(std::move(child));
    for (int a = 0; a < 3; ++a) {
        const double l = coordinate(lo, a), h = coordinate(hi, a);
        extent_[2 * a] = first ? l : std::min(extent_[2 * a], l);
        extent_[2 * a + 1] = first ? h : std::max(extent_[2 * a + 1], h);
    }
    double half_diagonal_squared = 0;
    for (int a = 0; a < 3; ++a) {
        const double half = 0.5 * (extent_[2 * a + 1] - extent_[2 * a]);
        half_diagonal_squared += half * half;
    }
    center_ = point(0.5 * (extent_[0] + extent_[1]), 0.5 * (extent_[2] + extent_[3]), 0.5 * (extent_[4] + extent_[5]));
    radius_ = std::sqrt(half_diagonal_squared);
}

intersection sphere_bound::find_intersection(const ray& r) const {
    if (children_.empty()) return intersection::none();
    if (!hits_sphere(r, center_, radius_)) return intersection::none();
    intersection nearest = intersection::none();
    for (const auto& child : children_) {
        const intersection i = child->intersect(r);
        if (i.nearer_than(nearest)) nearest = i;
    }
    return nearest.hit() ? nearest : intersection::composite_only(this);
}

std::unique_ptr<rtab_composite> make_bounding_sphere() { return std::make_unique<sphere_bound>(); }

}  // namespace vl::stage03
