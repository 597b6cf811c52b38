// Public tests of the pixel sample patterns (samplers.cc). The contract is stage_01.hh;
// the interface is vl::sampler in vl/camera.hh.
#include "vl/catch.hh"

#include <cmath>
#include <exception>
#include <set>
#include <thread>
#include <utility>
#include <vector>

#include "test_support.hh"

using namespace vl;
using namespace vl::stage01;

namespace {

/// `n` offsets of the pattern `name` for `seed`.
std::vector<sample_offset> offsets_of(std::string_view name, std::size_t n, std::uint64_t seed = 1) {
    const auto pattern = make_sampler(name);
    REQUIRE(pattern);
    std::vector<sample_offset> out(n, sample_offset{-1, -1});  // -1: not filled
    pattern->offsets(out, seed);
    return out;
}

bool same(const std::vector<sample_offset>& a, const std::vector<sample_offset>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (a[i].dx != b[i].dx || a[i].dy != b[i].dy) return false;
    return true;
}

bool in_pixel(const sample_offset& o) { return o.dx >= 0 && o.dx < 1 && o.dy >= 0 && o.dy < 1; }

/// The side of the grid for n samples: the smallest k with k * k >= n.
std::size_t side(std::size_t n) {
    std::size_t k = 0;
    while (k * k < n) ++k;
    return k;
}

/// True when sample i lies in cell (i % k, i / k) of the k x k grid (edges included,
/// as rounding may put a sample on one).
bool in_its_cell(const sample_offset& o, std::size_t i, std::size_t k) {
    const double s = static_cast<double>(k), cx = static_cast<double>(i % k), cy = static_cast<double>(i / k);
    return cx / s <= o.dx && o.dx <= (cx + 1) / s && cy / s <= o.dy && o.dy <= (cy + 1) / s;
}

}  // namespace

TEST_CASE("samplers: center puts every sample in the middle of the pixel", "[01][samplers]") {
    for (std::size_t n : {1u, 4u, 7u})
        for (const sample_offset& o : offsets_of("center", n, 99)) {
            CHECK(o.dx == 0.5);
            CHECK(o.dy == 0.5);
        }
}

TEST_CASE("samplers: grid with 4 samples is the thesis's 2 x 2 pattern - from the lower left", "[01][samplers]") {
    const auto o = offsets_of("grid", 4);
    const std::pair<double, double> expected[] = {{0.25, 0.25}, {0.75, 0.25}, {0.25, 0.75}, {0.75, 0.75}};
    for (std::size_t i = 0; i < 4; ++i) {
        CAPTURE(i);
        CHECK(o[i].dx == expected[i].first);
        CHECK(o[i].dy == expected[i].second);
    }
    CHECK(same(offsets_of("grid", 4, 1), offsets_of("grid", 4, 12345)));  // no randomness
}

TEST_CASE("samplers: grid with 5 samples takes the first 5 cells of a 3 x 3 grid", "[01][samplers]") {
    const auto o = offsets_of("grid", 5);
    const double third = 1.0 / 3;
    for (std::size_t i = 0; i < 5; ++i) {
        CAPTURE(i);
        CHECK(o[i].dx == Approx((static_cast<double>(i % 3) + 0.5) * third));
        CHECK(o[i].dy == Approx((static_cast<double>(i / 3) + 0.5) * third));
    }
    CHECK(offsets_of("grid", 1)[0].dx == 0.5);  // one sample: the 1 x 1 grid, the centre
}

TEST_CASE("samplers: jittered samples stay in their cells", "[01][samplers]") {
    for (std::size_t n : {1u, 2u, 4u, 7u, 9u, 16u, 64u}) {
        const std::size_t k = side(n);
        for (std::uint64_t seed = 0; seed < 200; ++seed) {
            const auto o = offsets_of("jittered", n, seed);
            for (std::size_t i = 0; i < n; ++i) {
                if (in_pixel(o[i]) && in_its_cell(o[i], i, k)) continue;
                CAPTURE(n, seed, i, o[i].dx, o[i].dy);
                FAIL_CHECK("sample " << i << " is not in cell (" << i % k << ", " << i / k << ") of the "
                                     << k << " x " << k << " grid");
            }
        }
    }
}

