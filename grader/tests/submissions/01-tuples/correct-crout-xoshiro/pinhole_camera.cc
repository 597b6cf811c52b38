// The pinhole camera: a direction in the eye's coordinates ((x - w/2) s, (y - h/2) s, -1)
// is taken to the world by the eye's frame matrix, whose columns are right, up and back.
#include <cmath>
#include <numbers>

#include "stage_01.hh"
#include "vl/error.hh"

namespace vl::stage01 {

namespace {

vector unit_of(const vector& v) {
    const double m = std::fmax(std::fabs(v.x), std::fmax(std::fabs(v.y), std::fabs(v.z)));
    const vector s(v.x / m, v.y / m, v.z / m);
    return s / s.length();
}

class frame_camera : public camera {
public:
    frame_camera(const camera_settings& s, int width, int height) : eye_(s.eye) {
        const vector view = s.look_at - s.eye;
        if (view.x == 0 && view.y == 0 && view.z == 0)
            throw usage_error("pinhole camera: the eye may not be at look_at");
        if (s.up.x == 0 && s.up.y == 0 && s.up.z == 0) throw usage_error("pinhole camera: up may not be zero");
        if (!(s.fov_degrees > 0 && s.fov_degrees < 180))
            throw usage_error("pinhole camera: the field of view must be between 0 and 180 degrees, exclusive");
        if (width < 1 || height < 1) throw usage_error("pinhole camera: an image needs a width and height of 1 or more");
        const vector back = -unit_of(view);
        const vector c = unit_of(s.up) % back;
        if (c.length() <= 1e-15) throw usage_error("pinhole camera: up is parallel to the view direction");
        const vector right = unit_of(c);
        const vector up = back % right;
        to_world_ = matrix(point(right.x, right.y, right.z, 0), point(up.x, up.y, up.z, 0),
                           point(back.x, back.y, back.z, 0), point(0, 0, 0, 1));
        scale_ = 2 * std::tan(s.fov_degrees * std::numbers::pi / 360) / height;
        half_w_ = width / 2.0;
        half_h_ = height / 2.0;
    }

    ray primary_ray(double x, double y) const override {
        return {eye_, to_world_ * vector((x - half_w_) * scale_, (y - half_h_) * scale_, -1)};
    }

private:
    point eye_;
    matrix to_world_;
    double scale_ = 0, half_w_ = 0, half_h_ = 0;
};

}  // namespace

std::unique_ptr<camera> make_pinhole_camera(const camera_settings& settings, int width, int height) {
    return std::make_unique<frame_camera>(settings, width, height);
}

}  // namespace vl::stage01
