// The pinhole camera, built on the view matrix: a ray is made in the eye's coordinates
// (the eye at the origin looking down -z, up +y, right +x) and taken to the world by the
// inverse of look_at_matrix.
#include <cmath>
#include <numbers>

#include "stage_01.hh"
#include "vl/error.hh"

namespace vl::stage01 {

namespace {

class view_camera : public camera {
public:
    view_camera(const camera_settings& s, int width, int height)
        : eye_(s.eye), half_w_(width / 2.0), half_h_(height / 2.0) {
        if (!(s.fov_degrees > 0 && s.fov_degrees < 180))
            throw usage_error("pinhole camera: the field of view must be more than 0 and less than 180 degrees");
        if (width < 1 || height < 1) throw usage_error("pinhole camera: width and height must be at least 1");
        to_world_ = inverse(look_at_matrix(s.eye, s.look_at, s.up));  // throws for eye == look_at or a bad up
        pixel_ = std::tan(s.fov_degrees / 2 * std::numbers::pi / 180) / half_h_;
    }

    ray primary_ray(double x, double y) const override {
        const vector in_eye((x - half_w_) * pixel_, (y - half_h_) * pixel_, -1);
        return {eye_, to_world_ * in_eye};
    }

private:
    point eye_;
    double half_w_, half_h_, pixel_ = 0;
    matrix to_world_;
};

}  // namespace

std::unique_ptr<camera> make_pinhole_camera(const camera_settings& settings, int width, int height) {
    return std::make_unique<view_camera>(settings, width, height);
}

}  // namespace vl::stage01
