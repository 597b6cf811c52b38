// Reference: the pinhole camera (see assignments/01-tuples/stage_01.hh). The frame is the
// one of the thesis's "Pinhole Camera Model" and of P. Shirley's *Ray Tracing in One
// Weekend* (the camera chapter): an image plane at distance 1 in front of the eye.
#include <cmath>
#include <numbers>
#include <string>

#include "stage_01.hh"
#include "vl/error.hh"

namespace vl::stage01 {

namespace {

/// \brief Rays from one eye through a rectangle of square pixels facing it.
class pinhole_camera final : public camera {
public:
    pinhole_camera(const camera_settings& s, int width, int height)
        : eye_(s.eye.homogenized()), half_width_(width / 2.0), half_height_(height / 2.0) {
        if (width < 1 || height < 1)
            throw usage_error("pinhole camera: the image is " + std::to_string(width) + " x " +
                              std::to_string(height) + " pixels; both sides must be at least 1");
        if (!(s.fov_degrees > 0 && s.fov_degrees < 180))
            throw usage_error("pinhole camera: fov " + std::to_string(s.fov_degrees) +
                              " degrees; it must be more than 0 and less than 180");
        const vector view = s.look_at.homogenized() - eye_;
        if (view.x == 0 && view.y == 0 && view.z == 0)
            throw usage_error("pinhole camera: eye and look_at are the same point, so the camera looks nowhere");
        const vector side = view % s.up;
        if (side.x == 0 && side.y == 0 && side.z == 0)
            throw usage_error("pinhole camera: up is zero or parallel to the view direction; choose an up that is not");

        forward_ = view.unit();
        const vector right = side.unit();
        const vector up = right % forward_;  // the part of s.up perpendicular to the view, made unit
        // The image plane at distance 1 is 2 tan(fov / 2) high; a pixel is that over height.
        const double pixel = 2 * std::tan(s.fov_degrees * std::numbers::pi / 360) / height;
        right_ = right * pixel;
        up_ = up * pixel;
    }

    // Measured from the image's centre, so the centre ray is forward_ exactly instead of
    // a sum of large terms that should cancel and leave rounding behind.
    ray primary_ray(double x, double y) const override {
        return {eye_, forward_ + right_ * (x - half_width_) + up_ * (y - half_height_)};
    }

private:
    point eye_;
    double half_width_, half_height_;  ///< the image's centre, in pixels
    vector forward_;                   ///< unit, from the eye towards look_at
    vector right_, up_;                ///< one pixel to the right and one pixel up, on the image plane
};

}  // namespace

std::unique_ptr<camera> make_pinhole_camera(const camera_settings& settings, int width, int height) {
    return std::make_unique<pinhole_camera>(settings, width, height);
}

}  // namespace vl::stage01
