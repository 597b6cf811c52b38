// The infinite plane.
#include <cmath>
#include <ostream>

#include "stage_02.hh"
#include "text.hh"
#include "vl/primitive_bases.hh"

namespace vl::stage02 {

namespace {

class plane final : public shapes::plane_base {
public:
    plane(const point& point_on_plane, const vector& normal) : plane_base(point_on_plane, normal) {
        geometry_changed();
    }

    vector normal(const point&) const override { return unit_; }

    void write(std::ostream& s) const override {
        s << "PLANE { point " << number{point_.x} << ' ' << number{point_.y} << ' ' << number{point_.z} << " normal "
          << number{normal_.x} << ' ' << number{normal_.y} << ' ' << number{normal_.z};
        write_surface(s);
        s << " }";
    }

private:
    void geometry_changed() override { unit_ = normal_.unit(); }

    intersection find_intersection(const ray& r) const override {
        const double den = r.direction() * unit_;
        if (!(std::fabs(den) > 0)) return intersection::none();
        const double t = ((point_ - r.origin()) * unit_) / den;
        return std::isfinite(t) && t > std::fabs(zero_t()) ? intersection::at(t, this) : intersection::none();
    }

    vector unit_;
};

}  // namespace

std::unique_ptr<primitive> make_plane(const point& point_on_plane, const vector& normal) {
    shapes::plane_base::check(point_on_plane, normal);
    return std::make_unique<plane>(point_on_plane, normal);
}

}  // namespace vl::stage02
