#pragma once
/// \file
/// \brief Image files: PNM (PBM, PGM, PPM), PNG, PFM, read into and written from a
/// vl::image (image.hh).
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
/// Every problem with a file throws vl::image_error (a vl::file_error) with the message
/// `FILE: what is wrong`; a reader never trusts a size in a header before checking that the
/// file can hold it.

#include "vl/error.hh"
#include "vl/image.hh"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>
#include <string>

namespace vl {

/// \brief Any problem reading or writing an image file; what() is `FILE: what is wrong`.
class image_error : public file_error {
public:
    /// `file` names the file (or the in-memory source) and `problem` says what is wrong.
    image_error(const std::string& file, const std::string& problem) : file_error(file + ": " + problem) {}
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

}  // namespace vl
