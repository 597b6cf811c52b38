#include "vl/shape_params.hh"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>
#include <ostream>
#include <utility>

#include "full_precision.hh"
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

bool below(const point& a, const point& b) { return a.x < b.x && a.y < b.y && a.z < b.z; }

const char* unusable_matrix(const matrix& m) {
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c)
            if (!std::isfinite(m(r, c))) return "it has an element that is not finite";
    if (m(3, 0) != 0 || m(3, 1) != 0 || m(3, 2) != 0 || m(3, 3) != 1)
        return "it is not affine (its bottom row must be 0 0 0 1)";
    if (m.determinant() == 0) return "it is singular (it has no inverse: is a scale 0?)";
    return nullptr;
}

}  // namespace vl::checks

namespace vl::shapes {

using detail::full_precision;

namespace {

/// Reads the point `what` ("center of SPHERE"), homogenized; fails where it starts when it
/// is not finite.
point read_finite_point(scene_reader& in, const std::string& what) {
    const source_location where = in.peek().where;
    const point p = in.read_point(what).homogenized();
    if (!checks::finite(p)) in.fail(where, what + " must be a finite point (w not 0)");
    return p;
}

}  // namespace

std::vector<scene_reader::property> sphere_params::properties(scene_reader& in) {
    return {{"center", [this, &in] { center = read_finite_point(in, "center of SPHERE"); }},
            {"radius", [this, &in] { radius = in.read_positive("radius of SPHERE"); }}};
}

void sphere_params::write(std::ostream& s) const {
    const full_precision digits(s);
    s << "SPHERE { center " << center.x << ' ' << center.y << ' ' << center.z << " radius " << radius;
}

std::vector<scene_reader::property> plane_params::properties(scene_reader& in) {
    return {{"point", [this, &in] { point_on_plane = read_finite_point(in, "point of PLANE"); }},
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

std::vector<scene_reader::property> frac_sphere_params::properties(scene_reader& in) {
    return {{"center", [this, &in] { center = read_finite_point(in, "center of FRACSPH"); }},
            {"radius", [this, &in] { radius = in.read_positive("radius of FRACSPH"); }},
            {"depth", [this, &in] { depth = in.read_int("depth of FRACSPH", 0, max_depth); }},
            {"ratio", [this, &in] {
                 const source_location where = in.peek().where;
                 ratio = in.read_number("ratio of FRACSPH");
                 if (!(ratio > 0 && ratio < 1))
                     in.fail(where, "ratio of FRACSPH must be between 0 and 1 (each level smaller), found " +
                                        std::to_string(ratio));
             }}};
}

void frac_sphere_params::write(std::ostream& s) const {
    const full_precision digits(s);
    s << "FRACSPH { center " << center.x << ' ' << center.y << ' ' << center.z << " radius " << radius << " depth "
      << depth << " ratio " << ratio;
}

std::vector<scene_reader::property> box_params::properties(scene_reader& in, source_location& where) {
    where = in.peek().where;
    return {{"min", [this, &in, &where] {
                 where = in.peek().where;
                 lo = read_finite_point(in, "min of BOX");
             }},
            {"max", [this, &in, &where] {
                 where = in.peek().where;
                 hi = read_finite_point(in, "max of BOX");
             }}};
}

void box_params::write(std::ostream& s) const {
    const full_precision digits(s);
    s << "BOX { min " << lo.x << ' ' << lo.y << ' ' << lo.z << " max " << hi.x << ' ' << hi.y << ' ' << hi.z;
}

int read_bvh_leaf_size(scene_reader& in, int leaf_size) {
    in.expect('{', "after BVH");
    if (in.peek().type == token::kind::word && in.peek().text == "leaf_size") {
        in.next();
        return in.read_int("leaf_size of BVH", 1, 64);
    }
    return leaf_size;
}

matrix read_transform_step(scene_reader& in, const token& step, const transform_step_makers& make) {
    if (step.text == "scale") {
        const double x = in.read_number("x of scale");
        const double y = in.read_number("y of scale");
        const double z = in.read_number("z of scale");
        return make.scale(x, y, z);
    }
    if (step.text == "rotate") {
        const double x = in.read_number("x of the axis of rotate");
        const double y = in.read_number("y of the axis of rotate");
        const double z = in.read_number("z of the axis of rotate");
        const vector axis(x, y, z);
        if (axis.x == 0 && axis.y == 0 && axis.z == 0) in.fail(step.where, "the axis of rotate must not be zero");
        return make.rotate(axis, in.read_number("degrees of rotate") * std::numbers::pi / 180);
    }
    if (step.text == "translate") {
        const double x = in.read_number("x of translate");
        const double y = in.read_number("y of translate");
        const double z = in.read_number("z of translate");
        return make.translate(vector(x, y, z));
    }
    if (step.text == "matrix") {
        double e[16];
        for (double& x : e) x = in.read_number("element of matrix");
        return matrix(e[0], e[1], e[2], e[3], e[4], e[5], e[6], e[7], e[8], e[9], e[10], e[11], e[12], e[13], e[14],
                      e[15]);
    }
    in.fail(step.where,
            "expected scale, rotate, translate, matrix or an object in TRANSFORM, found '" + step.text + "'");
}

void write_transform_matrix(std::ostream& s, const matrix& to_world) {
    const full_precision digits(s);
    s << "TRANSFORM { matrix";
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) s << ' ' << to_world(r, c);
}

}  // namespace vl::shapes
