// vl::splitmix64 against SplitMix64's published outputs (Vigna's splitmix64.c, seed 0),
// vl::uniform01's range, and vl::pixel_seed, which is one SplitMix64 step from the
// pixel's coordinates.
#include "vl/random.hh"

#include "vl/catch.hh"

#include <cmath>
#include <random>
#include <set>

#include "vl/render.hh"

using namespace vl;

static_assert(std::uniform_random_bit_generator<splitmix64>);

TEST_CASE("random: splitmix64 gives SplitMix64's published outputs for seed 0", "[random]") {
    splitmix64 g(0);
    CHECK(g() == 0xe220a8397b1dcdafull);
    CHECK(g() == 0x6e789e6aa1b965f4ull);
    CHECK(g() == 0x06c45d188009454full);
}

TEST_CASE("random: the same seed gives the same sequence, another seed another", "[random]") {
    splitmix64 a(42), b(42), c(43);
    for (int i = 0; i < 100; ++i) {
        const auto x = a();
        CHECK(x == b());
        CHECK(x != c());
    }
}

TEST_CASE("random: uniform01 runs from 0 to the largest double below 1", "[random]") {
    CHECK(uniform01(0) == 0.0);
    CHECK(uniform01(~0ull) == std::nextafter(1.0, 0.0));
    CHECK(uniform01(1ull << 63) == 0.5);
    splitmix64 g(7);
    double sum = 0;
    const int n = 100000;
    for (int i = 0; i < n; ++i) {
        const double u = uniform01(g());
        REQUIRE(u >= 0.0);
        REQUIRE(u < 1.0);
        sum += u;
    }
    CHECK(std::abs(sum / n - 0.5) < 0.005);  // 5.5 standard deviations of the mean
}

TEST_CASE("random: a std distribution takes splitmix64", "[random]") {
    splitmix64 g(3);
    std::uniform_int_distribution<int> d(1, 6);
    std::set<int> seen;
    for (int i = 0; i < 600; ++i) seen.insert(d(g));
    CHECK(seen == std::set<int>{1, 2, 3, 4, 5, 6});
}

TEST_CASE("random: pixel_seed is a SplitMix64 step of the coordinates and the image seed", "[random]") {
    CHECK(pixel_seed(0, 0) == 0xe220a8397b1dcdafull);  // the state 0, stepped once
    CHECK(pixel_seed(0, 0, 0) == pixel_seed(0, 0));
    std::set<std::uint64_t> seeds;
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) seeds.insert(pixel_seed(x, y));
    CHECK(seeds.size() == 64 * 64);
    CHECK(pixel_seed(5, 9, 1) != pixel_seed(5, 9, 0));
    CHECK(pixel_seed(5, 9) != pixel_seed(9, 5));
}
