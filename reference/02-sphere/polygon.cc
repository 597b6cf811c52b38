// Reference: the convex planar polygon (see assignments/02-sphere/stage_02.hh).
#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "ray_space.hh"
#include "stage_02.hh"
#include "vl/convex_polygon.hh"
#include "vl/primitive_bases.hh"

namespace vl::stage02 {

namespace {

/// \brief A convex planar polygon; its front is the side from which its vertices run
/// counter-clockwise.
class polygon final : public shapes::polygon_base {
public:
    vector normal(const point&) const override { return normal_; }
    point min_point() const override { return min_; }
    point max_point() const override { return max_; }

private:
    void geometry_changed() override {
        normal_ = newell_normal(vertices_, centroid_of(vertices_)).unit();
        min_ = max_ = vertices_.front();
        for (const point& p : vertices_) {
            min_ = {std::min(min_.x, p.x), std::min(min_.y, p.y), std::min(min_.z, p.z)};
            max_ = {std::max(max_.x, p.x), std::max(max_.y, p.y), std::max(max_.z, p.z)};
        }
    }

    // Plane + inside test. The inside test is the triangle's watertight one (Woop,
    // Benthin and Wald 2013; ray_space.hh) with one edge function per edge: the ray
    // passes through a convex polygon when no two edge functions have opposite signs.
    // Testing in ray space rather than projecting the hit point onto the polygon's plane
    // keeps neighbours that share an edge (the faces of a box) free of gaps, because
    // both evaluate the same edge function of the same two vertices. t then comes from
    // the plane, t = ((v0 - o) . n) / (d . n), as for vl::stage02::make_plane.
    intersection find_intersection(const ray& r) const override {
        const ray_space to_ray(r);
        bool positive = false, negative = false;
        ray_space_point previous = to_ray(vertices_.back());
        for (const point& p : vertices_) {
            const ray_space_point current = to_ray(p);
            const double e = edge_function(previous, current);
            positive = positive || e > 0;
            negative = negative || e < 0;
            if (positive && negative) return intersection::none();
            previous = current;
        }
        if (!positive && !negative) return intersection::none();  // the ray lies in the polygon's plane
        const double denominator = r.direction() * normal_;
        if (denominator == 0) return intersection::none();
        const double t = ((vertices_.front() - r.origin()) * normal_) / denominator;
        if (t > std::fabs(zero_t()) && std::isfinite(t)) return intersection::at(t, this);
        return intersection::none();
    }

    vector normal_;  ///< unit, by Newell's method: the counter-clockwise side
    point min_, max_;
};

}  // namespace

std::unique_ptr<primitive> make_polygon(std::vector<point> vertices) {
    return shapes::polygon_base::make<polygon>(std::move(vertices));
}

}  // namespace vl::stage02
