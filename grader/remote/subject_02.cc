// The subject's stage 02: serves each call of calls_02.hh with the student's factories,
// and the objects' members (calls_components.hh) with the student's shapes.
#include <vector>

#include "calls_02.hh"
#include "stage_02.hh"
#include "subject_components.hh"

namespace vl::remote {

namespace {

namespace c = calls_02;
using namespace vl::stage02;

/// A handler that reads the arguments `Args...` in order and keeps the object `f` makes
/// of them, answering with its handle.
template <class... Args, class F>
handler factory(F f) {
    return [f](message_reader& in, message_writer& out) {
        std::tuple<Args...> args{in.get<Args>()...};
        in.finish();
        out.put(components().add(std::apply(f, args)));
    };
}

/// The student's primitive `h` (every object the judge has made here is one).
primitive& primitive_at(handle h) {
    auto* p = dynamic_cast<primitive*>(&components().at(h));
    if (p == nullptr) throw protocol_error("the object " + std::to_string(h) + " is no primitive");
    return *p;
}

}  // namespace

std::vector<handler> subject_handlers() {
    std::vector<handler> h;
    add_component_handlers(h);
    h[c::make_sphere] = factory<point, double>(make_sphere);
    h[c::make_plane] = factory<point, vector>(make_plane);
    h[c::make_triangle] = factory<point, point, point>(make_triangle);
    h[c::make_polygon] = [](message_reader& in, message_writer& out) {
        std::vector<point> vertices = in.get_vector<point>(c::max_vertices);
        in.finish();
        out.put(components().add(make_polygon(std::move(vertices))));
    };
    h[c::adopt] = [](message_reader& in, message_writer&) {
        const auto into = in.get<handle>(), from = in.get<handle>();
        in.finish();
        components().adopt(into, from);
    };
    h[c::set_surface] = [](message_reader& in, message_writer&) {
        const auto target = in.get<handle>();
        const auto s = in.get<surface>();
        in.finish();
        primitive_at(target).set_surface(s);
    };
    return h;
}

void release_object(handle h) { components().erase(h); }

}  // namespace vl::remote
