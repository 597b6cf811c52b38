#include "vl/shape_params.hh"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <ostream>
#include <utility>

#include "vl/convex_polygon.hh"

namespace vl::checks {

bool finite(const point& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }
bool finite(const vector& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

bool usable_normal(const vector& n) {
    const vector u = vector(n.x, n.y, n.z).unit();
    return finite(n) && finite(u) && std::fabs(u.length() - 1) < 1e-9;
}

std::string triangle_problem(const point& a, const point& b, const point& c) {
    if (!finite(a) || !finite(b) || !finite(c)) return "every vertex must be a finite point (w not 0)";
    const vector ab = b - a, ac = c - a;
    if (!((ab % ac).length() > 1e-12 * ab.length() * ac.length()))
        return "its vertices a, b and c are on one line (or two coincide): it has no area";
    return "";
}

}  // namespace vl::checks

namespace vl::shapes {

namespace {

/// Sets `s` to max_digits10 digits and back.
class full_precision {
public:
    explicit full_precision(std::ostream& s) : s_(s), old_(s.precision(std::numeric_limits<double>::max_digits10)) {}
    ~full_precision() { s_.precision(old_); }
    full_precision(const full_precision&) = delete;
    full_precision& operator=(const full_precision&) = delete;

private:
    std::ostream& s_;
    std::streamsize old_;
};

}  // namespace

std::vector<scene_reader::property> sphere_params::properties(scene_reader& in) {
    return {{"center", [this, &in] {
                 const source_location where = in.peek().where;
                 center = in.read_point("center of SPHERE").homogenized();
                 if (!checks::finite(center)) in.fail(where, "center of SPHERE must be a finite point (w not 0)");
             }},
            {"radius", [this, &in] { radius = in.read_positive("radius of SPHERE"); }}};
}

void sphere_params::write(std::ostream& s) const {
    const full_precision digits(s);
    s << "SPHERE { center " << center.x << ' ' << center.y << ' ' << center.z << " radius " << radius;
}

std::vector<scene_reader::property> plane_params::properties(scene_reader& in) {
    return {{"point", [this, &in] {
                 const source_location where = in.peek().where;
                 point_on_plane = in.read_point("point of PLANE").homogenized();
                 if (!checks::finite(point_on_plane)) in.fail(where, "point of PLANE must be a finite point (w not 0)");
             }},
            {"normal", [this, &in] {
                 const source_location where = in.peek().where;
                 normal = in.read_vector("normal of PLANE");
                 normal.w = 0;
                 if (!checks::usable_normal(normal)) in.fail(where, "normal of PLANE must not be the zero vector");
             }}};
}

void plane_params::write(std::ostream& s) const {
    const full_precision digits(s);
    s << "PLANE { point " << point_on_plane.x << ' ' << point_on_plane.y << ' ' << point_on_plane.z << " normal "
      << normal.x << ' ' << normal.y << ' ' << normal.z;
}

std::vector<scene_reader::property> triangle_params::properties(scene_reader& in) {
    return {{"a", [this, &in] { a = in.read_point("vertex a of TRIANGLE").homogenized(); }},
            {"b", [this, &in] { b = in.read_point("vertex b of TRIANGLE").homogenized(); }},
            {"c", [this, &in] { c = in.read_point("vertex c of TRIANGLE").homogenized(); }}};
}

void triangle_params::check(scene_reader& in, const source_location& where) const {
    if (const std::string problem = checks::triangle_problem(a, b, c); !problem.empty())
        in.fail(where, "this TRIANGLE is not a triangle: " + problem);
}

void triangle_params::write(std::ostream& s) const {
    const full_precision digits(s);
    s << "TRIANGLE {";
    for (const auto& [key, p] : {std::pair{"a", a}, std::pair{"b", b}, std::pair{"c", c}})
        s << ' ' << key << ' ' << p.x << ' ' << p.y << ' ' << p.z;
}

std::vector<scene_reader::property> polygon_params::properties(scene_reader& in) {
    return {{"vertices", [this, &in] {
                 if (in.peek().text != "(")
                     in.fail_expected("'(' to start a vertex of POLYGON (each vertex is written (x, y, z))");
                 std::vector<source_location> where;
                 vertices.clear();
                 while (in.peek().type == token::kind::punct && in.peek().text == "(") {
                     where.push_back(in.peek().where);
                     vertices.push_back(in.read_point("vertex of POLYGON").homogenized());
                 }
                 if (const auto problem = find_polygon_problem(vertices)) {
                     const std::size_t at = std::min(problem->vertex, where.size() - 1);
                     in.fail(where[at], "this POLYGON is not convex and planar: " + problem->message);
                 }
             }}};
}

void polygon_params::write(std::ostream& s) const {
    const full_precision digits(s);
    s << "POLYGON { vertices";
    for (const point& p : vertices) s << " (" << p.x << ", " << p.y << ", " << p.z << ')';
}

}  // namespace vl::shapes
