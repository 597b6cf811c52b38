// The judge's stage 04: the contract's factory (stage_04.hh) as a call to the subject, and
// a stand-in for the tracer it makes. The scene stays here: its values cross with every
// call, its root is lent (judge_components.hh), so each object the student's tracer tests
// is tested here, by the judge's own code, and every probe the tests put in a scene
// (watchers, emitters, planes) sees exactly the rays the tracer asks about.
#include <memory>
#include <string>
#include <vector>

#include "calls_04.hh"
#include "judge_components.hh"
#include "stage_04.hh"

namespace vl::stage04 {

namespace {

using namespace vl::remote;
namespace c = calls_04;

/// Writes `s` as the subject reads it: its values, its strings, its lights, its root.
void put_scene(message_writer& w, const scene& s) {
    c::scene_values v;
    v.camera = s.camera;
    v.width = s.width;
    v.height = s.height;
    v.ambient = s.ambient;
    v.background = s.background;
    v.samples_per_pixel = s.samples_per_pixel;
    v.max_depth = s.max_depth;
    w.put(v).put_string(s.sampler).put_string(s.tracer).put_vector(s.lights);
    put_child(w, s.root.get());
}

/// \brief The student's tracer, in the subject, for the judge's scene `s`.
class remote_tracer final : public tracer, private remote_object {
public:
    remote_tracer(handle h, const scene& s) : remote_object(h), scene_(s) {}
    color trace(const ray& r, int depth) const override {
        message_writer w;
        w.put(id());
        put_scene(w, scene_);
        w.put(r).put(depth);
        message_reader in = subject().call(c::trace, w, "trace");
        const auto got = in.get<color>();
        in.finish();
        return got;
    }

private:
    const scene& scene_;
};

}  // namespace

std::unique_ptr<tracer> make_whitted_tracer(const scene& s) {
    message_writer w;
    put_scene(w, s);
    const handle h = made_in_subject(c::make_whitted_tracer, w, "make_whitted_tracer");
    if (h == 0) return nullptr;
    return std::make_unique<remote_tracer>(h, s);
}

}  // namespace vl::stage04
