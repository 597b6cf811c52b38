// Reference: the sphere (see assignments/02-sphere/stage_02.hh).
#include <cmath>
#include <utility>

#include "stage_02.hh"
#include "vl/primitive_bases.hh"

namespace vl::stage02 {

namespace {

/// \brief The thesis's sphere: every point at distance `radius_` from `center_`.
class sphere final : public shapes::sphere_base {
public:
    vector normal(const point& p) const override { return (p - center_).unit(); }
    bool contains(const point& p) const override { return (p - center_).length() < radius_; }
    point min_point() const override { return center_ - vector(radius_, radius_, radius_); }
    point max_point() const override { return center_ + vector(radius_, radius_, radius_); }
    ball bounding_ball() const override { return {center_, radius_}; }

private:
    // Robust ray-sphere intersection (Haines, Guenther and Akenine-Moeller, "Precision
    // Improvements for Ray/Sphere Intersection", Ray Tracing Gems ch. 7). With the unit
    // direction d and f = origin - center, t solves t^2 + 2 b t + c = 0 with b = f.d and
    // c = f.f - r^2.
    // - The discriminant b^2 - c subtracts two nearly equal large numbers when the sphere
    //   is small and far away (both are about |f|^2). It equals r^2 - |l|^2, where
    //   l = f - b d runs from the centre to the point of the line nearest to it; |l| is
    //   no larger than r near a hit, so nothing large cancels.
    // - The root -b - sign(b) sqrt(disc) adds numbers of the same sign; the other root
    //   follows from the product of the roots, t0 t1 = c, instead of from -b + sign(b)
    //   sqrt(disc), which cancels when a root is near 0 (a ray leaving the surface).
    intersection find_intersection(const ray& r) const override {
        const vector f = r.origin() - center_;
        const vector d = r.direction();
        const double b = f * d;
        const vector l = f - b * d;
        const double disc = radius_ * radius_ - l * l;
        if (disc < 0) return intersection::none();
        const double q = -(b + std::copysign(std::sqrt(disc), b));
        if (q == 0) return intersection::none();  // origin on the sphere, ray tangent: both roots 0
        const double c = f * f - radius_ * radius_;
        double t0 = c / q, t1 = q;
        if (t0 > t1) std::swap(t0, t1);
        const double eps = std::fabs(zero_t());
        if (t0 > eps) return intersection::at(t0, this);
        if (t1 > eps) return intersection::at(t1, this);  // the origin is inside (or on) the sphere
        return intersection::none();
    }
};

}  // namespace

std::unique_ptr<primitive> make_sphere(const point& center, double radius) {
    return shapes::sphere_base::make<sphere>(center, radius);
}

}  // namespace vl::stage02
