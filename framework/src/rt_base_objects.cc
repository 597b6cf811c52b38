#include "vl/rt_base_objects.hh"

#include <cmath>
#include <ostream>

#include "vl/error.hh"

namespace vl {

vector rtab_component::normal(const point&) const { return NaN_vector; }

bool rtab_component::contains(const point&) const { return false; }

void rtab_component::read(scene_reader&) {}

void rtab_component::write(std::ostream& s) const { s << type_name(); }

void rtab_component::insert(std::unique_ptr<rtab_component>) {
    throw usage_error(type_name() + " cannot hold other objects: insert() is for composites"
                      " (put both objects in a LIST instead)");
}

void rtab_component::delete_all_children() {
    throw usage_error(type_name() + " has no children to delete: delete_all_children() is for composites");
}

void rtab_composite::check_insertable(const rtab_component* child) const {
    if (child == nullptr) throw usage_error(type_name() + ": insert() was given no object (a null pointer)");
    if (child == this) throw usage_error(type_name() + ": a composite cannot contain itself");
}

void rtab_composite::insert(std::unique_ptr<rtab_component> child) {
    check_insertable(child.get());
    children_.push_back(std::move(child));
}

void rtab_composite::write(std::ostream& s) const {
    s << type_name() << " {\n";
    for (const auto& c : children_) s << "  " << *c << '\n';
    s << '}';
}

namespace {
point corner(std::span<const std::unique_ptr<rtab_component>> children, bool lowest) {
    if (children.empty()) return NaN_point;
    point result = lowest ? children.front()->min_point() : children.front()->max_point();
    for (const auto& c : children) {
        const point p = lowest ? c->min_point() : c->max_point();
        if (is_nan(p)) return NaN_point;
        result = lowest ? point(std::fmin(result.x, p.x), std::fmin(result.y, p.y), std::fmin(result.z, p.z))
                        : point(std::fmax(result.x, p.x), std::fmax(result.y, p.y), std::fmax(result.z, p.z));
    }
    return result;
}
}  // namespace

point rtab_composite::min_point() const { return corner(children_, true); }
point rtab_composite::max_point() const { return corner(children_, false); }

bool rtab_composite::contains(const point& p) const {
    for (const auto& c : children_)
        if (c->contains(p)) return true;
    return false;
}

intersection rtab_composite::nearest_child_hit(const ray& r) const {
    intersection nearest = intersection::none();
    for (const auto& c : children_) {
        const intersection i = c->intersect(r);
        if (i.nearer_than(nearest)) nearest = i;
    }
    return nearest;
}

std::ostream& operator<<(std::ostream& s, const rtab_component& c) {
    c.write(s);
    return s;
}

}  // namespace vl
