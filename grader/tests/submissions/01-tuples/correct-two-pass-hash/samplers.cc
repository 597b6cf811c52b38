// Pixel sample patterns with counter-based randomness: the numbers of sample i are a
// hash of (seed, i), so no generator state exists at all.
#include <cmath>
#include <cstdint>

#include "stage_01.hh"

namespace vl::stage01 {

namespace {

/// The SplitMix64 finalizer: a bijective 64-bit mix.
std::uint64_t mix(std::uint64_t z) {
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

/// Uniform in [0, 1), a function of (seed, counter) alone.
double hashed_uniform(std::uint64_t seed, std::uint64_t counter) {
    const std::uint64_t bits = mix(mix(seed) + 0x9e3779b97f4a7c15ull * (counter + 1));
    return static_cast<double>(bits >> 11) / 9007199254740992.0;  // 2^53
}

enum class pattern_kind { center, grid, jittered, random };

class hashed_sampler : public sampler {
public:
    explicit hashed_sampler(pattern_kind k) : kind_(k) {}

    void offsets(std::span<sample_offset> out, std::uint64_t seed) const override {
        const std::size_t n = out.size();
        std::size_t k = 1;
        while (k * k < n) ++k;
        const double side = static_cast<double>(k);
        for (std::size_t i = 0; i < n; ++i) {
            const double ux = hashed_uniform(seed, 2 * i), uy = hashed_uniform(seed, 2 * i + 1);
            switch (kind_) {
                case pattern_kind::center: out[i] = {0.5, 0.5}; break;
                case pattern_kind::random: out[i] = {ux, uy}; break;
                case pattern_kind::grid:
                case pattern_kind::jittered: {
                    const double cx = static_cast<double>(i % k), cy = static_cast<double>(i / k);
                    const double jx = kind_ == pattern_kind::grid ? 0.5 : ux;
                    const double jy = kind_ == pattern_kind::grid ? 0.5 : uy;
                    double dx = (cx + jx) / side, dy = (cy + jy) / side;
                    const double ex = (cx + 1) / side, ey = (cy + 1) / side;
                    if (dx >= ex) dx = std::nextafter(ex, 0.0);
                    if (dy >= ey) dy = std::nextafter(ey, 0.0);
                    out[i] = {dx, dy};
                    break;
                }
            }
        }
    }

private:
    pattern_kind kind_;
};

}  // namespace

std::unique_ptr<sampler> make_sampler(std::string_view name) {
    if (name == "center") return std::make_unique<hashed_sampler>(pattern_kind::center);
    if (name == "grid") return std::make_unique<hashed_sampler>(pattern_kind::grid);
    if (name == "jittered") return std::make_unique<hashed_sampler>(pattern_kind::jittered);
    if (name == "random") return std::make_unique<hashed_sampler>(pattern_kind::random);
    return nullptr;
}

}  // namespace vl::stage01