TEST_CASE("samplers: jittered samples repeat for the same seed and change with the seed", "[01][samplers]") {
    CHECK(same(offsets_of("jittered", 9, 42), offsets_of("jittered", 9, 42)));
    CHECK_FALSE(same(offsets_of("jittered", 9, 42), offsets_of("jittered", 9, 43)));
    // Jittered is not the grid: somewhere a sample is off its cell's centre.
    CHECK_FALSE(same(offsets_of("jittered", 9, 42), offsets_of("grid", 9)));
}

TEST_CASE("samplers: random offsets repeat for a seed - change with it and cover the pixel evenly", "[01][samplers]") {
    CHECK(same(offsets_of("random", 16, 7), offsets_of("random", 16, 7)));
    CHECK_FALSE(same(offsets_of("random", 16, 7), offsets_of("random", 16, 8)));
    const auto o = offsets_of("random", 4096, 2024);
    double sum_x = 0, sum_y = 0;
    int lower_left = 0;
    for (const sample_offset& s : o) {
        REQUIRE(in_pixel(s));
        sum_x += s.dx;
        sum_y += s.dy;
        lower_left += s.dx < 0.5 && s.dy < 0.5;
    }
    // Means of 4096 uniform numbers: 0.5 give or take 0.0045 (one standard deviation).
    CHECK(sum_x / 4096 == Approx(0.5).margin(0.03));
    CHECK(sum_y / 4096 == Approx(0.5).margin(0.03));
    CHECK(lower_left == Approx(1024).margin(150));  // a quarter of them in each quadrant
}

TEST_CASE("samplers: the seed alone decides the offsets (no state kept between calls)", "[01][samplers]") {
    for (std::string_view name : {"jittered", "random"}) {
        CAPTURE(name);
        const auto a = make_sampler(name), b = make_sampler(name);
        REQUIRE(a);
        REQUIRE(b);
        std::vector<sample_offset> first(8), second(8), other(8);
        a->offsets(first, 5);
        a->offsets(other, 6);  // another pixel in between
        a->offsets(second, 5);
        CHECK(same(first, second));
        b->offsets(second, 5);  // another object of the same pattern
        CHECK(same(first, second));
    }
}

TEST_CASE("samplers: one sampler used from four threads at once gives each thread the same offsets",
          "[01][samplers]") {
    const auto pattern = make_sampler("jittered");
    REQUIRE(pattern);
    std::vector<std::vector<sample_offset>> results(4, std::vector<sample_offset>(16));
    std::vector<std::exception_ptr> errors(4);
    {
        std::vector<std::jthread> threads;
        for (std::size_t t = 0; t < 4; ++t)
            threads.emplace_back([&, t] {
                try {
                    for (int repeat = 0; repeat < 200; ++repeat) pattern->offsets(results[t], 77);
                } catch (...) {
                    errors[t] = std::current_exception();
                }
            });
    }
    for (const auto& e : errors)
        if (e) std::rethrow_exception(e);
    for (std::size_t t = 1; t < 4; ++t) CHECK(same(results[0], results[t]));
    CHECK(same(results[0], offsets_of("jittered", 16, 77)));
}

TEST_CASE("samplers: every pattern fills every offset - each at least 0 and below 1 - for any count", "[01][samplers]") {
    for (std::string_view name : {"center", "grid", "jittered", "random"})
        for (std::size_t n = 1; n <= 30; ++n)
            for (std::uint64_t seed : {0ull, 1ull, 0xffffffffffffffffull}) {
                for (const sample_offset& o : offsets_of(name, n, seed)) {
                    if (in_pixel(o)) continue;
                    CAPTURE(name, n, seed, o.dx, o.dy);
                    FAIL_CHECK("an offset is outside [0, 1) or was not filled");
                }
            }
    // Grid cells are all different: n samples, n places.
    std::set<std::pair<double, double>> places;
    for (const sample_offset& o : offsets_of("grid", 10)) places.insert({o.dx, o.dy});
    CHECK(places.size() == 10);
}

TEST_CASE("samplers: zero samples fill nothing - and unknown names give nullptr", "[01][samplers]") {
    const auto pattern = make_sampler("jittered");
    REQUIRE(pattern);
    pattern->offsets(std::span<sample_offset>(), 3);  // must not crash
    CHECK(make_sampler("stratified") == nullptr);
    CHECK(make_sampler("Grid") == nullptr);  // names are case-sensitive
    CHECK(make_sampler("") == nullptr);
}
