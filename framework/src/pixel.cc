// The sRGB transfer function (IEC 61966-2-1:1999) and its 8-bit tables.
#include "vl/pixel.hh"

#include <algorithm>
#include <array>
#include <cmath>

namespace vl {

double linear_to_srgb(double linear) {
    const double x = std::clamp(linear, 0.0, 1.0);  // NaN falls through clamp unchanged...
    if (!(x > 0.0031308)) return x > 0 ? 12.92 * x : 0.0;  // ...and ends here as 0
    return 1.055 * std::pow(x, 1 / 2.4) - 0.055;
}

double srgb_to_linear(double encoded) {
    const double v = std::clamp(encoded, 0.0, 1.0);
    if (!(v > 0.04045)) return v > 0 ? v / 12.92 : 0.0;
    return std::pow((v + 0.055) / 1.055, 2.4);
}

namespace {

// code_to_linear[k] is the linear value of sRGB code k.
const std::array<float, 256> code_to_linear = [] {
    std::array<float, 256> t{};
    for (int k = 0; k < 256; ++k) t[k] = static_cast<float>(srgb_to_linear(k / 255.0));
    return t;
}();

// boundary[k] is the linear value halfway (in code space) between codes k and k + 1, so
// the nearest code for x is the number of boundaries that x reaches.
const std::array<double, 255> boundary = [] {
    std::array<double, 255> t{};
    for (int k = 0; k < 255; ++k) t[k] = srgb_to_linear((k + 0.5) / 255.0);
    return t;
}();

}  // namespace

std::uint8_t linear_to_srgb8(double linear) {
    if (!(linear > 0)) return 0;  // also NaN
    const auto it = std::upper_bound(boundary.begin(), boundary.end(), linear);
    return static_cast<std::uint8_t>(it - boundary.begin());
}

float srgb8_to_linear(std::uint8_t code) { return code_to_linear[code]; }

}  // namespace vl
