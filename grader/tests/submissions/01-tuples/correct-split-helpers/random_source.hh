#pragma once
// Uniform numbers in [0, 1) from std::mt19937_64, made fresh for each call of offsets().

#include <cstdint>
#include <random>

namespace vl::stage01 {

class random_source {
public:
    explicit random_source(std::uint64_t seed) : engine_(seed) {}
    /// The top 53 bits of one output: a multiple of 2^-53 in [0, 1), never 1.
    double next() { return static_cast<double>(engine_() >> 11) * 0x1p-53; }

private:
    std::mt19937_64 engine_;
};

}  // namespace vl::stage01
