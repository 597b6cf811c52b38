// libFuzzer target: the scene reader must turn any bytes into a scene or a vl::file_error,
// never a crash, a hang or an unbounded allocation.
#include <cstddef>
#include <cstdint>
#include <string>

#include "vl/error.hh"
#include "vl/primitive.hh"
#include "vl/registry.hh"
#include "vl/scene.hh"

namespace {

// A leaf with a few typed properties, so the fuzzer reaches every kind of typed read.
class fuzz_leaf final : public vl::primitive {
public:
    std::string type_name() const override { return "LEAF"; }
    void read(vl::scene_reader& in) override {
        read_with_surface(in, {{"at", [&] { p_ = in.read_point("at"); }},
                               {"dir", [&] { v_ = in.read_vector("dir"); }},
                               {"size", [&] { s_ = in.read_positive("size"); }},
                               {"count", [&] { n_ = in.read_int("count", 0, 100); }},
                               {"name", [&] { name_ = in.read_string("name"); }}});
    }

private:
    vl::intersection find_intersection(const vl::ray&) const override { return vl::intersection::none(); }
    vl::point p_;
    vl::vector v_;
    double s_ = 1;
    int n_ = 0;
    std::string name_;
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const vl::registry types = [] {
        vl::registry r;
        vl::register_framework(r);
        r.add("LEAF", [] { return std::make_unique<fuzz_leaf>(); });
        return r;
    }();
    try {
        // Text only: includes would read the disk, which a fuzzer must not depend on.
        std::string text(reinterpret_cast<const char*>(data), size);
        if (text.find("include") != std::string::npos) return 0;
        vl::parse_scene(std::move(text), "fuzz.ray_trace", types);
    } catch (const vl::file_error&) {
    } catch (const vl::usage_error&) {
    }
    return 0;
}
