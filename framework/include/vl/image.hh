#pragma once
/// \file
/// \brief Images in memory: vl::image, its sample types and size limits, and conversions
/// between sample types and channel counts.
///
/// Integer samples are sRGB-encoded, float samples are linear (vl::linear_to_srgb converts).
/// Image files (PNM, PNG, PFM) are read and written by the functions of image_io.hh.
/// Using an image wrongly (a size outside the limits, samples viewed as the wrong type, a
/// row outside the image) throws vl::usage_error.

#include "vl/error.hh"

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

namespace vl {

/// The largest width or height an image may have.
inline constexpr int max_image_dimension = 65535;
/// The most pixels an image may have (2^28: 256 megapixels, 1 GB as 8-bit RGBA).
inline constexpr std::int64_t max_image_pixels = std::int64_t{1} << 28;

/// How one sample (one channel of one pixel) is stored.
enum class sample_type {
    u8,   ///< 8-bit unsigned, sRGB-encoded, 0..255
    u16,  ///< 16-bit unsigned (host byte order), sRGB-encoded, 0..65535
    f32,  ///< 32-bit float, linear
};

/// Bytes in one sample of type t.
constexpr std::size_t sample_size(sample_type t) { return t == sample_type::u8 ? 1 : t == sample_type::u16 ? 2 : 4; }

/// \brief A rectangle of pixels in memory, rows **top to bottom** as files store them.
///
/// Channels are 1 (gray), 2 (gray, alpha), 3 (RGB) or 4 (RGBA), interleaved. The samples
/// are one contiguous array; samples<T>() and row<T>() view it with T = std::uint8_t,
/// std::uint16_t or float matching type() (anything else throws vl::usage_error).
class image {
public:
    /// An empty image (0 x 0).
    image() = default;
    /// A black image; throws vl::usage_error for sizes outside
    /// vl::max_image_dimension and vl::max_image_pixels or channels outside 1..4.
    image(int width, int height, int channels, sample_type type);

    int width() const { return width_; }          ///< Pixels per row.
    int height() const { return height_; }        ///< Rows.
    int channels() const { return channels_; }    ///< Samples per pixel, 1..4.
    sample_type type() const { return type_; }    ///< How samples are stored.
    /// Samples in one row (width * channels).
    std::size_t row_samples() const { return static_cast<std::size_t>(width_) * channels_; }
    /// Bytes in one row.
    std::size_t row_bytes() const { return row_samples() * sample_size(type_); }

    /// All samples, row after row.
    template <class T> std::span<T> samples() {
        check_type<T>();
        return {reinterpret_cast<T*>(bytes_.data()), row_samples() * height_};
    }
    /// All samples, row after row.
    template <class T> std::span<const T> samples() const {
        check_type<T>();
        return {reinterpret_cast<const T*>(bytes_.data()), row_samples() * height_};
    }
    /// Row y (0 is the top row).
    template <class T> std::span<T> row(int y) { return samples<T>().subspan(row_offset(y), row_samples()); }
    /// Row y (0 is the top row).
    template <class T> std::span<const T> row(int y) const {
        return samples<T>().subspan(row_offset(y), row_samples());
    }
    /// The raw bytes of row y, whatever the sample type (for fread and fwrite).
    std::byte* row_data(int y) { return bytes_.data() + row_offset(y) * sample_size(type_); }
    /// The raw bytes of row y.
    const std::byte* row_data(int y) const { return bytes_.data() + row_offset(y) * sample_size(type_); }

private:
    std::size_t row_offset(int y) const;
    // The bytes are allocated by operator new, so they are aligned for any sample type, and
    // viewing them as T is well defined for these implicit-lifetime types (C++20 [intro.object]).
    template <class T> void check_type() const {
        static_assert(std::is_same_v<T, std::uint8_t> || std::is_same_v<T, std::uint16_t> ||
                          std::is_same_v<T, float>,
                      "image samples are std::uint8_t, std::uint16_t or float");
        constexpr sample_type wanted = std::is_same_v<T, std::uint8_t>    ? sample_type::u8
                                       : std::is_same_v<T, std::uint16_t> ? sample_type::u16
                                                                           : sample_type::f32;
        if (wanted != type_) throw usage_error("vl::image: samples are not of the requested type");
    }

    int width_ = 0, height_ = 0, channels_ = 0;
    sample_type type_ = sample_type::u8;
    std::vector<std::byte> bytes_;
};

/// \name Conversions
///@{

/// The same image with other samples: between u8 and u16 by scaling, to and from f32
/// through the sRGB transfer function (vl::linear_to_srgb, vl::srgb_to_linear).
image convert_samples(const image& img, sample_type to);
/// The same image with other channels: gray from RGB by vl::luminance (on linear values),
/// RGB from gray by copying, alpha dropped or added opaque.
image convert_channels(const image& img, int channels);
///@}

}  // namespace vl
