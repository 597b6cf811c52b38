#pragma once
/// \file
/// \brief Stage 04's calls across the connection: the contract's factory
/// (make_whitted_tracer) and the tracer's trace(). The scene crosses with every call as
/// values (camera, lights, ambient, background, depth, ...) and its root as a lent object
/// (calls_components.hh): the tracer's every test of an object is a call back to the judge,
/// where the scene lives, and a change a test makes to the scene between two calls is
/// seen at the next, as in one process.
#include "channel.hh"
#include "vl/scene.hh"

namespace vl::remote::calls_04 {

enum op : op_id {
    make_whitted_tracer,  ///< scene -> handle
    trace,                ///< handle, scene, ray, int depth -> color
};

/// The values of a vl::scene that cross as bytes (its strings, lights and root follow).
struct scene_values {
    camera_settings camera;
    int width = 0, height = 0;
    color ambient, background;
    int samples_per_pixel = 1;
    int max_depth = 5;
};

/// The most lights a scene crosses with.
inline constexpr std::size_t max_lights = 1 << 16;

}  // namespace vl::remote::calls_04
