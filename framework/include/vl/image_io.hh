#pragma once
/// \file
/// \brief Images in memory (vl::image) and image files: PNM (PBM, PGM, PPM), PNG, PFM.
///
/// This is the bulk path the thesis's `vfb::load` and `vfb::save` lacked (its "known
/// problem" was reading and writing one pixel at a time): files are read and written a
/// whole buffer or row at a time. vl::vfb converts between its pixels and a vl::image.
///
/// | format | read | write | samples |
/// |---|---|---|---|
/// | PBM `P4` / `P1` | yes / yes | `P4` (`.pbm`) | 1 bit, read as 8-bit gray 0 or 255 |
/// | PGM `P5` / `P2` | yes / yes | `P5` (`.pgm`) | 8 or 16 bit gray |
/// | PPM `P6` / `P3` | yes / yes | `P6` (`.ppm`, `.pnm`) | 8 or 16 bit RGB |
/// | PNG (libpng) | 1-16 bit gray, gray+alpha, palette, RGB, RGBA | 8 or 16 bit, sRGB chunk | |
/// | PFM `PF` / `Pf` | yes | yes (`.pfm`) | linear float RGB / gray |
///
/// Integer samples are sRGB-encoded, float samples are linear (vl::linear_to_srgb converts).
/// Readers pick the format by the file's first bytes, writers by the file name's extension.
/// Every problem with a file throws vl::image_error with the message `FILE: what is wrong`;
/// a reader never trusts a size in a header before checking that the file can hold it.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace vl {

/// The largest width or height an image may have.
inline constexpr int max_image_dimension = 65535;
/// The most pixels an image may have (2^28: 256 megapixels, 1 GB as 8-bit RGBA).
inline constexpr std::int64_t max_image_pixels = std::int64_t{1} << 28;

/// \brief Any problem reading or writing an image file; what() is `FILE: what is wrong`.
class image_error : public std::runtime_error {
public:
    /// `file` names the file (or the in-memory source) and `problem` says what is wrong.
    image_error(const std::string& file, const std::string& problem)
        : std::runtime_error(file + ": " + problem) {}
};

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
/// std::uint16_t or float matching type() (anything else throws std::logic_error).
class image {
public:
    /// An empty image (0 x 0).
    image() = default;
    /// A black image; throws std::invalid_argument for sizes outside
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
        if (wanted != type_) throw std::logic_error("vl::image: samples are not of the requested type");
    }

    int width_ = 0, height_ = 0, channels_ = 0;
    sample_type type_ = sample_type::u8;
    std::vector<std::byte> bytes_;
};

/// \name Reading and writing whole files
///@{

/// Reads a PNM, PNG or PFM file, recognised by its first bytes.
image read_image(const std::filesystem::path& file);
/// Reads an image from bytes already in memory; `name` is used in error messages.
image read_image(std::span<const std::uint8_t> bytes, const std::string& name);
/// Writes `img` in the format named by the file's extension: `.ppm`, `.pgm`, `.pbm`,
/// `.pnm`, `.png` or `.pfm`. Channels the format cannot hold are dropped (alpha in PNM and
/// PFM) or combined (RGB to gray for PGM and PBM, by vl::luminance); integer samples go to
/// PFM through vl::srgb_to_linear and float samples to PNM or PNG through
/// vl::linear_to_srgb, so what the file shows is what the image meant.
void write_image(const std::filesystem::path& file, const image& img);
///@}

/// \name One format each (the reader of a given format, for tests and fuzzing)
///@{

/// Reads PBM, PGM or PPM (`P1` to `P6`), with `#` comments in the header.
image read_pnm(std::span<const std::uint8_t> bytes, const std::string& name);
/// Reads PNG through libpng: 8- or 16-bit result (less is expanded to 8), palettes and
/// transparency expanded to RGB(A).
image read_png(std::span<const std::uint8_t> bytes, const std::string& name);
/// Reads PFM (`PF` RGB or `Pf` gray; byte order from the sign of the scale; rows bottom
/// to top in the file, top to bottom in the image).
image read_pfm(std::span<const std::uint8_t> bytes, const std::string& name);
/// Writes binary PNM: `P4` if `pbm`, else `P5` (1 channel) or `P6` (3); 8 or 16 bits.
void write_pnm(const std::filesystem::path& file, const image& img, bool pbm = false);
/// Writes PNG (8 or 16 bits, gray / gray+alpha / RGB / RGBA) with an sRGB chunk.
void write_png(const std::filesystem::path& file, const image& img);
/// Writes little-endian PFM (`PF` or `Pf`) from a 1- or 3-channel float image.
void write_pfm(const std::filesystem::path& file, const image& img);
///@}

/// \brief Writes a binary 8-bit PGM (1 channel) or PPM (3 channels) one row at a time, top
/// row first.
///
/// The bulk path for pixels that are not in a vl::image: vl::vfb::save streams its rows
/// through one of these, so saving never copies the whole buffer. Throws vl::image_error
/// if the file cannot be written.
class pnm_row_writer {
public:
    /// Creates the file and writes the header.
    pnm_row_writer(const std::filesystem::path& file, int width, int height, int channels);
    /// Closes the file (if finish() was not called, the file may be incomplete).
    ~pnm_row_writer();
    pnm_row_writer(const pnm_row_writer&) = delete;             ///< Not copyable.
    pnm_row_writer& operator=(const pnm_row_writer&) = delete;  ///< Not copyable.
    /// Writes the next row: width * channels sRGB-encoded samples.
    void write_row(std::span<const std::uint8_t> row);
    /// Checks that every row was written and closes the file.
    void finish();

private:
    class file;
    std::unique_ptr<file> out_;
    std::size_t row_bytes_;
    int rows_left_;
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
