// The infinite plane: t from the plane equation (p - point) . n = 0.
#include <cmath>
#include <limits>
#include <ostream>

#include "stage_02.hh"
#include "vl/primitive_bases.hh"

namespace vl::stage02 {

namespace {

class plane final : public shapes::plane_base {
public:
    plane(const point& point_on_plane, const vector& normal) : plane_base(point_on_plane, normal) { geometry_changed(); }

    vector normal(const point&) const override { return unit_normal_; }

    void write(std::ostream& s) const override {
        const auto old_precision = s.precision(std::numeric_limits<double>::max_digits10);
        s << "PLANE { point " << point_.x << ' ' << point_.y << ' ' << point_.z << " normal " << normal_.x << ' '
          << normal_.y << ' ' << normal_.z;
        s.precision(old_precision);
        write_surface(s);
        s << " }";
    }

private:
    void geometry_changed() override {
        unit_normal_ = normal_.unit();
    }

    intersection find_intersection(const ray& r) const override {
        const double facing = r.direction() * unit_normal_;
        if (facing == 0) return intersection::none();  // parallel, or lying in the plane
        const double t = ((point_ - r.origin()) * unit_normal_) / facing;
        if (std::isfinite(t) && t > std::fabs(zero_t())) return intersection::at(t, this);
        return intersection::none();
    }

    vector unit_normal_;
};

}  // namespace

std::unique_ptr<primitive> make_plane(const point& point_on_plane, const vector& normal) {
    shapes::plane_base::check(point_on_plane, normal);
    return std::make_unique<plane>(point_on_plane, normal);
}

}  // namespace vl::stage02
