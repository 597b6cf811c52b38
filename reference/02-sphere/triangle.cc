// Reference: the watertight triangle (see assignments/02-sphere/stage_02.hh).
#include <algorithm>
#include <cmath>

#include "ray_space.hh"
#include "stage_02.hh"
#include "vl/primitive_bases.hh"

namespace vl::stage02 {

namespace {

/// \brief The triangle a b c; its front is the side from which a, b, c run counter-clockwise.
class triangle final : public shapes::triangle_base {
public:
    vector normal(const point&) const override { return normal_; }
    point min_point() const override {
        return {std::min({a_.x, b_.x, c_.x}), std::min({a_.y, b_.y, c_.y}), std::min({a_.z, b_.z, c_.z})};
    }
    point max_point() const override {
        return {std::max({a_.x, b_.x, c_.x}), std::max({a_.y, b_.y, c_.y}), std::max({a_.z, b_.z, c_.z})};
    }

private:
    void geometry_changed() override { normal_ = ((b_ - a_) % (c_ - a_)).unit(); }

    // Watertight ray/triangle intersection (Woop, Benthin and Wald, JCGT 2(1), 2013).
    // The vertices go to ray space (ray_space.hh), where the ray is the +z axis; the ray
    // passes through the triangle when the three edge functions U, V, W do not have
    // mixed signs. A zero counts as inside, so a ray exactly on a shared edge is reported
    // by both neighbours rather than by neither. Unlike Moeller-Trumbore, no barycentric
    // coordinate is compared against a rounded 1 - u - v, so no ray slips between the
    // triangles of a mesh.
    intersection find_intersection(const ray& r) const override {
        const ray_space to_ray(r);
        const ray_space_point a = to_ray(a_), b = to_ray(b_), c = to_ray(c_);
        const double u = edge_function(b, c), v = edge_function(c, a), w = edge_function(a, b);
        if ((u < 0 || v < 0 || w < 0) && (u > 0 || v > 0 || w > 0)) return intersection::none();
        const double det = u + v + w;
        if (det == 0) return intersection::none();  // the ray lies in the triangle's plane
        // t is the z of the hit point, interpolated with the (unnormalised) barycentrics.
        const double t = (u * a.z + v * b.z + w * c.z) / det;
        if (t > std::fabs(zero_t())) return intersection::at(t, this);
        return intersection::none();
    }

    vector normal_;  ///< ((b - a) % (c - a)).unit()
};

}  // namespace

std::unique_ptr<primitive> make_triangle(const point& a, const point& b, const point& c) {
    return shapes::triangle_base::make<triangle>(a, b, c);
}

}  // namespace vl::stage02
