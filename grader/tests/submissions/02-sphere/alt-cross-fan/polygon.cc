// The convex polygon as a fan of the watertight triangles of frame.hh around its first
// vertex: neighbouring fan triangles share a spoke, neighbouring polygons an edge, and
// each side computes that edge's function from the same two points.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "frame.hh"
#include "stage_02.hh"
#include "text.hh"
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
        for (const point& p : vertices_) s << " (" << number{p.x} << ", " << number{p.y} << ", " << number{p.z} << ')';
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
        const frame f(r);
        const in_frame hub = f(vertices_[0]);
        in_frame previous = f(vertices_[1]);
        for (std::size_t k = 2; k < vertices_.size(); ++k) {
            const in_frame current = f(vertices_[k]);
            if (const auto t = crossing(hub, previous, current)) {
                if (std::isfinite(*t) && *t > std::fabs(zero_t())) return intersection::at(*t, this);
                return intersection::none();
            }
            previous = current;
        }
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
