#include "vl/heat_map.hh"

#include <algorithm>

namespace vl {

color heat_color(double fraction) {
    const double f = std::clamp(fraction, 0.0, 1.0) * 3;
    // Three equal steps: black -> red, red -> yellow, yellow -> white.
    return {std::min(f, 1.0), std::clamp(f - 1, 0.0, 1.0), std::clamp(f - 2, 0.0, 1.0)};
}

std::uint32_t draw_heat_map(std::span<const std::uint32_t> tests, int width, int height, vfb& out) {
    const std::uint32_t most = tests.empty() ? 0 : *std::max_element(tests.begin(), tests.end());
    const double scale = most == 0 ? 0 : 1.0 / most;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            out.put_pixel(x, y, vfb_pixel(heat_color(tests[static_cast<std::size_t>(x + y * width)] * scale)));
    for (int y = 0; y < height; ++y) {
        const color c = heat_color(height > 1 ? static_cast<double>(y) / (height - 1) : 1);
        for (int x = width; x < width + heat_scale_gap; ++x) out.put_pixel(x, y, vfb_pixel(color(0.2, 0.2, 0.2)));
        for (int x = width + heat_scale_gap; x < width + heat_scale_gap + heat_scale_width; ++x)
            out.put_pixel(x, y, vfb_pixel(c));
    }
    return most;
}

}  // namespace vl
