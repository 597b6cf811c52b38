// The convex polygon: one long double edge function per edge in the ray's sheared frame
// (shear.hh), inside when no two disagree in sign; t from the polygon's plane in long
// double. Polygons sharing an edge compute its function from the same two sheared points.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "shear.hh"
#include "stage_02.hh"
#include "vl/convex_polygon.hh"
#include "vl/primitive_bases.hh"
#include "wide.hh"

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
        const shear to_ray(r);
        int signs = 0;  // bit 0: some edge function < 0, bit 1: some > 0
        sheared previous = to_ray(vertices_.back());
        for (const point& p : vertices_) {
            const sheared current = to_ray(p);
            const long double e = edge_of(previous, current);
            if (e < 0) signs |= 1;
            if (e > 0) signs |= 2;
            previous = current;
        }
        if (signs != 1 && signs != 2) return intersection::none();  // outside, or the ray is in the plane
        const wide::vec n = wide::from(normal_);
        const long double cosine = wide::dot(wide::from(r.direction()), n);
        if (cosine == 0) return intersection::none();
        const double t = static_cast<double>(wide::dot(wide::from(vertices_.front()) - wide::from(r.origin()), n) / cosine);
        if (std::isfinite(t) && t > std::fabs(zero_t())) return intersection::at(t, this);
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
