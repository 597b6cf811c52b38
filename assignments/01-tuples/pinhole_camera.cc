// Stage 01: the pinhole camera. What its rays must be is in stage_01.hh; the interface it
// implements is vl::camera (vl/camera.hh); the public tests are in
// tests/pinhole_camera_test.cc.
#include "stage_01.hh"
#include "vl/error.hh"
#include "vl/not_implemented.hh"

namespace vl::stage01 {

// TODO: write a class that derives from vl::camera and overrides primary_ray(x, y). Put
//       it in an anonymous namespace: nothing outside this file needs its name.
// TODO: in its constructor, check the settings (vl::usage_error for each bad case the
//       contract lists), then work out everything primary_ray needs once: the unit view
//       direction, the image's right and up as unit vectors (the up you are given need
//       not be perpendicular to the view), and how big one pixel is on an image plane at
//       distance 1 from the eye. Which angle does the field of view measure, and what is
//       the half-height of that plane?
// TODO: in primary_ray, go from the eye to the point of the image plane at (x, y). Where
//       is (0, 0), and where is the centre? Think about which way of writing the sum gives
//       exactly the view direction at the centre of the image.

std::unique_ptr<camera> make_pinhole_camera([[maybe_unused]] const camera_settings& settings,
                                            [[maybe_unused]] int width, [[maybe_unused]] int height) {
    // TODO: return std::make_unique of your camera class.
    throw not_implemented_error();
}

}  // namespace vl::stage01
