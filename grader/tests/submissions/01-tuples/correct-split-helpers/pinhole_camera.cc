// The pinhole camera: image positions become normalized device coordinates in [-1, 1]
// (the centre is 0, 0), scaled by the half-extent of the image plane at distance 1.
#include <cmath>
#include <numbers>

#include "geometry.hh"
#include "stage_01.hh"
#include "vl/error.hh"

namespace vl::stage01 {

namespace {

class ndc_camera : public camera {
public:
    ndc_camera(const camera_settings& s, int width, int height)
        : eye_(s.eye), frame_(geometry::eye_frame(s.eye, s.look_at, s.up, "pinhole camera")) {
        if (!(s.fov_degrees > 0 && s.fov_degrees < 180))
            throw usage_error("pinhole camera: fov_degrees must lie strictly between 0 and 180");
        if (width < 1 || height < 1) throw usage_error("pinhole camera: the image must be at least 1 x 1 pixels");
        w_ = width;
        h_ = height;
        half_height_ = std::tan(s.fov_degrees * (std::numbers::pi / 180) / 2);
        half_width_ = half_height_ * w_ / h_;  // square pixels
    }

    ray primary_ray(double x, double y) const override {
        const double ndc_x = 2 * x / w_ - 1, ndc_y = 2 * y / h_ - 1;
        return {eye_, frame_.forward + frame_.right * (ndc_x * half_width_) + frame_.up * (ndc_y * half_height_)};
    }

private:
    point eye_;
    geometry::frame frame_;
    double w_ = 1, h_ = 1, half_width_ = 0, half_height_ = 0;
};

}  // namespace

std::unique_ptr<camera> make_pinhole_camera(const camera_settings& settings, int width, int height) {
    return std::make_unique<ndc_camera>(settings, width, height);
}

}  // namespace vl::stage01
