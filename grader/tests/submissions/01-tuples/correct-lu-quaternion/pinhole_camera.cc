// The pinhole camera: the image plane one unit in front of the eye, reached from its
// lower-left corner by whole steps along right and up (as in P. Shirley's "Ray Tracing in
// One Weekend"). At the centre the corner and the steps cancel only up to rounding, a few
// units in the last place of the image plane's half-width.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "stage_01.hh"
#include "vl/error.hh"

namespace vl::stage01 {

namespace {

vector unit_xyz(const vector& v) {
    const double big = std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
    const vector s(v.x / big, v.y / big, v.z / big);
    return s / s.length();
}

bool is_zero(const vector& v) { return v.x == 0 && v.y == 0 && v.z == 0; }

class corner_camera : public camera {
public:
    corner_camera(const camera_settings& s, int width, int height) : eye_(s.eye) {
        const vector view = s.look_at - s.eye;
        if (is_zero(view)) throw usage_error("pinhole camera: eye and look_at are the same point");
        if (is_zero(s.up)) throw usage_error("pinhole camera: up is the zero vector");
        if (!(s.fov_degrees > 0 && s.fov_degrees < 180))
            throw usage_error("pinhole camera: fov_degrees must be strictly between 0 and 180");
        if (width < 1 || height < 1) throw usage_error("pinhole camera: the image needs at least 1 x 1 pixels");
        const vector forward = unit_xyz(view);
        const vector side = forward % unit_xyz(s.up);
        if (side.length() <= 4 * std::numeric_limits<double>::epsilon())
            throw usage_error("pinhole camera: up is parallel to the view direction");
        const vector right = unit_xyz(side);
        const vector up = right % forward;
        const double pixel = 2 * std::tan(s.fov_degrees * std::numbers::pi / 360) / height;
        step_right_ = right * pixel;
        step_up_ = up * pixel;
        lower_left_ = forward - step_right_ * (width / 2.0) - step_up_ * (height / 2.0);
    }

    ray primary_ray(double x, double y) const override {
        return {eye_, lower_left_ + step_right_ * x + step_up_ * y};
    }

private:
    point eye_;
    vector lower_left_, step_right_, step_up_;
};

}  // namespace

std::unique_ptr<camera> make_pinhole_camera(const camera_settings& settings, int width, int height) {
    return std::make_unique<corner_camera>(settings, width, height);
}

}  // namespace vl::stage01
