// Pixel sample patterns from std::mt19937 (32 bits), seeded per call through
// std::seed_seq with both halves of the 64-bit seed; std::generate_canonical makes the
// doubles, kept below 1 (and below each cell's upper edge).
#include <cmath>
#include <random>

#include "stage_01.hh"

namespace vl::stage01 {

namespace {

std::mt19937 engine_for(std::uint64_t seed) {
    std::seed_seq seq{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32)};
    return std::mt19937(seq);
}

double canonical(std::mt19937& g) {
    const double u = std::generate_canonical<double, 53>(g);
    return u < 1 ? u : std::nextafter(1.0, 0.0);
}

double in_cell(double cell, double u, double k) {
    const double v = (cell + u) / k, top = (cell + 1) / k;
    return v < top ? v : std::nextafter(top, 0.0);
}

class center_s : public sampler {
    void offsets(std::span<sample_offset> out, std::uint64_t) const override {
        for (auto& o : out) o.dx = 0.5, o.dy = 0.5;
    }
};

class grid_s : public sampler {
public:
    explicit grid_s(bool jitter) : jitter_(jitter) {}
    void offsets(std::span<sample_offset> out, std::uint64_t seed) const override {
        if (out.empty()) return;
        auto g = engine_for(seed);
        std::size_t k = 1;
        while (k * k < out.size()) ++k;
        const double side = static_cast<double>(k);
        for (std::size_t i = 0; i < out.size(); ++i) {
            const double cx = static_cast<double>(i % k), cy = static_cast<double>(i / k);
            if (jitter_) {
                const double ux = canonical(g);
                out[i] = {in_cell(cx, ux, side), in_cell(cy, canonical(g), side)};
            } else {
                out[i] = {in_cell(cx, 0.5, side), in_cell(cy, 0.5, side)};
            }
        }
    }

private:
    bool jitter_;
};

class random_s : public sampler {
    void offsets(std::span<sample_offset> out, std::uint64_t seed) const override {
        auto g = engine_for(seed);
        for (auto& o : out) {
            o.dx = canonical(g);
            o.dy = canonical(g);
        }
    }
};

}  // namespace

std::unique_ptr<sampler> make_sampler(std::string_view name) {
    if (name == "center") return std::make_unique<center_s>();
    if (name == "grid") return std::make_unique<grid_s>(false);
    if (name == "jittered") return std::make_unique<grid_s>(true);
    if (name == "random") return std::make_unique<random_s>();
    return nullptr;
}

}  // namespace vl::stage01
