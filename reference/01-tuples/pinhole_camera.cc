// Reference: the pinhole camera (see assignments/01-tuples/stage_01.hh).
#include <cmath>
#include <numbers>

#include "stage_01.hh"

namespace vl::stage01 {

namespace {

/// An orthonormal frame at the eye: w looks backwards (away from the scene), u right, v up.
class pinhole_camera final : public camera {
public:
    pinhole_camera(const camera_settings& s, int width, int height) : eye_(s.eye) {
        const vector w = (s.eye - s.look_at).unit();
        const vector u = (s.up % w).unit();
        const vector v = w % u;
        // The image plane at distance 1: its height is 2 tan(fov / 2).
        const double pixel = 2 * std::tan(s.fov_degrees * std::numbers::pi / 360) / height;
        right_ = u * pixel;
        up_ = v * pixel;
        lower_left_ = -w - right_ * (width / 2.0) - up_ * (height / 2.0);
    }

    ray primary_ray(double x, double y) const override {
        return {eye_, lower_left_ + right_ * x + up_ * y};
    }

private:
    point eye_;
    vector right_, up_, lower_left_;  // one pixel right, one pixel up, and where (0, 0) is
};

}  // namespace

std::unique_ptr<camera> make_pinhole_camera(const camera_settings& settings, int width, int height) {
    return std::make_unique<pinhole_camera>(settings, width, height);
}

}  // namespace vl::stage01
