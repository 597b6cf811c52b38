#pragma once
/// \file
/// \brief A random generator that costs nothing to seed: SplitMix64.
///
/// A sample pattern seeds a generator once per pixel (vl::sampler::offsets), so seeding
/// must be cheap. `std::mt19937_64` fills 312 words of state from its seed, which takes
/// longer than tracing the rays of a simple pixel; SplitMix64 (G. L. Steele, D. Lea and
/// C. H. Flood, "Fast splittable pseudorandom number generators", OOPSLA 2014) keeps one
/// word and passes BigCrush. It is the generator Java's SplittableRandom uses and the one
/// recommended for seeding xoshiro generators.
#include <cstdint>
#include <limits>

namespace vl {

/// SplitMix64's output function: a bijective mix of the 64 bits of `z` in which every
/// input bit changes about half the output bits.
constexpr std::uint64_t splitmix64_mix(std::uint64_t z) {
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

/// The step of SplitMix64's Weyl sequence: the golden ratio's 64-bit fraction.
inline constexpr std::uint64_t splitmix64_gamma = 0x9e3779b97f4a7c15ull;

/// \brief SplitMix64 as a C++ UniformRandomBitGenerator: usable with every
/// `std::*_distribution`, or through uniform01() for doubles in [0, 1).
class splitmix64 {
public:
    using result_type = std::uint64_t;  ///< every 64-bit value can come out

    /// The generator whose first output is splitmix64_mix(seed + splitmix64_gamma).
    constexpr explicit splitmix64(std::uint64_t seed) : state_(seed) {}

    static constexpr result_type min() { return 0; }  ///< the least output
    /// The greatest output.
    static constexpr result_type max() { return std::numeric_limits<result_type>::max(); }

    /// The next 64 random bits.
    constexpr result_type operator()() {
        state_ += splitmix64_gamma;
        return splitmix64_mix(state_);
    }

private:
    std::uint64_t state_;
};

/// A double uniform in [0, 1) from the top 53 bits of `bits`: k / 2^53 for k from 0 to
/// 2^53 - 1, each equally likely, and never 1 (every such k / 2^53 is exact in a double).
constexpr double uniform01(std::uint64_t bits) { return static_cast<double>(bits >> 11) * 0x1p-53; }

}  // namespace vl
