// The sphere, by the geometric method: the ray's closest approach to the centre, then
// the half chord on either side of it.
#include <cmath>
#include <limits>
#include <ostream>
#include <utility>

#include "stage_02.hh"
#include "vl/primitive_bases.hh"

namespace vl::stage02 {

namespace {

class sphere final : public shapes::sphere_base {
public:
    sphere(const point& center, double radius) : sphere_base(center, radius) {}

    vector normal(const point& p) const override { return (p - center_).unit(); }
    bool contains(const point& p) const override {
        const vector f = p - center_;
        return f * f < radius_ * radius_;
    }
    point min_point() const override { return {center_.x - radius_, center_.y - radius_, center_.z - radius_}; }
    point max_point() const override { return {center_.x + radius_, center_.y + radius_, center_.z + radius_}; }

    void write(std::ostream& s) const override {
        const auto old_precision = s.precision(std::numeric_limits<double>::max_digits10);
        s << "SPHERE { center " << center_.x << ' ' << center_.y << ' ' << center_.z << " radius " << radius_;
        s.precision(old_precision);
        write_surface(s);
        s << " }";
    }

private:
    intersection find_intersection(const ray& r) const override {
        const vector d = r.direction();
        const vector to_center = center_ - r.origin();
        const double along = to_center * d;              // where the ray comes closest to the centre
        const vector miss = to_center - along * d;        // from that closest point to the centre
        const double miss2 = miss * miss;
        const double r2 = radius_ * radius_;
        if (miss2 > r2) return intersection::none();
        const double half_chord = std::sqrt(r2 - miss2);
        // The two roots multiply to c = |to_center|^2 - r^2; the one with no cancellation
        // is computed directly and the other from the product.
        const double c = to_center * to_center - r2;
        double t_near = 0, t_far = 0;
        if (along > 0) {
            t_far = along + half_chord;
            t_near = c / t_far;
        } else {
            t_near = along - half_chord;
            if (t_near == 0) return intersection::none();
            t_far = c / t_near;
        }
        if (t_near > t_far) std::swap(t_near, t_far);
        const double eps = std::fabs(zero_t());
        if (t_near > eps && std::isfinite(t_near)) return intersection::at(t_near, this);
        if (t_far > eps && std::isfinite(t_far)) return intersection::at(t_far, this);
        return intersection::none();
    }
};

}  // namespace

std::unique_ptr<primitive> make_sphere(const point& center, double radius) {
    shapes::sphere_base::check(center, radius);
    return std::make_unique<sphere>(center, radius);
}

}  // namespace vl::stage02
