// Binds stage 01's pieces for the scene reader and the render driver (see stage_01.hh).
// This file is complete: there is nothing to write here.
#include "stage_01.hh"

namespace vl::stage01 {

void register_stage_01(registry& r) {
    r.set_camera([](const camera_settings& s, int width, int height) { return make_pinhole_camera(s, width, height); });
    for (const std::string_view name : sampler_names)
        r.add_sampler(name, [name] { return make_sampler(name); });
}

}  // namespace vl::stage01
