// The pinhole camera, reusing the look-at matrix: its upper-left 3 x 3 block turns world
// directions into the eye's, so its transpose turns the eye's directions back into the
// world's. A ray is made in the eye's coordinates and turned.
#include <cmath>
#include <numbers>

#include "stage_01.hh"
#include "vl/error.hh"

namespace vl::stage01 {

namespace {

class turned_camera : public camera {
public:
    turned_camera(const camera_settings& s, int width, int height) : eye_(s.eye) {
        if (width < 1 || height < 1) throw usage_error("pinhole camera: width and height must be 1 or more");
        if (!(s.fov_degrees > 0 && s.fov_degrees < 180))
            throw usage_error("pinhole camera: fov_degrees must be strictly between 0 and 180");
        matrix turn = look_at_matrix(s.eye, s.look_at, s.up);  // throws for a bad eye, look_at or up
        for (int i = 0; i < 3; ++i) turn(i, 3) = 0;
        to_world_ = turn.transpose();
        tan_half_ = std::tan(s.fov_degrees / 2 * (std::numbers::pi / 180));
        aspect_ = static_cast<double>(width) / height;
        width_ = width;
        height_ = height;
    }

    ray primary_ray(double x, double y) const override {
        const double u = (x / width_ * 2 - 1) * tan_half_ * aspect_;
        const double v = (y / height_ * 2 - 1) * tan_half_;
        return {eye_, to_world_ * vector(u, v, -1)};
    }

private:
    point eye_;
    matrix to_world_;
    double tan_half_ = 0, aspect_ = 1, width_ = 1, height_ = 1;
};

}  // namespace

std::unique_ptr<camera> make_pinhole_camera(const camera_settings& settings, int width, int height) {
    return std::make_unique<turned_camera>(settings, width, height);
}

}  // namespace vl::stage01
