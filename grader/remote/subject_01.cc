// The subject's stage 01: serves each call of calls_01.hh with the student's code. It
// holds the objects the student's factories make, under handles the judge uses.
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "calls_01.hh"
#include "calls_components.hh"
#include "stage_01.hh"
#include "subject.hh"

namespace vl::remote {

namespace {

namespace c = calls_01;
using namespace vl::stage01;

objects<camera> cameras;
objects<sampler> samplers;

/// A handler that reads the arguments `Args...` in order, calls `f` with them and writes
/// its result.
template <class... Args, class F>
handler plain(F f) {
    return [f](message_reader& in, message_writer& out) {
        // Braces: the arguments are read in the order they are listed.
        std::tuple<Args...> args{in.get<Args>()...};
        in.finish();
        out.put(std::apply(f, args));
    };
}

}  // namespace

std::vector<handler> subject_handlers() {
    std::vector<handler> h(calls_components::table_size);
    h[c::translate_matrix] = plain<vector>(translate_matrix);
    h[c::scale_matrix] = plain<double, double, double>(scale_matrix);
    h[c::rotate_x_matrix] = plain<double>(rotate_x_matrix);
    h[c::rotate_y_matrix] = plain<double>(rotate_y_matrix);
    h[c::rotate_z_matrix] = plain<double>(rotate_z_matrix);
    h[c::rotate_matrix] = plain<vector, double>(rotate_matrix);
    h[c::shear_matrix] = plain<double, double>(shear_matrix);
    h[c::look_at_matrix] = plain<point, point, vector>(look_at_matrix);
    h[c::inverse] = plain<matrix>(inverse);
    h[c::make_pinhole_camera] = plain<camera_settings, int, int>([](const camera_settings& s, int w, int ht) {
        return cameras.add(make_pinhole_camera(s, w, ht));
    });
    h[c::make_sampler] = [](message_reader& in, message_writer& out) {
        const std::string name = in.get_string();
        in.finish();
        out.put(samplers.add(make_sampler(name)));
    };
    h[c::primary_ray] = plain<handle, double, double>(
        [](handle cam, double x, double y) { return cameras.at(cam).primary_ray(x, y); });
    h[c::offsets] = [](message_reader& in, message_writer& out) {
        const auto pattern = in.get<handle>();
        std::vector<sample_offset> values = in.get_vector<sample_offset>(c::max_offsets);
        const auto seed = in.get<std::uint64_t>();
        in.finish();
        samplers.at(pattern).offsets(values, seed);
        out.put_vector(values);
    };
    h[c::offsets_each] = [](message_reader& in, message_writer& out) {
        const auto pattern = in.get<handle>();
        const std::vector<sample_offset> fill = in.get_vector<sample_offset>(c::max_offsets);
        const std::vector<std::uint64_t> seeds = in.get_vector<std::uint64_t>(c::max_offsets);
        in.finish();
        if (fill.size() * seeds.size() > c::max_offsets) throw protocol_error("a batch of offsets too large");
        std::vector<sample_offset> values;
        values.reserve(fill.size() * seeds.size());
        for (const std::uint64_t seed : seeds) {
            std::vector<sample_offset> one = fill;
            samplers.at(pattern).offsets(one, seed);
            values.insert(values.end(), one.begin(), one.end());
        }
        out.put_vector(values);
    };
    return h;
}

void release_object(handle h) {
    cameras.erase(h);
    samplers.erase(h);
}

}  // namespace vl::remote
