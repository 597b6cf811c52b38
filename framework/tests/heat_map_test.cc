// The heat map's scale: linear and logarithmic fractions, their inverse for the legend's
// tick labels, and the picture draw_heat_map makes.
#include "vl/heat_map.hh"

#include "vl/catch.hh"

#include <cmath>
#include <vector>

using namespace vl;

TEST_CASE("heat_fraction is count / most on the linear scale") {
    CHECK(heat_fraction(0, 20, false) == 0);
    CHECK(heat_fraction(5, 20, false) == Approx(0.25));
    CHECK(heat_fraction(20, 20, false) == 1);
    CHECK(heat_fraction(30, 20, false) == 1);  // above the largest: the top of the scale
    CHECK(heat_fraction(7, 0, false) == 0);    // nothing counted: all black
}

TEST_CASE("heat_fraction is log(1 + count) / log(1 + most) on the log scale") {
    CHECK(heat_fraction(0, 1000, true) == 0);
    CHECK(heat_fraction(1000, 1000, true) == 1);
    CHECK(heat_fraction(9, 999, true) == Approx(std::log(10.0) / std::log(1000.0)));
    CHECK(heat_fraction(9, 999, true) == Approx(1.0 / 3));
    // The log scale lifts the cheap pixels: 10 of 1000 tests is 1 % linearly, a third in log.
    CHECK(heat_fraction(10, 1000, true) > 30 * heat_fraction(10, 1000, false));
    CHECK(heat_fraction(3, 0, true) == 0);
}

TEST_CASE("heat_count inverts heat_fraction for the legend's ticks") {
    for (const bool log_scale : {false, true})
        for (const std::uint32_t c : {0u, 1u, 9u, 99u, 250u, 999u})
            CHECK(heat_count(heat_fraction(c, 999, log_scale), 999, log_scale) == c);
    CHECK(heat_count(0.5, 20, false) == 10);
    CHECK(heat_count(1.0 / 3, 999, true) == 9);
    CHECK(heat_count(2, 20, false) == 20);  // clamped
    CHECK(heat_count(-1, 20, true) == 0);
}

TEST_CASE("draw_heat_map scales from 0 tests (black) to the most (white), log on request") {
    const std::vector<std::uint32_t> tests{0, 9, 99, 999};
    for (const bool log_scale : {false, true}) {
        vfb out(4 + heat_scale_gap + heat_scale_width - 1, 0, "rgbf");
        CHECK(draw_heat_map(tests, 4, 1, out, log_scale) == 999);
        for (int x = 0; x < 4; ++x) {
            const color want = heat_color(heat_fraction(tests[static_cast<std::size_t>(x)], 999, log_scale));
            CHECK(out.get_pixel(x, 0).r() == Approx(want.r));
            CHECK(out.get_pixel(x, 0).g() == Approx(want.g));
        }
        CHECK(out.get_pixel(0, 0).r() == 0);
        CHECK(out.get_pixel(3, 0).b() == 1);
    }
}
