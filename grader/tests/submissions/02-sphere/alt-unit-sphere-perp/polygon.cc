// The convex polygon: one edge function per edge (across.hh); the ray passes through the
// polygon when they do not disagree in sign. t comes from the polygon's plane.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "across.hh"
#include "format.hh"
#include "stage_02.hh"
#include "vl/convex_polygon.hh"
#include "vl/primitive_bases.hh"

namespace vl::stage02 {

namespace {

class polygon final : public shapes::polygon_base {
public:
    explicit polygon(std::vector<point> vertices) : polygon_base(std::move(vertices)) { geometry_changed(); }

    vector normal(const point&) const override { return normal_; }
    point min_point() const override { return low_; }
    point max_point() const override { return high_; }

    void write(std::ostream& s) const override {
        s << "POLYGON { vertices";
        for (const point& p : vertices_) s << " (" << exact(p.x) << ", " << exact(p.y) << ", " << exact(p.z) << ')';
        write_surface(s);
        s << " }";
    }

private:
    void geometry_changed() override {
        normal_ = newell_normal(vertices_, centroid_of(vertices_)).unit();
        low_ = high_ = vertices_[0];
        for (const point& p : vertices_) {
            low_ = point(std::min(low_.x, p.x), std::min(low_.y, p.y), std::min(low_.z, p.z));
            high_ = point(std::max(high_.x, p.x), std::max(high_.y, p.y), std::max(high_.z, p.z));
        }
    }

    intersection find_intersection(const ray& r) const override {
        std::size_t below = 0, above = 0;
        seen previous = see(r, vertices_.back());
        for (const point& p : vertices_) {
            const seen current = see(r, p);
            const double e = edge_value(r, previous, current);
            if (e < 0) ++below;
            if (e > 0) ++above;
            previous = current;
        }
        if ((below > 0 && above > 0) || below + above == 0) return intersection::none();
        const double cosine = r.direction() * normal_;
        if (cosine == 0) return intersection::none();
        const double t = ((vertices_[0] - r.origin()) * normal_) / cosine;
        if (std::isfinite(t) && t > std::fabs(zero_t())) return intersection::at(t, this);
        return intersection::none();
    }

    vector normal_;
    point low_, high_;
};

}  // namespace

std::unique_ptr<primitive> make_polygon(std::vector<point> vertices) {
    shapes::polygon_base::check(vertices);
    return std::make_unique<polygon>(std::move(vertices));
}

}  // namespace vl::stage02
