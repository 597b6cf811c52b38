// The infinite plane in the form n . p = offset, with n unit.
#include <cmath>
#include <ostream>

#include "numbers.hh"
#include "stage_02.hh"
#include "vl/primitive_bases.hh"

namespace vl::stage02 {

namespace {

class plane final : public shapes::plane_base {
public:
    plane(const point& point_on_plane, const vector& normal) : plane_base(point_on_plane, normal) { geometry_changed(); }

    vector normal(const point&) const override { return unit_; }

    void write(std::ostream& s) const override {
        s << "PLANE { point";
        for (const double x : {point_.x, point_.y, point_.z}) {
            s << ' ';
            write_number(s, x);
        }
        s << " normal";
        for (const double x : {normal_.x, normal_.y, normal_.z}) {
            s << ' ';
            write_number(s, x);
        }
        write_surface(s);
        s << " }";
    }

private:
    void geometry_changed() override {
        unit_ = normal_.unit();
        offset_ = unit_.x * point_.x + unit_.y * point_.y + unit_.z * point_.z;
    }

    intersection find_intersection(const ray& r) const override {
        const double speed = unit_ * r.direction();
        if (speed == 0) return intersection::none();
        const point& o = r.origin();
        const double t = (offset_ - (unit_.x * o.x + unit_.y * o.y + unit_.z * o.z)) / speed;
        if (!std::isfinite(t) || !(t > std::fabs(zero_t()))) return intersection::none();
        return intersection::at(t, this);
    }

    vector unit_;
    double offset_ = 0;
};

}  // namespace

std::unique_ptr<primitive> make_plane(const point& point_on_plane, const vector& normal) {
    shapes::plane_base::check(point_on_plane, normal);
    return std::make_unique<plane>(point_on_plane, normal);
}

}  // namespace vl::stage02
