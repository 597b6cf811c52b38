// The convex polygon as a fan of watertight triangles (woop.hh) around its first vertex.
// Neighbouring triangles of the fan share a spoke and neighbouring polygons share an edge;
// both compute that edge's function from the same two sheared vertices, so no ray slips
// between them.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "stage_02.hh"
#include "vl/convex_polygon.hh"
#include "woop.hh"

namespace vl::stage02 {

namespace {

class polygon final : public primitive {
public:
    explicit polygon(std::vector<point> vertices) { set_geometry(std::move(vertices)); }

    std::string type_name() const override { return "POLYGON"; }

    vector normal(const point&) const override { return normal_; }
    bool contains(const point&) const override { return false; }
    point min_point() const override { return min_; }
    point max_point() const override { return max_; }

    void read(scene_reader& in) override {
        std::vector<point> vertices = vertices_;
        read_with_surface(in, {{"vertices", [&] {
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
                                }}});
        set_geometry(std::move(vertices));
    }
    void write(std::ostream& s) const override {
        const auto old_precision = s.precision(std::numeric_limits<double>::max_digits10);
        s << "POLYGON { vertices";
        for (const point& p : vertices_) s << " (" << p.x << ", " << p.y << ", " << p.z << ')';
        s.precision(old_precision);
        write_surface(s);
        s << " }";
    }

private:
    void set_geometry(std::vector<point> vertices) {
        vertices_ = std::move(vertices);
        for (point& p : vertices_) p = p.homogenized();
        normal_ = newell_normal(vertices_, centroid_of(vertices_)).unit();
        min_ = max_ = vertices_.front();
        for (const point& p : vertices_) {
            min_ = point(std::min(min_.x, p.x), std::min(min_.y, p.y), std::min(min_.z, p.z));
            max_ = point(std::max(max_.x, p.x), std::max(max_.y, p.y), std::max(max_.z, p.z));
        }
    }

    intersection find_intersection(const ray& r) const override {
        const sheared_ray shear(r);
        std::vector<sheared_vertex> v;
        v.reserve(vertices_.size());
        for (const point& p : vertices_) v.push_back(shear(p));
        const double eps = std::fabs(zero_t());
        for (std::size_t k = 1; k + 1 < v.size(); ++k) {
            const std::optional<double> t = woop_distance(v[0], v[k], v[k + 1]);
            if (!t) continue;
            if (std::isfinite(*t) && *t > eps) return intersection::at(*t, this);
            return intersection::none();  // through the polygon, but behind the ray or at its origin
        }
        return intersection::none();
    }

    std::vector<point> vertices_;
    vector normal_;
    point min_, max_;
};

}  // namespace

std::unique_ptr<primitive> make_polygon(std::vector<point> vertices) {
    for (point& p : vertices) p = p.homogenized();
    if (const auto problem = find_polygon_problem(vertices)) throw usage_error("make_polygon: " + problem->message);
    return std::make_unique<polygon>(std::move(vertices));
}

}  // namespace vl::stage02
