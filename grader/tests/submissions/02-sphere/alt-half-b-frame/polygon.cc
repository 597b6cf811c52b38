// The convex polygon: the ray passes through it when no two of its edge functions, in the
// ray's frame (ray_frame.hh), have opposite signs. Two polygons sharing an edge compute
// that edge's function from the same two points, so a box of faces has no gaps.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "numbers.hh"
#include "ray_frame.hh"
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
        for (const point& p : vertices_) {
            s << " (";
            write_number(s, p.x);
            s << ", ";
            write_number(s, p.y);
            s << ", ";
            write_number(s, p.z);
            s << ')';
        }
        write_surface(s);
        s << " }";
    }

private:
    void geometry_changed() override {
        normal_ = newell_normal(vertices_, centroid_of(vertices_)).unit();
        low_ = high_ = vertices_.front();
        for (const point& p : vertices_) {
            low_ = point(std::min(low_.x, p.x), std::min(low_.y, p.y), std::min(low_.z, p.z));
            high_ = point(std::max(high_.x, p.x), std::max(high_.y, p.y), std::max(high_.z, p.z));
        }
    }

    intersection find_intersection(const ray& r) const override {
        const ray_frame frame(r);
        bool negative = false, positive = false;
        frame_point previous = frame(vertices_.back());
        for (const point& p : vertices_) {
            const frame_point current = frame(p);
            const double e = edge(previous, current);
            negative = negative || e < 0;
            positive = positive || e > 0;
            if (negative && positive) return intersection::none();
            previous = current;
        }
        if (!negative && !positive) return intersection::none();  // the ray lies in the plane
        const double speed = r.direction() * normal_;
        if (speed == 0) return intersection::none();
        const double t = ((vertices_.front() - r.origin()) * normal_) / speed;
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
