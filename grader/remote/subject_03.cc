// The subject's stage 03: serves each call of calls_03.hh with the student's factories,
// and the composites' members (calls_components.hh) with the student's composites. The
// shapes of stage 02 that the student's code makes (a BOX's faces, a FRACSPH's spheres)
// are the judge's (subject_shapes.cc): their tests are counted there.
#include <memory>
#include <string>
#include <vector>

#include "calls_03.hh"
#include "stage_03.hh"
#include "subject_components.hh"
#include "vl/registry.hh"
#include "vl/scene_reader.hh"

namespace vl::remote {

namespace {

namespace c = calls_03;
using namespace vl::stage03;

/// The types a scene text read here may name: the framework's and the student's.
const registry& types() {
    static const registry* const r = [] {
        auto* made = new registry();
        register_framework(*made);
        register_stage_03(*made);
        return made;
    }();
    return *r;
}

}  // namespace

std::vector<handler> subject_handlers() {
    std::vector<handler> h;
    add_component_handlers(h);
    h[c::make_bounding_sphere] = [](message_reader& in, message_writer& out) {
        in.finish();
        out.put(components().add(make_bounding_sphere()));
    };
    h[c::make_frac_sphere] = [](message_reader& in, message_writer& out) {
        const auto center = in.get<point>();
        const auto radius = in.get<double>();
        const auto depth = in.get<int>();
        const auto ratio = in.get<double>();
        in.finish();
        out.put(components().add(make_frac_sphere(center, radius, depth, ratio)));
    };
    h[c::make_box] = [](message_reader& in, message_writer& out) {
        const auto lo = in.get<point>();
        const auto hi = in.get<point>();
        in.finish();
        out.put(components().add(make_box(lo, hi)));
    };
    h[c::make_transformed] = [](message_reader& in, message_writer& out) {
        std::unique_ptr<rtab_component> child = read_child(in);
        const auto m = in.get<matrix>();
        in.finish();
        out.put(components().add(make_transformed(std::move(child), m)));
    };
    h[c::make_bvh] = [](message_reader& in, message_writer& out) {
        const auto leaf_size = in.get<int>();
        in.finish();
        out.put(components().add(make_bvh(leaf_size)));
    };
    h[c::read_object] = [](message_reader& in, message_writer& out) {
        const std::string text = in.get_string(c::max_text_bytes);
        in.finish();
        scene_reader reader(types());
        reader.open_text(text, "hidden.ray_trace");
        out.put(components().add(reader.read_object()));
    };
    return h;
}

void release_object(handle h) { components().erase(h); }

}  // namespace vl::remote
