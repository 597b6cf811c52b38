// The pinhole camera in pixel units: the image plane lies `focal` pixels in front of the
// eye, focal = (height / 2) / tan(fov / 2), so one pixel is one unit along right and up.
#include <cmath>
#include <numbers>

#include "stage_01.hh"
#include "vl/error.hh"

namespace vl::stage01 {

namespace {

vector normalize(const vector& v) {
    const double len = std::hypot(v.x, v.y, v.z);
    return vector(v.x / len, v.y / len, v.z / len);
}

class pixel_unit_camera : public camera {
public:
    pixel_unit_camera(const camera_settings& s, int width, int height) : eye_(s.eye) {
        const vector d = s.look_at - s.eye;
        if (d.x == 0 && d.y == 0 && d.z == 0) throw usage_error("pinhole camera: eye and look_at must differ");
        if (s.up.x == 0 && s.up.y == 0 && s.up.z == 0) throw usage_error("pinhole camera: up must not be zero");
        if (!(s.fov_degrees > 0 && s.fov_degrees < 180))
            throw usage_error("pinhole camera: fov_degrees must be greater than 0 and less than 180");
        if (width <= 0 || height <= 0) throw usage_error("pinhole camera: width and height must be positive");
        const vector f = normalize(d);
        const vector side = f % normalize(s.up);
        if (side.length() < 1e-15) throw usage_error("pinhole camera: up is parallel to the view direction");
        right_ = normalize(side);
        up_ = right_ % f;
        const double focal = (height / 2.0) / std::tan(s.fov_degrees / 2 * std::numbers::pi / 180);
        forward_ = f * focal;
        cx_ = width / 2.0;
        cy_ = height / 2.0;
    }

    ray primary_ray(double x, double y) const override {
        return {eye_, forward_ + right_ * (x - cx_) + up_ * (y - cy_)};
    }

private:
    point eye_;
    vector forward_, right_, up_;
    double cx_ = 0, cy_ = 0;
};

}  // namespace

std::unique_ptr<camera> make_pinhole_camera(const camera_settings& settings, int width, int height) {
    return std::make_unique<pixel_unit_camera>(settings, width, height);
}

}  // namespace vl::stage01
