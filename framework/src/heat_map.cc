#include "vl/heat_map.hh"

#include <algorithm>
#include <cmath>

namespace vl {

color heat_color(double fraction) {
    const double f = std::clamp(fraction, 0.0, 1.0) * 3;
    // Three equal steps: black -> red, red -> yellow, yellow -> white.
    return {std::min(f, 1.0), std::clamp(f - 1, 0.0, 1.0), std::clamp(f - 2, 0.0, 1.0)};
}

double heat_fraction(std::uint32_t count, std::uint32_t most, bool log_scale) {
    if (most == 0) return 0;
    const std::uint32_t c = std::min(count, most);
    return log_scale ? std::log1p(static_cast<double>(c)) / std::log1p(static_cast<double>(most))
                     : static_cast<double>(c) / most;
}

std::uint32_t heat_count(double fraction, std::uint32_t most, bool log_scale) {
    const double f = std::clamp(fraction, 0.0, 1.0);
    const double c = log_scale ? std::expm1(f * std::log1p(static_cast<double>(most))) : f * most;
    return std::min(most, static_cast<std::uint32_t>(std::lround(c)));
}

std::uint32_t draw_heat_map(std::span<const std::uint32_t> tests, int width, int height, vfb& out, bool log_scale) {
    const std::uint32_t most = tests.empty() ? 0 : *std::max_element(tests.begin(), tests.end());
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            out.put_pixel(x, y, vfb_pixel(heat_color(
                                    heat_fraction(tests[static_cast<std::size_t>(x + y * width)], most, log_scale))));
    for (int y = 0; y < height; ++y) {
        const color c = heat_color(height > 1 ? static_cast<double>(y) / (height - 1) : 1);
        for (int x = width; x < width + heat_scale_gap; ++x) out.put_pixel(x, y, vfb_pixel(color(0.2, 0.2, 0.2)));
        for (int x = width + heat_scale_gap; x < width + heat_scale_gap + heat_scale_width; ++x)
            out.put_pixel(x, y, vfb_pixel(c));
    }
    return most;
}

}  // namespace vl
