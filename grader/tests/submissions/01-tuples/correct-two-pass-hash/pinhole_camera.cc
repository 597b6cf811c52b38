// The pinhole camera with its image plane through look_at: the centre ray is exactly
// look_at - eye, and one pixel is 2 d tan(fov / 2) / height there (d the distance to it).
// The view is first scaled by a power of two (exact) so that its length is near 1 and
// vl::ray can square its components even for an eye 1e200 away.
#include <cmath>
#include <numbers>

#include "stage_01.hh"
#include "vl/error.hh"

namespace vl::stage01 {

namespace {

vector to_unit(const vector& v) {
    const double ax = std::abs(v.x), ay = std::abs(v.y), az = std::abs(v.z);
    const double big = ax > ay ? (ax > az ? ax : az) : (ay > az ? ay : az);
    const vector s(v.x / big, v.y / big, v.z / big);
    return s / s.length();
}

class plane_camera : public camera {
public:
    plane_camera(const camera_settings& s, int width, int height)
        : eye_(s.eye), view_(s.look_at - s.eye), cx_(0.5 * width), cy_(0.5 * height) {
        if (view_.x == 0 && view_.y == 0 && view_.z == 0)
            throw usage_error("pinhole camera: eye == look_at leaves no direction to look in");
        if (s.up.x == 0 && s.up.y == 0 && s.up.z == 0) throw usage_error("pinhole camera: up is zero");
        if (!(s.fov_degrees > 0) || !(s.fov_degrees < 180))
            throw usage_error("pinhole camera: fov_degrees must be in (0, 180)");
        if (width < 1 || height < 1) throw usage_error("pinhole camera: the image must have pixels");
        {
            const double ax = std::abs(view_.x), ay = std::abs(view_.y), az = std::abs(view_.z);
            const int e = std::ilogb(ax > ay ? (ax > az ? ax : az) : (ay > az ? ay : az));
            view_ = vector(std::ldexp(view_.x, -e), std::ldexp(view_.y, -e), std::ldexp(view_.z, -e));
        }
        const vector forward = to_unit(view_);
        const vector r = forward % to_unit(s.up);
        if (r * r < 1e-30) throw usage_error("pinhole camera: up is parallel to the view direction");
        const vector right = to_unit(r);
        const vector up = right % forward;
        // Distance to the plane, measured without squaring the components.
        const double ax = std::abs(view_.x), ay = std::abs(view_.y), az = std::abs(view_.z);
        const double big = ax > ay ? (ax > az ? ax : az) : (ay > az ? ay : az);
        const double distance = big * vector(view_.x / big, view_.y / big, view_.z / big).length();
        const double pixel = 2 * distance * std::tan(s.fov_degrees / 360 * std::numbers::pi) / height;
        right_ = right * pixel;
        up_ = up * pixel;
    }

    ray primary_ray(double x, double y) const override { return {eye_, view_ + right_ * (x - cx_) + up_ * (y - cy_)}; }

private:
    point eye_;
    vector view_, right_, up_;
    double cx_, cy_;
};

}  // namespace

std::unique_ptr<camera> make_pinhole_camera(const camera_settings& settings, int width, int height) {
    return std::make_unique<plane_camera>(settings, width, height);
}

}  // namespace vl::stage01
