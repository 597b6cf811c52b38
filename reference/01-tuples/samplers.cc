// Reference: pixel sample patterns (see assignments/01-tuples/stage_01.hh). Jittered
// (stratified) sampling: R. L. Cook, "Stochastic sampling in computer graphics", ACM
// Transactions on Graphics 5(1), 1986; M. Pharr, W. Jakob and G. Humphreys, *Physically
// Based Rendering*, 4th ed., §8.5.
#include <algorithm>
#include <bit>

#include "stage_01.hh"
#include "vl/random.hh"

namespace vl::stage01 {

namespace {

/// The side k of the smallest k x k grid with at least n cells: counted up, exact and
/// without a square root (a pattern asks for it once per pixel, and k is small).
std::size_t grid_side(std::size_t n) {
    std::size_t k = 0;
    while (k * k < n) ++k;
    return k;
}

/// `value`, or the largest double below `limit` when rounding carried `value` up to it
/// (pbrt clamps its samples to OneMinusEpsilon for the same reason):
/// (k - 1 + 0.9999999999999999) / k rounds to exactly 1 for k = 3.
/// `limit` is a cell's upper edge, positive and finite, so the double just below it is
/// the one whose bits are one less (what std::nextafter(limit, 0.0) computes, without the
/// library call that cost a tenth of a simple render).
double below(double value, double limit) {
    return std::min(value, std::bit_cast<double>(std::bit_cast<std::uint64_t>(limit) - 1));
}

/// Uniform numbers in [0, 1) from a generator seeded with the pixel's seed only, so a
/// pixel's offsets are the same on every run, thread and sampler object. SplitMix64
/// (vl/random.hh), because a pattern seeds one per pixel: seeding std::mt19937_64 fills
/// 312 words and cost more than half of a 4-sample render.
class uniform_source {
public:
    explicit uniform_source(std::uint64_t seed) : rng_(seed) {}
    double operator()() { return uniform01(rng_()); }

private:
    splitmix64 rng_;
};

class center_sampler final : public sampler {
public:
    void offsets(std::span<sample_offset> out, std::uint64_t) const override {
        std::fill(out.begin(), out.end(), sample_offset{0.5, 0.5});
    }
};

/// The k x k grid; sample i in cell (i % k, i / k), at its centre or jittered within it.
class grid_sampler final : public sampler {
public:
    explicit grid_sampler(bool jitter) : jitter_(jitter) {}

    void offsets(std::span<sample_offset> out, std::uint64_t seed) const override {
        const std::size_t k = grid_side(out.size());
        const double side = static_cast<double>(k);
        // Where cell coordinate c (0 to k - 1) plus j (in [0, 1)) falls, in [0, 1). For a
        // power-of-two k, 1 / k and every product with it are exact, so multiplying gives
        // the very double the division gives, without the division's cost; the choice is
        // made once, outside the loops.
        if (std::has_single_bit(k)) {
            const double inverse = 1 / side;
            place_all(out, k, seed, [inverse](double c, double j) { return below((c + j) * inverse, (c + 1) * inverse); });
        } else {
            place_all(out, k, seed, [side](double c, double j) { return below((c + j) / side, (c + 1) / side); });
        }
    }

private:
    /// Sample i in cell (x, y) = (i % k, i / k), counted row by row without dividing, at
    /// `along(x, jx), along(y, jy)`: the cell's centre, or jittered within it.
    template <class along_axis>
    void place_all(std::span<sample_offset> out, std::size_t k, std::uint64_t seed, along_axis along) const {
        auto place = [&](std::size_t i, std::size_t cx, std::size_t cy, double jx, double jy) {
            out[i] = {along(static_cast<double>(cx), jx), along(static_cast<double>(cy), jy)};
        };
        if (!jitter_) {  // nothing is drawn, so no generator is made
            for (std::size_t i = 0, y = 0; i < out.size(); ++y)
                for (std::size_t x = 0; x < k && i < out.size(); ++x, ++i) place(i, x, y, 0.5, 0.5);
            return;
        }
        uniform_source u(seed);
        for (std::size_t i = 0, y = 0; i < out.size(); ++y) {
            for (std::size_t x = 0; x < k && i < out.size(); ++x, ++i) {
                const double jx = u();  // x first, then y: the order of the draws is part of the image
                place(i, x, y, jx, u());
            }
        }
    }

    bool jitter_;
};

class random_sampler final : public sampler {
public:
    void offsets(std::span<sample_offset> out, std::uint64_t seed) const override {
        uniform_source u(seed);
        for (auto& o : out) {
            o.dx = u();
            o.dy = u();
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
