// PFM files (www.pauldebevec.com/Research/HDR/PFM): linear float RGB (PF) or gray (Pf),
// the byte order given by the sign of the scale, rows bottom to top. Reader and writer.
#include "image_file.hh"

#include <bit>
#include <charconv>
#include <cmath>
#include <cstring>

namespace vl {

using namespace image_detail;

namespace {

std::endian pfm_byte_order(double scale) { return scale < 0 ? std::endian::little : std::endian::big; }

}  // namespace

image read_pfm(std::span<const std::uint8_t> bytes, const std::string& name) {
    if (bytes.size() < 2 || bytes[0] != 'P' || (bytes[1] != 'F' && bytes[1] != 'f'))
        throw image_error(name, "not a PFM file (it should start with PF or Pf)");
    const int channels = bytes[1] == 'F' ? 3 : 1;
    header_reader h(bytes, 2, name);
    const auto w = h.number("the width", max_image_dimension + std::int64_t{1});
    const auto ht = h.number("the height", max_image_dimension + std::int64_t{1});
    check_size(name, w, ht);
    const std::string_view text = h.token("the scale");
    double scale = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), scale);
    if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(scale) || scale == 0)
        throw image_error(name, "the scale '" + std::string(text) +
                                    "' is not a non-zero number (negative means little-endian, positive big-endian)");
    h.end_of_header("the scale");
    const std::size_t row_bytes = static_cast<std::size_t>(w) * channels * 4;
    const std::size_t needed = row_bytes * static_cast<std::size_t>(ht);
    if (h.left() < needed)
        throw image_error(name, "truncated: the header promises " + size_text(w, ht) + " pixels (" + std::to_string(needed) +
                                    " bytes of samples), but only " + std::to_string(h.left()) + " bytes follow");
    image img(static_cast<int>(w), static_cast<int>(ht), channels, sample_type::f32);
    const bool swap = pfm_byte_order(scale) != std::endian::native;
    for (int y = 0; y < img.height(); ++y) {
        // PFM stores the bottom row first.
        const std::uint8_t* in = h.here() + static_cast<std::size_t>(img.height() - 1 - y) * row_bytes;
        std::byte* out = img.row_data(y);
        std::memcpy(out, in, row_bytes);
        if (swap) {
            auto* words = reinterpret_cast<std::uint32_t*>(out);
            for (std::size_t i = 0; i < row_bytes / 4; ++i) words[i] = __builtin_bswap32(words[i]);
        }
    }
    return img;
}

void write_pfm(const std::filesystem::path& file, const image& img_in) {
    std::optional<image> keep;
    const image& img = as_needed(img_in, sample_type::f32, img_in.channels() <= 2 ? 1 : 3, keep);
    if (img.width() == 0 || img.height() == 0) throw image_error(file_name(file), "cannot write an empty image");
    output_file out(file);
    // The sign of the scale gives the byte order: we write the host's.
    const char* scale = std::endian::native == std::endian::little ? "-1.0" : "1.0";
    out.write(std::string(img.channels() == 3 ? "PF" : "Pf") + "\n" + std::to_string(img.width()) + " " +
              std::to_string(img.height()) + "\n" + scale + "\n");
    for (int y = img.height() - 1; y >= 0; --y) out.write(img.row_data(y), img.row_bytes());  // bottom row first
    out.finish();
}

}  // namespace vl
