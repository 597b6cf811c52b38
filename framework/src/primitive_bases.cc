#include "vl/primitive_bases.hh"

#include <cmath>
#include <ostream>
#include <utility>

#include "vl/convex_polygon.hh"
#include "vl/error.hh"
#include "vl/shape_params.hh"

namespace vl::shapes {

namespace {

/// Each homogenized.
std::vector<point> homogenized(std::vector<point> vertices) {
    for (point& p : vertices) p = p.homogenized();
    return vertices;
}

}  // namespace

std::string sphere_base::type_name() const { return "SPHERE"; }

void sphere_base::read(scene_reader& in) {
    sphere_params p{center_, radius_};
    read_with_surface(in, p.properties(in));
    set_geometry(p.center, p.radius);
}

void sphere_base::write(std::ostream& s) const {
    sphere_params{center_, radius_}.write(s);
    write_surface(s);
    s << " }";
}

void sphere_base::check(const point& center, double radius) {
    if (!checks::finite(center.homogenized()) || !std::isfinite(radius) || !(radius > 0))
        throw usage_error("make_sphere: the center must be finite and the radius a finite number > 0");
}

sphere_base::sphere_base(const point& center, double radius) : center_(center.homogenized()), radius_(radius) {}

void sphere_base::set_geometry(const point& center, double radius) {
    center_ = center.homogenized();
    radius_ = radius;
    geometry_changed();
}

std::string plane_base::type_name() const { return "PLANE"; }

bool plane_base::contains(const point&) const { return false; }

void plane_base::read(scene_reader& in) {
    plane_params p{point_, normal_};
    read_with_surface(in, p.properties(in));
    set_geometry(p.point_on_plane, p.normal);
}

void plane_base::write(std::ostream& s) const {
    plane_params{point_, normal_}.write(s);
    write_surface(s);
    s << " }";
}

void plane_base::check(const point& point_on_plane, const vector& normal) {
    if (!checks::finite(point_on_plane.homogenized()) || !checks::usable_normal(normal))
        throw usage_error("make_plane: the point must be finite and the normal a finite, non-zero vector");
}

plane_base::plane_base(const point& point_on_plane, const vector& normal)
    : point_(point_on_plane.homogenized()), normal_(normal.x, normal.y, normal.z) {}

void plane_base::set_geometry(const point& point_on_plane, const vector& normal) {
    point_ = point_on_plane.homogenized();
    normal_ = vector(normal.x, normal.y, normal.z);
    geometry_changed();
}

std::string triangle_base::type_name() const { return "TRIANGLE"; }

bool triangle_base::contains(const point&) const { return false; }

void triangle_base::read(scene_reader& in) {
    const source_location where = in.peek().where;
    triangle_params p{a_, b_, c_};
    read_with_surface(in, p.properties(in));
    p.check(in, where);
    set_geometry(p.a, p.b, p.c);
}

void triangle_base::write(std::ostream& s) const {
    triangle_params{a_, b_, c_}.write(s);
    write_surface(s);
    s << " }";
}

void triangle_base::check(const point& a, const point& b, const point& c) {
    if (const std::string problem = checks::triangle_problem(a.homogenized(), b.homogenized(), c.homogenized());
        !problem.empty())
        throw usage_error("make_triangle: " + problem);
}

triangle_base::triangle_base(const point& a, const point& b, const point& c)
    : a_(a.homogenized()), b_(b.homogenized()), c_(c.homogenized()) {}

void triangle_base::set_geometry(const point& a, const point& b, const point& c) {
    a_ = a.homogenized();
    b_ = b.homogenized();
    c_ = c.homogenized();
    geometry_changed();
}

std::string polygon_base::type_name() const { return "POLYGON"; }

bool polygon_base::contains(const point&) const { return false; }

void polygon_base::read(scene_reader& in) {
    polygon_params p{vertices_};
    read_with_surface(in, p.properties(in));
    set_geometry(std::move(p.vertices));
}

void polygon_base::write(std::ostream& s) const {
    polygon_params{vertices_}.write(s);
    write_surface(s);
    s << " }";
}

void polygon_base::check(const std::vector<point>& vertices) {
    if (const auto problem = find_polygon_problem(homogenized(vertices)))
        throw usage_error("make_polygon: " + problem->message);
}

polygon_base::polygon_base(std::vector<point> vertices) : vertices_(homogenized(std::move(vertices))) {}

void polygon_base::set_geometry(std::vector<point> vertices) {
    vertices_ = homogenized(std::move(vertices));
    geometry_changed();
}

}  // namespace vl::shapes
