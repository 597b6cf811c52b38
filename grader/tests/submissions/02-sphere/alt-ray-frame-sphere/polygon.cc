// The convex polygon as a fan of watertight triangles; t from the polygon's plane.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "across.hh"
#include "numbers.hh"
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

    // A fan of triangles around vertex 0; each fan triangle is tested with the edge
    // functions of across.hh. Fan triangles share spokes and polygons share edges, and
    // both sides of a shared edge compute its function from the same two points.
    intersection find_intersection(const ray& r) const override {
        const seen hub = see(r, vertices_[0]);
        for (std::size_t k = 1; k + 1 < vertices_.size(); ++k) {
            const seen b = see(r, vertices_[k]), c = see(r, vertices_[k + 1]);
            const double wa = edge_value(r, b, c), wb = edge_value(r, c, hub), wc = edge_value(r, hub, b);
            if ((wa < 0 || wb < 0 || wc < 0) && (wa > 0 || wb > 0 || wc > 0)) continue;
            if (wa == 0 && wb == 0 && wc == 0) continue;
            const double cosine = r.direction() * normal_;
            if (cosine == 0) return intersection::none();
            const double t = ((vertices_[0] - r.origin()) * normal_) / cosine;
            if (std::isfinite(t) && t > std::fabs(zero_t())) return intersection::at(t, this);
            return intersection::none();
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
