// Pixel sample patterns from xoshiro256** (Blackman and Vigna, https://prng.di.unimi.it),
// its four words of state filled from the seed by SplitMix64, all local to offsets().
#include <cmath>
#include <cstdint>

#include "stage_01.hh"

namespace vl::stage01 {

namespace {

class xoshiro256ss {
public:
    explicit xoshiro256ss(std::uint64_t seed) {
        for (std::uint64_t& word : s_) {
            std::uint64_t z = (seed += 0x9e3779b97f4a7c15ull);
            z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
            z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
            word = z ^ (z >> 31);
        }
    }
    std::uint64_t operator()() {
        const std::uint64_t result = rotl(s_[1] * 5, 7) * 9, t = s_[1] << 17;
        s_[2] ^= s_[0];
        s_[3] ^= s_[1];
        s_[1] ^= s_[2];
        s_[0] ^= s_[3];
        s_[2] ^= t;
        s_[3] = rotl(s_[3], 45);
        return result;
    }
    double uniform() { return static_cast<double>((*this)() >> 11) * 0x1.0p-53; }

private:
    static std::uint64_t rotl(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
    std::uint64_t s_[4];
};

class center_pattern : public sampler {
public:
    void offsets(std::span<sample_offset> out, std::uint64_t) const override {
        for (auto& o : out) o = sample_offset{};
    }
};

class random_pattern : public sampler {
public:
    void offsets(std::span<sample_offset> out, std::uint64_t seed) const override {
        xoshiro256ss g(seed);
        for (auto& o : out) {
            o.dx = g.uniform();
            o.dy = g.uniform();
        }
    }
};

class cell_pattern : public sampler {
public:
    explicit cell_pattern(bool jittered) : jittered_(jittered) {}

    void offsets(std::span<sample_offset> out, std::uint64_t seed) const override {
        std::size_t k = 0;
        while (k * k < out.size()) ++k;
        xoshiro256ss g(seed);
        for (std::size_t i = 0; i < out.size(); ++i) {
            const double u = jittered_ ? g.uniform() : 0.5, v = jittered_ ? g.uniform() : 0.5;
            out[i].dx = place(i % k, u, k);
            out[i].dy = place(i / k, v, k);
        }
    }

private:
    static double place(std::size_t cell, double u, std::size_t k) {
        const double c = static_cast<double>(cell), n = static_cast<double>(k);
        const double x = (c + u) / n, upper = (c + 1) / n;
        return x < upper ? x : std::nextafter(upper, 0.0);
    }
    bool jittered_;
};

}  // namespace

std::unique_ptr<sampler> make_sampler(std::string_view name) {
    if (name == "center") return std::make_unique<center_pattern>();
    if (name == "grid") return std::make_unique<cell_pattern>(false);
    if (name == "jittered") return std::make_unique<cell_pattern>(true);
    if (name == "random") return std::make_unique<random_pattern>();
    return nullptr;
}

}  // namespace vl::stage01
