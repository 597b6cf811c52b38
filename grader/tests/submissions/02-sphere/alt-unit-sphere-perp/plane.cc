// The infinite plane.
#include <cmath>
#include <ostream>

#include "format.hh"
#include "stage_02.hh"
#include "vl/primitive_bases.hh"

namespace vl::stage02 {

namespace {

class plane final : public shapes::plane_base {
public:
    plane(const point& point_on_plane, const vector& normal) : plane_base(point_on_plane, normal) { geometry_changed(); }

    vector normal(const point&) const override { return unit_; }

    void write(std::ostream& s) const override {
        s << "PLANE { point " << exact(point_.x) << ' ' << exact(point_.y) << ' ' << exact(point_.z) << " normal "
          << exact(normal_.x) << ' ' << exact(normal_.y) << ' ' << exact(normal_.z);
        write_surface(s);
        s << " }";
    }

private:
    void geometry_changed() override {
        unit_ = normal_.unit();
    }

    intersection find_intersection(const ray& r) const override {
        const double cosine = r.direction() * unit_;
        const double height = (r.origin() - point_) * unit_;  // signed distance of the origin from the plane
        if (cosine == 0) return intersection::none();
        const double t = -height / cosine;
        if (t > std::fabs(zero_t()) && t < HUGE_VAL) return intersection::at(t, this);
        return intersection::none();
    }

    vector unit_;
};

}  // namespace

std::unique_ptr<primitive> make_plane(const point& point_on_plane, const vector& normal) {
    shapes::plane_base::check(point_on_plane, normal);
    return std::make_unique<plane>(point_on_plane, normal);
}

}  // namespace vl::stage02
