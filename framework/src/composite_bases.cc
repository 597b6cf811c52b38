#include "vl/composite_bases.hh"

#include <cmath>
#include <ostream>
#include <string>
#include <vector>

#include "vl/error.hh"
#include "vl/registry.hh"
#include "vl/scene_reader.hh"

namespace vl::shapes {

bool finite_box(const rtab_component& c) { return checks::finite(c.min_point()) && checks::finite(c.max_point()); }

// ---- BOUNDSPH ----

void bounding_sphere_base::read(scene_reader& in) { in.read_children(*this); }

void bounding_sphere_base::delete_all_children() {
    rtab_composite::delete_all_children();
    lo_ = hi_ = bound_center_ = NaN_point;
    bound_radius_ = 0;
}

// ---- FRACSPH ----

void check_frac_sphere(const point& center, double radius, int depth, double ratio) {
    if (!checks::finite(center.homogenized()) || !std::isfinite(radius) || !(radius > 0))
        throw usage_error("make_frac_sphere: the center must be finite and the radius a finite number > 0");
    if (depth < 0 || depth > frac_sphere_params::max_depth)
        throw usage_error("make_frac_sphere: the depth must be from 0 to 7, not " + std::to_string(depth));
    if (!(ratio > 0 && ratio < 1)) throw usage_error("make_frac_sphere: the ratio must be between 0 and 1");
}

void read_frac_sphere(scene_reader& in, frac_sphere_params& p, surface& s) {
    std::vector<scene_reader::property> properties = p.properties(in);
    add_surface_properties(properties, in, s, "FRACSPH");
    in.read_block("FRACSPH", properties);
}

void write_frac_sphere(std::ostream& out, const frac_sphere_params& p, const surface& s) {
    p.write(out);
    write_surface(out, s);
    out << " }";
}

// ---- BOX ----

void box_base::insert(std::unique_ptr<rtab_component>) {
    throw usage_error("BOX is made of its six faces: insert() cannot add to it"
                      " (put the BOX and the other object in a LIST)");
}

void box_base::delete_all_children() { throw usage_error("BOX is made of its six faces: they cannot be deleted"); }

void box_base::read(scene_reader& in) {
    box_params p{lo_, hi_};
    source_location where;
    std::vector<scene_reader::property> properties = p.properties(in, where);
    add_surface_properties(properties, in, surface_, "BOX");
    in.read_block("BOX", properties);
    if (!checks::below(p.lo, p.hi)) in.fail(where, "min of BOX must be below max in x, y and z (a box has volume)");
    set_geometry(p.lo, p.hi);
}

void box_base::write(std::ostream& s) const {
    box_params{lo_, hi_}.write(s);
    write_surface(s, surface_);
    s << " }";
}

void box_base::check_corners(const point& lo, const point& hi) {
    if (!checks::finite(lo.homogenized()) || !checks::finite(hi.homogenized()))
        throw usage_error("make_box: both corners must be finite points");
    if (!checks::below(lo.homogenized(), hi.homogenized()))
        throw usage_error("make_box: lo must be below hi in x, y and z (a box has volume)");
}

void box_base::set_geometry(const point& lo, const point& hi) {
    lo_ = lo.homogenized();
    hi_ = hi.homogenized();
    children_.clear();
    make_faces();
}

// ---- TRANSFORM ----

transformed_base::transformed_base(std::unique_ptr<rtab_component> child, const matrix& object_to_world,
                                   const transform_step_makers& steps, inverter inverse) {
    set_up(std::move(child), object_to_world, steps, inverse);
}

void transformed_base::set_up(std::unique_ptr<rtab_component> child, const matrix& object_to_world,
                              const transform_step_makers& steps, inverter inverse) {
    steps_ = steps;
    inverse_ = inverse;
    set_matrix(object_to_world);
    children_.clear();
    if (child) children_.push_back(std::move(child));
}

void transformed_base::insert(std::unique_ptr<rtab_component> child) {
    if (!children_.empty())
        throw usage_error("TRANSFORM holds one object and has it already (put a LIST inside for several)");
    rtab_composite::insert(std::move(child));
}

color transformed_base::clr() const { return children_.empty() ? WHITE : children_.front()->clr(); }
double transformed_base::kdr() const { return children_.empty() ? 0 : children_.front()->kdr(); }
double transformed_base::ksr() const { return children_.empty() ? 0 : children_.front()->ksr(); }
double transformed_base::kdt() const { return children_.empty() ? 0 : children_.front()->kdt(); }
double transformed_base::kst() const { return children_.empty() ? 0 : children_.front()->kst(); }
double transformed_base::n() const { return children_.empty() ? 1 : children_.front()->n(); }
double transformed_base::ior() const { return children_.empty() ? 1 : children_.front()->ior(); }
double transformed_base::zero_t() const {
    return children_.empty() ? default_zero_t : children_.front()->zero_t();
}

void transformed_base::read(scene_reader& in) {
    in.expect('{', "after TRANSFORM");
    matrix m = IDENTITY;
    for (;;) {
        const token t = in.peek();
        if (t.type != token::kind::word || registry::valid_name(t.text)) break;
        in.next();
        const matrix step = read_transform_step(in, t, steps_);
        m = step * m;  // each step acts after the ones before it
        if (const char* why = checks::unusable_matrix(m))
            in.fail(t.where, std::string("TRANSFORM cannot use this matrix: ") + why);
    }
    if (in.peek().type == token::kind::punct && in.peek().text == "}")
        in.fail_expected("the object of TRANSFORM (such as SPHERE { }) before '}'");
    set_matrix(m);
    children_.clear();
    in.read_child(*this);
    if (!in.accept('}')) in.fail_expected("'}' to close TRANSFORM (it holds exactly one object)");
}

void transformed_base::write(std::ostream& s) const {
    write_transform_matrix(s, to_world_);
    for (const auto& c : children_) s << ' ' << *c;
    s << " }";
}

void transformed_base::check_matrix(const matrix& object_to_world) {
    if (const char* why = checks::unusable_matrix(object_to_world))
        throw usage_error(std::string("make_transformed: the matrix cannot place an object: ") + why);
}

void transformed_base::set_matrix(const matrix& m) {
    to_world_ = m;
    to_object_ = inverse_(m);
    normal_matrix_ = to_object_.transpose();
}

// ---- BVH ----

void bvh_base::insert(std::unique_ptr<rtab_component> child) {
    if (child && child.get() != this && !finite_box(*child))
        throw usage_error("BVH cannot hold " + child->type_name() +
                          ": its box is unknown (it is unbounded or empty), so no box can hold it;"
                          " put it beside the BVH in a LIST");
    if (child.get() == this) throw usage_error("BVH: a composite cannot contain itself");
    adopt(std::move(child));
}

void bvh_base::adopt(std::unique_ptr<rtab_component> child) {
    std::lock_guard lock(build_mutex_);
    rtab_composite::insert(std::move(child));
    built_.store(false, std::memory_order_release);
}

void bvh_base::delete_all_children() {
    std::lock_guard lock(build_mutex_);
    rtab_composite::delete_all_children();
    built_.store(false, std::memory_order_release);
}

void bvh_base::read(scene_reader& in) {
    leaf_size_ = read_bvh_leaf_size(in, leaf_size_);
    while (!in.accept('}')) in.read_child(*this);
}

void bvh_base::write(std::ostream& s) const {
    s << "BVH { leaf_size " << leaf_size_ << '\n';
    for (const auto& c : children_) s << "  " << *c << '\n';
    s << '}';
}

void bvh_base::check_leaf_size(int leaf_size) {
    if (leaf_size < 1 || leaf_size > 64)
        throw usage_error("make_bvh: leaf_size must be from 1 to 64, not " + std::to_string(leaf_size));
}

void bvh_base::ensure_built() const {
    if (built_.load(std::memory_order_acquire)) return;
    std::lock_guard lock(build_mutex_);
    if (built_.load(std::memory_order_relaxed)) return;
    build();
    built_.store(true, std::memory_order_release);
}

}  // namespace vl::shapes
