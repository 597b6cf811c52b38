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
#include "vl/primitive_bases.hh"
#include "woop.hh"

namespace vl::stage02 {

namespace {

class polygon final : public shapes::polygon_base {
public:
    explicit polygon(std::vector<point> vertices) : polygon_base(std::move(vertices)) { geometry_changed(); }

    vector normal(const point&) const override { return normal_; }
    point min_point() const override { return min_; }
    point max_point() const override { return max_; }

    void write(std::ostream& s) const override {
        const auto old_precision = s.precision(std::numeric_limits<double>::max_digits10);
        s << "POLYGON { vertices";
        for (const point& p : vertices_) s << " (" << p.x << ", " << p.y << ", " << p.z << ')';
        s.precision(old_precision);
        write_surface(s);
        s << " }";
    }

private:
    void geometry_changed() override {
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

    vector normal_;
    point min_, max_;
};

}  // namespace

std::unique_ptr<primitive> make_polygon(std::vector<point> vertices) {
    shapes::polygon_base::check(vertices);
    return std::make_unique<polygon>(std::move(vertices));
}

}  // namespace vl::stage02
