// The sphere, intersected in the ray's own frame.
#include <cmath>
#include <ostream>
#include <utility>

#include "numbers.hh"
#include "ray_frame.hh"
#include "stage_02.hh"
#include "vl/primitive_bases.hh"

namespace vl::stage02 {

namespace {

class sphere final : public shapes::sphere_base {
public:
    sphere(const point& center, double radius) : sphere_base(center, radius) {}

    vector normal(const point& p) const override {
        const vector out = p - center_;
        return out / out.length();
    }
    bool contains(const point& p) const override { return (p - center_).length() < radius_; }
    point min_point() const override { return center_ - vector(radius_, radius_, radius_); }
    point max_point() const override { return center_ + vector(radius_, radius_, radius_); }

    void write(std::ostream& s) const override {
        s << "SPHERE { center ";
        write_number(s, center_.x);
        s << ' ';
        write_number(s, center_.y);
        s << ' ';
        write_number(s, center_.z);
        s << " radius ";
        write_number(s, radius_);
        write_surface(s);
        s << " }";
    }

private:
    // In the ray's frame (ray_frame.hh) the ray is the +z axis from (0, 0, 0); the centre
    // is at (x, y, z). The ray meets the sphere at z -+ h with h^2 = r^2 - (x^2 + y^2); the
    // root that is a sum of like signs is computed directly, the other from their product
    // |centre|^2 - r^2.
    intersection find_intersection(const ray& r) const override {
        const frame_point c = ray_frame(r)(center_);
        const double across2 = c.x * c.x + c.y * c.y;
        const double rr = radius_ * radius_;
        if (across2 > rr) return intersection::none();
        const double h = std::sqrt(rr - across2);
        const double product = across2 + c.z * c.z - rr;
        const double far = c.z >= 0 ? c.z + h : c.z - h;
        if (far == 0) return intersection::none();
        double t0 = product / far, t1 = far;
        if (t0 > t1) std::swap(t0, t1);
        const double eps = std::fabs(zero_t());
        if (t0 > eps) return intersection::at(t0, this);
        if (t1 > eps) return intersection::at(t1, this);
        return intersection::none();
    }
};

}  // namespace

std::unique_ptr<primitive> make_sphere(const point& center, double radius) {
    shapes::sphere_base::check(center, radius);
    return std::make_unique<sphere>(center, radius);
}

}  // namespace vl::stage02
