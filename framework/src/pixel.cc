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

// The unit interval cut into `buckets` equal pieces; first_code[b] is the number of
// boundaries below b / buckets, the code where a search for x in that piece starts. A
// piece is narrower than the gap between any two boundaries but the first few (1 / 4096
// against 3e-4 near black, where the curve is straight, and 0.009 near white), so the
// search then takes a step or two where a binary search over all 255 took eight, each a
// branch the processor cannot predict.
constexpr int buckets = 4096;
const std::array<std::uint8_t, buckets> first_code = [] {
    std::array<std::uint8_t, buckets> t{};
    for (int b = 0; b < buckets; ++b) {
        const double start = static_cast<double>(b) / buckets;
        t[static_cast<std::size_t>(b)] =
            static_cast<std::uint8_t>(std::lower_bound(boundary.begin(), boundary.end(), start) - boundary.begin());
    }
    return t;
}();

}  // namespace

std::uint8_t linear_to_srgb8(double linear) {
    if (!(linear > 0)) return 0;  // also NaN
    if (!(linear < 1)) return 255;
    // linear * buckets is exact (a power of two), so its floor is the piece x lies in and
    // first_code counts boundaries at or below x; the loop counts the rest.
    std::size_t code = first_code[static_cast<std::size_t>(linear * buckets)];
    while (code < boundary.size() && boundary[code] <= linear) ++code;
    return static_cast<std::uint8_t>(code);
}

float srgb8_to_linear(std::uint8_t code) { return code_to_linear[code]; }

}  // namespace vl
