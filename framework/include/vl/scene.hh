#pragma once
/// \file
/// \brief The scene model: what a scene file describes, with a default for every value.

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "vl/object_list.hh"
#include "vl/tuples_based.hh"

namespace vl {

class registry;

/// \brief Where the eye is and what it looks at (a pinhole camera, stage 01).
struct camera_settings {
    point eye{0, 0, 5};       ///< the pinhole
    point look_at{0, 0, 0};   ///< the point seen at the centre of the image
    vector up{0, 1, 0};       ///< which way is up (need not be perpendicular to the view)
    double fov_degrees = 45;  ///< vertical field of view
};

/// \brief Everything a scene file says, ready to render.
///
/// Only what a scene uses is modelled: no z-buffer, alpha or sub-pixels unless it asks
/// for them (samples_per_pixel > 1 is what asks for sub-pixels).
struct scene {
    std::string source;                   ///< the file it was read from
    camera_settings camera;               ///< the viewpoint
    int width = 320;                      ///< image width in pixels
    int height = 240;                     ///< image height in pixels
    std::vector<color_point> lights;      ///< point lights: a colour at a position
    color ambient{0.1, 0.1, 0.1};         ///< light that reaches everything
    color background = BLACK;             ///< what a ray that hits nothing sees
    int samples_per_pixel = 1;            ///< rays per pixel
    std::string sampler = "center";       ///< how those rays are placed in the pixel (a registered name)
    int max_depth = 5;                    ///< recursion depth for reflection and refraction
    std::string tracer = "flat";          ///< the client that turns rays into colours (a registered name)
    std::unique_ptr<object_list> root = std::make_unique<object_list>();  ///< every object
};

/// The largest width or height a scene may ask for.
inline constexpr int max_image_side = 16384;

/// Reads a scene file, creating objects through `types`. Throws vl::file_error with
/// `FILE:LINE:COL: ...` for anything malformed, and for a `sampler` or `tracer` that
/// `types` does not register (the error lists those it does).
scene read_scene(const std::filesystem::path& file, const registry& types);
/// Reads a scene from `text`, reporting errors as in file `name`.
scene parse_scene(std::string text, const std::string& name, const registry& types);

}  // namespace vl
