// Reference: pixel sample patterns (see assignments/01-tuples/stage_01.hh).
#include <cmath>
#include <random>
#include <string>

#include "stage_01.hh"

namespace vl::stage01 {

namespace {

int grid_side(std::size_t n) { return static_cast<int>(std::ceil(std::sqrt(static_cast<double>(n)))); }

class center_sampler final : public sampler {
public:
    void offsets(std::span<sample_offset> out, std::uint64_t) const override {
        for (auto& o : out) o = {0.5, 0.5};
    }
};

class grid_sampler final : public sampler {
public:
    explicit grid_sampler(bool jitter) : jitter_(jitter) {}
    void offsets(std::span<sample_offset> out, std::uint64_t seed) const override {
        const int k = grid_side(out.size());
        std::mt19937_64 rng(seed);
        std::uniform_real_distribution<double> u(0, 1);
        for (std::size_t i = 0; i < out.size(); ++i) {
            const int cx = static_cast<int>(i) % k, cy = static_cast<int>(i) / k;
            const double jx = jitter_ ? u(rng) : 0.5, jy = jitter_ ? u(rng) : 0.5;
            out[i] = {(cx + jx) / k, (cy + jy) / k};
        }
    }

private:
    bool jitter_;
};

class random_sampler final : public sampler {
public:
    void offsets(std::span<sample_offset> out, std::uint64_t seed) const override {
        std::mt19937_64 rng(seed);
        std::uniform_real_distribution<double> u(0, 1);
        for (auto& o : out) o = {u(rng), u(rng)};
    }
};

}  // namespace

std::unique_ptr<sampler> make_sampler(std::string_view name) {
    if (name == "center") return std::make_unique<center_sampler>();
    if (name == "grid") return std::make_unique<grid_sampler>(false);
    if (name == "jittered") return std::make_unique<grid_sampler>(true);
    if (name == "random") return std::make_unique<random_sampler>();
    return nullptr;
}

void register_stage_01(registry& r) {
    r.set_camera([](const camera_settings& s, int w, int h) { return make_pinhole_camera(s, w, h); });
    for (const char* name : {"center", "grid", "jittered", "random"})
        r.add_sampler(name, [name] { return make_sampler(name); });
}

}  // namespace vl::stage01
