// Reference: the convex planar polygon (see assignments/02-sphere/stage_02.hh).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "ray_space.hh"
#include "stage_02.hh"

namespace vl::stage02 {

namespace {

bool finite(const point& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

/// \brief Why a list of points is not a convex planar polygon: the vertex at fault
/// (counted from 0) and what is wrong, for make_polygon() and for the scene reader.
struct polygon_problem {
    std::size_t vertex = 0;
    std::string message;
};

// The polygon's normal by Newell's method (Sutherland, Sproull and Schumacker 1974;
// Glassner, Graphics Gems III, "Newell's method"): the sum of the cross products of
// consecutive vertices about their centroid. Its length is twice the area, and it
// points to the side from which the vertices wind counter-clockwise; unlike the cross
// product of two edges it does not depend on which vertices are picked.
vector newell_normal(const std::vector<point>& v, const point& centroid) {
    vector n;
    for (std::size_t i = 0; i < v.size(); ++i) n += (v[i] - centroid) % (v[(i + 1) % v.size()] - centroid);
    return n;
}

point centroid_of(const std::vector<point>& v) {
    vector sum;
    for (const point& p : v) sum += p - point(0, 0, 0);
    return point(0, 0, 0) + sum / static_cast<double>(v.size());
}

std::optional<polygon_problem> find_problem(const std::vector<point>& v) {
    const auto name = [](std::size_t i) { return "vertex " + std::to_string(i + 1); };
    if (v.size() < 3)
        return polygon_problem{v.size(), "a POLYGON needs at least 3 vertices, found " + std::to_string(v.size())};
    for (std::size_t i = 0; i < v.size(); ++i)
        if (!finite(v[i])) return polygon_problem{i, name(i) + " is not a finite point (w is 0)"};

    point lo = v[0], hi = v[0];
    for (const point& p : v) {
        lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
        hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
    }
    const double size = (hi - lo).length();  // tolerances are relative to it
    for (std::size_t i = 0; i < v.size(); ++i) {
        const std::size_t next = (i + 1) % v.size();
        if ((v[next] - v[i]).length() <= 1e-12 * size || size == 0)
            return polygon_problem{next, name(next) + " is the same point as " + name(i)};
    }

    const point centroid = centroid_of(v);
    const vector newell = newell_normal(v, centroid);
    if (!(newell.length() > 1e-12 * size * size))
        return polygon_problem{2, "all its vertices are on one line: it has no area"};
    const vector n = newell.unit();

    // Planar: every vertex on the plane of vertices 1, 2 and the one furthest from
    // their line (the best-conditioned choice of three), within 1e-6 of the size.
    std::size_t k = 2;
    for (std::size_t i = 3; i < v.size(); ++i)
        if (((v[1] - v[0]) % (v[i] - v[0])).length() > ((v[1] - v[0]) % (v[k] - v[0])).length()) k = i;
    const vector m = ((v[1] - v[0]) % (v[k] - v[0])).unit();
    for (std::size_t i = 0; i < v.size(); ++i) {
        const double off = std::fabs((v[i] - v[0]) * m);
        if (off > 1e-6 * size)
            return polygon_problem{i, name(i) + " is " + std::to_string(off) + " away from the plane of vertices 1, 2 and " +
                                          std::to_string(k + 1) + ": a POLYGON must be planar"};
    }
    // Convex: every vertex lies on the inner side (or on the line) of every edge.
    for (std::size_t i = 0; i < v.size(); ++i) {
        const std::size_t next = (i + 1) % v.size();
        const vector edge = v[next] - v[i];
        for (std::size_t j = 0; j < v.size(); ++j) {
            const double side = ((edge % (v[j] - v[i])) * n) / edge.length();  // signed distance from the edge's line
            if (side < -1e-6 * size)
                return polygon_problem{j, name(j) + " lies outside the edge from " + name(i) + " to " + name(next) +
                                              ": a POLYGON must be convex (split it into convex pieces)"};
        }
    }
    return std::nullopt;
}

/// \brief A convex planar polygon; its front is the side from which its vertices run
/// counter-clockwise.
class polygon final : public primitive {
public:
    explicit polygon(std::vector<point> vertices) { set_geometry(std::move(vertices)); }

    std::string type_name() const override { return "POLYGON"; }
    vector normal(const point&) const override { return normal_; }
    bool contains(const point&) const override { return false; }  // a flat object has no inside
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
                                    if (const auto problem = find_problem(vertices)) {
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
            min_ = {std::min(min_.x, p.x), std::min(min_.y, p.y), std::min(min_.z, p.z)};
            max_ = {std::max(max_.x, p.x), std::max(max_.y, p.y), std::max(max_.z, p.z)};
        }
    }

    // Plane + inside test: the hit point of the polygon's plane must lie in the box
    // around the vertices (with a little room for round-off).
    intersection find_intersection(const ray& r) const override {
        const double denominator = r.direction() * normal_;
        if (denominator == 0) return intersection::none();
        const double t = ((vertices_.front() - r.origin()) * normal_) / denominator;
        if (!(t > std::fabs(zero_t())) || !std::isfinite(t)) return intersection::none();
        const point p = r.t_point(t);
        const double room = 1e-9 * (max_ - min_).length();
        if (p.x < min_.x - room || p.y < min_.y - room || p.z < min_.z - room || p.x > max_.x + room ||
            p.y > max_.y + room || p.z > max_.z + room)
            return intersection::none();
        return intersection::at(t, this);
    }

    std::vector<point> vertices_;
    vector normal_;  ///< unit, by Newell's method: the counter-clockwise side
    point min_, max_;
};

}  // namespace

std::unique_ptr<primitive> make_polygon(std::vector<point> vertices) {
    for (point& p : vertices) p = p.homogenized();
    if (const auto problem = find_problem(vertices)) throw usage_error("make_polygon: " + problem->message);
    return std::make_unique<polygon>(std::move(vertices));
}

}  // namespace vl::stage02
