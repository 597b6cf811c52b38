// Pixel sample patterns, one class for all four; the random ones draw from SplitMix64
// seeded with the pixel's seed, a local of offsets().
#include <cmath>
#include <cstdint>

#include "stage_01.hh"

namespace vl::stage01 {

namespace {

struct splitmix64 {
    std::uint64_t state;
    std::uint64_t next() {
        std::uint64_t z = (state += 0x9e3779b97f4a7c15ull);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        return z ^ (z >> 31);
    }
    /// Uniform in [0, 1): the top 53 bits.
    double uniform() { return static_cast<double>(next() >> 11) * 0x1p-53; }
};

enum class kind { center, grid, jittered, random };

std::size_t grid_side(std::size_t n) {
    std::size_t k = 1;
    while (k * k < n) ++k;
    return k;
}

/// (cell + u) / k, kept below the cell's upper edge.
double in_cell(std::size_t cell, double u, std::size_t k) {
    const double kk = static_cast<double>(k), c = static_cast<double>(cell);
    const double v = (c + u) / kk, top = (c + 1) / kk;
    return v < top ? v : std::nextafter(top, 0.0);
}

class pattern : public sampler {
public:
    explicit pattern(kind k) : kind_(k) {}

    void offsets(std::span<sample_offset> out, std::uint64_t seed) const override {
        const std::size_t n = out.size();
        if (n == 0) return;
        splitmix64 rng{seed};
        if (kind_ == kind::center) {
            for (auto& o : out) o = {0.5, 0.5};
        } else if (kind_ == kind::random) {
            for (auto& o : out) {
                const double dx = rng.uniform();
                o = {dx, rng.uniform()};
            }
        } else {
            const std::size_t k = grid_side(n);
            for (std::size_t i = 0; i < n; ++i) {
                const double ux = kind_ == kind::grid ? 0.5 : rng.uniform();
                const double uy = kind_ == kind::grid ? 0.5 : rng.uniform();
                out[i] = {in_cell(i % k, ux, k), in_cell(i / k, uy, k)};
            }
        }
    }

private:
    kind kind_;
};

}  // namespace

std::unique_ptr<sampler> make_sampler(std::string_view name) {
    if (name == "center") return std::make_unique<pattern>(kind::center);
    if (name == "grid") return std::make_unique<pattern>(kind::grid);
    if (name == "jittered") return std::make_unique<pattern>(kind::jittered);
    if (name == "random") return std::make_unique<pattern>(kind::random);
    return nullptr;
}

}  // namespace vl::stage01
