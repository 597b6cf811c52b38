// vl::image itself (its size checks and rows) and the conversions between sample types
// and channel counts (image.hh).
#include "vl/image.hh"

#include "vl/pixel.hh"

#include <algorithm>
#include <cmath>

namespace vl {

image::image(int width, int height, int channels, sample_type type)
    : width_(width), height_(height), channels_(channels), type_(type) {
    if (width < 0 || height < 0 || width > max_image_dimension || height > max_image_dimension ||
        std::int64_t{width} * height > max_image_pixels)
        throw usage_error("vl::image: size " + std::to_string(width) + " x " +
                          std::to_string(height) + " is outside what an image may be");
    if (channels < 1 || channels > 4)
        throw usage_error("vl::image: channels must be 1 to 4, not " + std::to_string(channels));
    bytes_.resize(row_bytes() * static_cast<std::size_t>(height));
}

std::size_t image::row_offset(int y) const {
    if (y < 0 || y >= height_)
        throw usage_error("vl::image: row " + std::to_string(y) + " is outside 0.." +
                          std::to_string(height_ - 1));
    return static_cast<std::size_t>(y) * row_samples();
}

image convert_samples(const image& img, sample_type to) {
    if (img.type() == to) return img;
    image out(img.width(), img.height(), img.channels(), to);
    const std::size_t n = img.row_samples() * static_cast<std::size_t>(img.height());
    const int c = img.channels();
    // Alpha (the last of 2 or 4 channels) is linear coverage, not sRGB-encoded.
    const auto is_alpha = [c](std::size_t i) { return (c == 2 || c == 4) && i % c == static_cast<std::size_t>(c - 1); };

    if (img.type() == sample_type::u8 && to == sample_type::u16) {
        const auto s = img.samples<std::uint8_t>();
        const auto d = out.samples<std::uint16_t>();
        for (std::size_t i = 0; i < n; ++i) d[i] = static_cast<std::uint16_t>(s[i] * 257);  // 255 -> 65535
    } else if (img.type() == sample_type::u16 && to == sample_type::u8) {
        const auto s = img.samples<std::uint16_t>();
        const auto d = out.samples<std::uint8_t>();
        for (std::size_t i = 0; i < n; ++i) d[i] = static_cast<std::uint8_t>((s[i] + 128) / 257);
    } else if (img.type() == sample_type::u8) {  // to linear float
        const auto s = img.samples<std::uint8_t>();
        const auto d = out.samples<float>();
        for (std::size_t i = 0; i < n; ++i) d[i] = is_alpha(i) ? s[i] / 255.0f : srgb8_to_linear(s[i]);
    } else if (img.type() == sample_type::u16) {  // to linear float
        const auto s = img.samples<std::uint16_t>();
        const auto d = out.samples<float>();
        for (std::size_t i = 0; i < n; ++i) {
            const double v = s[i] / 65535.0;
            d[i] = static_cast<float>(is_alpha(i) ? v : srgb_to_linear(v));
        }
    } else if (to == sample_type::u8) {  // from linear float
        const auto s = img.samples<float>();
        const auto d = out.samples<std::uint8_t>();
        for (std::size_t i = 0; i < n; ++i)
            d[i] = is_alpha(i) ? static_cast<std::uint8_t>(std::lround(std::clamp(s[i], 0.0f, 1.0f) * 255)) : linear_to_srgb8(s[i]);
    } else {  // from linear float to u16
        const auto s = img.samples<float>();
        const auto d = out.samples<std::uint16_t>();
        for (std::size_t i = 0; i < n; ++i) {
            const double e = is_alpha(i) ? std::clamp(static_cast<double>(s[i]), 0.0, 1.0) : linear_to_srgb(s[i]);
            d[i] = static_cast<std::uint16_t>(std::lround(e * 65535));
        }
    }
    return out;
}

image convert_channels(const image& img, int channels) {
    if (img.channels() == channels) return img;
    if (channels < 1 || channels > 4) throw usage_error("vl::convert_channels: channels must be 1 to 4");
    // Work in linear float, where luminance is defined, and go back to the original type.
    const image lin = convert_samples(img, sample_type::f32);
    image out(img.width(), img.height(), channels, sample_type::f32);
    const int ci = img.channels();
    const bool in_alpha = ci == 2 || ci == 4, out_alpha = channels == 2 || channels == 4;
    const bool in_gray = ci <= 2, out_gray = channels <= 2;
    const auto src = lin.samples<float>();
    auto dst = out.samples<float>();
    const std::size_t pixels = static_cast<std::size_t>(img.width()) * img.height();
    for (std::size_t p = 0; p < pixels; ++p) {
        const float* s = &src[p * ci];
        float* d = &dst[p * channels];
        const float r = s[0], g = in_gray ? s[0] : s[1], b = in_gray ? s[0] : s[2];
        const float a = in_alpha ? s[ci - 1] : 1.0f;
        if (out_gray) {
            d[0] = static_cast<float>(in_gray ? r : luminance(r, g, b));
        } else {
            d[0] = r; d[1] = g; d[2] = b;
        }
        if (out_alpha) d[channels - 1] = a;
    }
    return convert_samples(out, img.type());
}

}  // namespace vl
