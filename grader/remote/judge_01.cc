// The judge's stage 01: every function of the contract (stage_01.hh) as a call to the
// subject, where the student's code runs, and stand-ins for the camera and the sample
// pattern it makes. The hidden tests link these in place of a stage 01 and read as tests
// of it; nothing here decides anything.
#include <algorithm>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "calls_01.hh"
#include "grading.hh"
#include "judge_connection.hh"
#include "stage_01.hh"

namespace vl::stage01 {

namespace {

using namespace vl::remote;
namespace c = calls_01;

/// Calls `op` with `args` and reads its one result of type T.
template <class T>
T call_for(c::op op, const message_writer& args, const char* what) {
    message_reader r = subject().call(op, args, what);
    const T value = r.get<T>();
    r.finish();
    return value;
}

class remote_camera final : public camera, private remote_object {
public:
    using remote_object::remote_object;
    ray primary_ray(double x, double y) const override {
        message_writer w;
        w.put(id()).put(x).put(y);
        return call_for<ray>(c::primary_ray, w, "the camera's primary_ray");
    }
};

class remote_sampler final : public sampler, private remote_object {
public:
    using remote_object::remote_object;
    handle handle_of() const { return id(); }
    void offsets(std::span<sample_offset> out, std::uint64_t seed) const override {
        // The span crosses with what it holds, so that a pattern that leaves a slot
        // alone leaves it as the test filled it.
        message_writer w;
        w.put(id()).put_vector(std::vector<sample_offset>(out.begin(), out.end())).put(seed);
        message_reader r = subject().call(c::offsets, w, "the sample pattern's offsets");
        const auto got = r.get_vector<sample_offset>(out.size());
        r.finish();
        if (got.size() != out.size())
            throw protocol_error("your code's process answered offsets with " + std::to_string(got.size()) +
                                 " values for a span of " + std::to_string(out.size()));
        std::copy(got.begin(), got.end(), out.begin());
    }
};

/// grading::offsets_for_seeds for a stand-in: the seeds in runs of a few MiB of answer,
/// one crossing each (false for a pattern that is no stand-in).
bool offsets_batch(const sampler& pattern, std::span<const sample_offset> fill, std::span<const std::uint64_t> seeds,
                   std::span<sample_offset> out) {
    const auto* remote = dynamic_cast<const remote_sampler*>(&pattern);
    if (remote == nullptr) return false;
    const std::size_t n = fill.size();
    const std::size_t per_crossing = std::max<std::size_t>(1, (std::size_t{4} << 20) / (sizeof(sample_offset) * std::max<std::size_t>(n, 1)));
    for (std::size_t first = 0; first < seeds.size(); first += per_crossing) {
        const std::size_t count = std::min(per_crossing, seeds.size() - first);
        message_writer w;
        w.put(remote->handle_of()).put_vector(std::vector<sample_offset>(fill.begin(), fill.end()))
            .put_vector(std::vector<std::uint64_t>(seeds.begin() + first, seeds.begin() + first + count));
        message_reader r = subject().call(c::offsets_each, w, "the sample pattern's offsets");
        const auto got = r.get_vector<sample_offset>(n * count);
        r.finish();
        if (got.size() != n * count)
            throw protocol_error("your code's process answered offsets with " + std::to_string(got.size()) +
                                 " values for " + std::to_string(count) + " spans of " + std::to_string(n));
        std::copy(got.begin(), got.end(), out.begin() + static_cast<std::ptrdiff_t>(first * n));
    }
    return true;
}

/// The judge asks batches through its stand-ins from the start.
const bool batches_set = [] {
    grading::batch_of_offsets() = offsets_batch;
    return true;
}();

}  // namespace

matrix translate_matrix(const vector& offset) {
    return call_for<matrix>(c::translate_matrix, message_writer().put(offset), "translate_matrix");
}
matrix scale_matrix(double sx, double sy, double sz) {
    return call_for<matrix>(c::scale_matrix, message_writer().put(sx).put(sy).put(sz), "scale_matrix");
}
matrix rotate_x_matrix(double radians) {
    return call_for<matrix>(c::rotate_x_matrix, message_writer().put(radians), "rotate_x_matrix");
}
matrix rotate_y_matrix(double radians) {
    return call_for<matrix>(c::rotate_y_matrix, message_writer().put(radians), "rotate_y_matrix");
}
matrix rotate_z_matrix(double radians) {
    return call_for<matrix>(c::rotate_z_matrix, message_writer().put(radians), "rotate_z_matrix");
}
matrix rotate_matrix(const vector& axis, double radians) {
    return call_for<matrix>(c::rotate_matrix, message_writer().put(axis).put(radians), "rotate_matrix");
}
matrix shear_matrix(double shx, double shy) {
    return call_for<matrix>(c::shear_matrix, message_writer().put(shx).put(shy), "shear_matrix");
}
matrix look_at_matrix(const point& eye, const point& look_at, const vector& up) {
    return call_for<matrix>(c::look_at_matrix, message_writer().put(eye).put(look_at).put(up), "look_at_matrix");
}
matrix inverse(const matrix& m) { return call_for<matrix>(c::inverse, message_writer().put(m), "inverse"); }

std::unique_ptr<camera> make_pinhole_camera(const camera_settings& settings, int width, int height) {
    const auto h = call_for<handle>(c::make_pinhole_camera, message_writer().put(settings).put(width).put(height),
                                    "make_pinhole_camera");
    if (h == 0) return nullptr;
    return std::make_unique<remote_camera>(h);
}

std::unique_ptr<sampler> make_sampler(std::string_view name) {
    const auto h = call_for<handle>(c::make_sampler, message_writer().put_string(name), "make_sampler");
    if (h == 0) return nullptr;
    return std::make_unique<remote_sampler>(h);
}

}  // namespace vl::stage01
