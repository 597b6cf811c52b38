// Pixel sample patterns, one class each. Random numbers come from PCG32 (O'Neill,
// https://www.pcg-random.org), a local generator seeded with the pixel's seed.
#include <cmath>
#include <cstdint>

#include "stage_01.hh"

namespace vl::stage01 {

namespace {

class pcg32 {
public:
    explicit pcg32(std::uint64_t seed, std::uint64_t stream = 0x5851f42d4c957f2dull) : inc_((stream << 1) | 1) {
        next();
        state_ += seed;
        next();
    }
    std::uint32_t next() {
        const std::uint64_t old = state_;
        state_ = old * 6364136223846793005ull + inc_;
        const auto xorshifted = static_cast<std::uint32_t>(((old >> 18) ^ old) >> 27);
        const auto rot = static_cast<std::uint32_t>(old >> 59);
        return (xorshifted >> rot) | (xorshifted << ((32 - rot) & 31));
    }
    /// 53 random bits from two outputs: uniform in [0, 1).
    double uniform() {
        const std::uint64_t hi = next(), lo = next();
        return static_cast<double>(((hi << 32) | lo) >> 11) * 0x1p-53;
    }

private:
    std::uint64_t state_ = 0, inc_;
};

std::size_t side_for(std::size_t n) {
    std::size_t k = static_cast<std::size_t>(std::sqrt(static_cast<double>(n)));
    while (k * k < n) ++k;
    while (k > 1 && (k - 1) * (k - 1) >= n) --k;
    return k;
}

/// A coordinate in cell `c` of `k`, at fraction `u` of it, strictly below the cell's end.
double cell_coordinate(std::size_t c, double u, std::size_t k) {
    const double end = static_cast<double>(c + 1) / static_cast<double>(k);
    const double v = (static_cast<double>(c) + u) / static_cast<double>(k);
    return v >= end ? std::nextafter(end, 0.0) : v;
}

class center_sampler : public sampler {
public:
    void offsets(std::span<sample_offset> out, std::uint64_t) const override {
        for (sample_offset& o : out) o = {0.5, 0.5};
    }
};

class grid_sampler : public sampler {
public:
    explicit grid_sampler(bool jitter) : jitter_(jitter) {}
    void offsets(std::span<sample_offset> out, std::uint64_t seed) const override {
        if (out.empty()) return;
        pcg32 g(seed);
        const std::size_t k = side_for(out.size());
        for (std::size_t i = 0; i < out.size(); ++i) {
            const double ux = jitter_ ? g.uniform() : 0.5;
            const double uy = jitter_ ? g.uniform() : 0.5;
            out[i] = {cell_coordinate(i % k, ux, k), cell_coordinate(i / k, uy, k)};
        }
    }

private:
    bool jitter_;
};

class random_sampler : public sampler {
public:
    void offsets(std::span<sample_offset> out, std::uint64_t seed) const override {
        pcg32 g(seed);
        for (sample_offset& o : out) {
            o.dx = g.uniform();
            o.dy = g.uniform();
        }
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

}  // namespace vl::stage01
