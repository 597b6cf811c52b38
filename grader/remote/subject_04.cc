// The subject's stage 04: serves make_whitted_tracer and trace (calls_04.hh) with the
// student's tracer. Each tracer has a scene of its own here, made of the values the judge
// sends and a stand-in of the judge's root (a lent object): the tracer's tests of the
// scene's objects are calls back to the judge.
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "calls_04.hh"
#include "stage_04.hh"
#include "subject_components.hh"

namespace vl::remote {

namespace {

namespace c = calls_04;
using namespace vl::stage04;

/// \brief A tracer and the scene it was made for (it keeps a reference to it).
struct traced_scene {
    std::mutex mutex;  ///< a change of the scene's values (trace() of two threads asks for none)
    scene s;
    handle root = 0;
    std::unique_ptr<tracer> t;
};

objects<traced_scene> tracers;

bool same(const color& a, const color& b) { return a.r == b.r && a.g == b.g && a.b == b.b && a.a == b.a; }
bool same(const point& a, const point& b) { return a.x == b.x && a.y == b.y && a.z == b.z && a.w == b.w; }
bool same(const vector& a, const vector& b) { return a.x == b.x && a.y == b.y && a.z == b.z && a.w == b.w; }

/// Reads a scene as put_scene() wrote it into `ts`, changing only what differs (a tracer
/// may be tracing on another thread meanwhile, with the same values).
void read_scene(message_reader& in, traced_scene& ts) {
    const auto v = in.get<c::scene_values>();
    std::string sampler = in.get_string(), kind = in.get_string();
    const auto lights = in.get_vector<color_point>(c::max_lights);
    const auto root_kind = in.get<child_kind>();
    handle root = 0;
    std::string type;
    description d;
    if (root_kind == child_kind::lent) {
        root = in.get<handle>();
        type = in.get_string();
        d = in.get<description>();
    } else if (root_kind != child_kind::none) {
        throw protocol_error("a scene's root that is not the judge's");
    }
    const std::lock_guard<std::mutex> lock(ts.mutex);
    scene& s = ts.s;
    if (!same(s.camera.eye, v.camera.eye) || !same(s.camera.look_at, v.camera.look_at) ||
        !same(s.camera.up, v.camera.up) || s.camera.fov_degrees != v.camera.fov_degrees)
        s.camera = v.camera;
    if (s.width != v.width) s.width = v.width;
    if (s.height != v.height) s.height = v.height;
    if (!same(s.ambient, v.ambient)) s.ambient = v.ambient;
    if (!same(s.background, v.background)) s.background = v.background;
    if (s.samples_per_pixel != v.samples_per_pixel) s.samples_per_pixel = v.samples_per_pixel;
    if (s.max_depth != v.max_depth) s.max_depth = v.max_depth;
    if (s.sampler != sampler) s.sampler = std::move(sampler);
    if (s.tracer != kind) s.tracer = std::move(kind);
    bool lights_same = s.lights.size() == lights.size();
    for (std::size_t k = 0; lights_same && k < lights.size(); ++k)
        lights_same = same(s.lights[k].clr(), lights[k].clr()) && same(s.lights[k].pnt(), lights[k].pnt());
    if (!lights_same) s.lights = lights;
    if (ts.root != root || !s.root) {
        s.root = root == 0 ? std::make_unique<object_list>() : lent_list(root, std::move(type), d);
        ts.root = root;
    }
}

}  // namespace

std::vector<handler> subject_handlers() {
    std::vector<handler> h;
    add_component_handlers(h);
    h[c::make_whitted_tracer] = [](message_reader& in, message_writer& out) {
        auto ts = std::make_unique<traced_scene>();
        read_scene(in, *ts);
        in.finish();
        ts->t = make_whitted_tracer(ts->s);
        if (!ts->t) {
            out.put(handle{0});
            return;
        }
        out.put(tracers.add(std::move(ts)));
    };
    h[c::trace] = [](message_reader& in, message_writer& out) {
        traced_scene& ts = tracers.at(in.get<handle>());
        read_scene(in, ts);
        const auto r = in.get<ray>();
        const auto depth = in.get<int>();
        in.finish();
        out.put(ts.t->trace(r, depth));
    };
    return h;
}

void release_object(handle h) {
    tracers.erase(h);
    components().erase(h);
}

}  // namespace vl::remote
