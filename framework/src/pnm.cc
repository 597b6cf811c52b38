// PNM files (netpbm.sourceforge.net/doc/pnm.html): the reader of PBM, PGM and PPM, plain
// (P1-P3) and binary (P4-P6), the writer of binary PNM, and pnm_row_writer.
//
// The reader checks each number the header gives against what it takes *and* against the
// bytes the file really has, and only then allocates (see image_file.hh).
#include "image_file.hh"

#include <algorithm>
#include <bit>
#include <cstring>

namespace vl {

using namespace image_detail;

namespace {

std::uint16_t swap_bytes(std::uint16_t v) { return static_cast<std::uint16_t>((v >> 8) | (v << 8)); }

// Scales a sample from 0..maxval to 0..full (255 or 65535), rounding.
template <class T>
T rescale(std::uint32_t v, std::uint32_t maxval, std::uint32_t full) {
    return static_cast<T>((std::uint64_t{v} * full + maxval / 2) / maxval);
}

void check_sample(const std::string& name, std::uint32_t v, std::uint32_t maxval, std::size_t index) {
    if (v > maxval)
        throw image_error(name, "sample " + std::to_string(index) + " is " + std::to_string(v) +
                                    ", more than the maxval " + std::to_string(maxval));
}

image read_pnm_ascii(header_reader& h, int kind, int w, int ht, std::uint32_t maxval, const std::string& name) {
    const int channels = kind == 3 ? 3 : 1;
    const std::size_t count = static_cast<std::size_t>(w) * ht * channels;
    // Each sample takes at least one byte of text: a cheap truncation test before allocating.
    if (count > h.left())
        throw image_error(name, "truncated: the header promises " + size_text(w, ht) + " pixels, but only " +
                                    std::to_string(h.left()) + " bytes follow");
    image img(w, ht, channels, maxval > 255 ? sample_type::u16 : sample_type::u8);
    const auto truncated = [&](std::size_t found) {
        return image_error(name, "truncated: expected " + std::to_string(count) + " samples, found " + std::to_string(found));
    };
    if (kind == 1) {
        // Plain PBM digits need no separating space: "0101" is four pixels. 1 is black.
        const auto s = img.samples<std::uint8_t>();
        for (std::size_t i = 0; i < count; ++i) {
            h.skip_space_and_comments();
            if (h.left() == 0) throw truncated(i);
            const std::uint8_t c = *h.here();
            if (c != '0' && c != '1')
                throw image_error(name, "pixel " + std::to_string(i) + " is " + header_reader::describe(c) + ", not 0 or 1");
            h.advance();
            s[i] = c == '1' ? 0 : 255;
        }
        return img;
    }
    const std::uint32_t full = maxval > 255 ? 65535 : 255;
    for (std::size_t i = 0; i < count; ++i) {
        h.skip_space_and_comments();
        if (h.left() == 0) throw truncated(i);
        const auto v = static_cast<std::uint32_t>(h.number("a sample", 65535));
        check_sample(name, v, maxval, i);
        if (full == 255)
            img.samples<std::uint8_t>()[i] = rescale<std::uint8_t>(v, maxval, full);
        else
            img.samples<std::uint16_t>()[i] = rescale<std::uint16_t>(v, maxval, full);
    }
    return img;
}

image read_pnm_binary(header_reader& h, int kind, int w, int ht, std::uint32_t maxval, const std::string& name) {
    const int channels = kind == 6 ? 3 : 1;
    const std::size_t sample_bytes = maxval > 255 ? 2 : 1;
    const std::size_t row_bytes = kind == 4 ? (static_cast<std::size_t>(w) + 7) / 8
                                            : static_cast<std::size_t>(w) * channels * sample_bytes;
    const std::size_t needed = row_bytes * static_cast<std::size_t>(ht);
    if (h.left() < needed)
        throw image_error(name, "truncated: the header promises " + size_text(w, ht) + " pixels (" +
                                    std::to_string(needed) + " bytes of samples), but only " +
                                    std::to_string(h.left()) + " bytes follow");
    const std::uint8_t* in = h.here();
    image img(w, ht, channels, maxval > 255 ? sample_type::u16 : sample_type::u8);

    if (kind == 4) {  // one bit a pixel, rows padded to a byte, 1 is black
        for (int y = 0; y < ht; ++y) {
            const std::uint8_t* bits = in + y * row_bytes;
            auto out = img.row<std::uint8_t>(y);
            for (int x = 0; x < w; ++x) out[x] = (bits[x >> 3] >> (7 - (x & 7))) & 1 ? 0 : 255;
        }
        return img;
    }
    if (maxval == 255) {  // the common case: the file's samples are the image's, one copy
        std::memcpy(img.row_data(0), in, needed);
        return img;
    }
    const std::size_t count = needed / sample_bytes;
    if (sample_bytes == 1) {
        auto s = img.samples<std::uint8_t>();
        for (std::size_t i = 0; i < count; ++i) {
            check_sample(name, in[i], maxval, i);
            s[i] = rescale<std::uint8_t>(in[i], maxval, 255);
        }
    } else {
        auto s = img.samples<std::uint16_t>();
        for (std::size_t i = 0; i < count; ++i) {
            const std::uint32_t v = (std::uint32_t{in[2 * i]} << 8) | in[2 * i + 1];  // big-endian
            check_sample(name, v, maxval, i);
            s[i] = maxval == 65535 ? static_cast<std::uint16_t>(v) : rescale<std::uint16_t>(v, maxval, 65535);
        }
    }
    return img;
}

}  // namespace

image read_pnm(std::span<const std::uint8_t> bytes, const std::string& name) {
    if (bytes.size() < 2 || bytes[0] != 'P' || bytes[1] < '1' || bytes[1] > '6')
        throw image_error(name, "not a PNM file (it should start with P1 to P6)");
    const int kind = bytes[1] - '0';
    header_reader h(bytes, 2, name);
    if (h.left() > 0 && !pnm_space(*h.here()) && *h.here() != '#')
        throw image_error(name, "not a PNM file (P" + std::to_string(kind) + " is followed by " +
                                    header_reader::describe(*h.here()) + ")");
    const auto w = h.number("the width", max_image_dimension + std::int64_t{1});
    const auto ht = h.number("the height", max_image_dimension + std::int64_t{1});
    check_size(name, w, ht);
    std::uint32_t maxval = 1;
    if (kind != 1 && kind != 4) {
        const auto m = h.number("the maxval", 65536);
        if (m < 1 || m > 65535)
            throw image_error(name, "the maxval is " + std::to_string(m) + "; it must be 1 to 65535");
        maxval = static_cast<std::uint32_t>(m);
    }
    if (kind <= 3) return read_pnm_ascii(h, kind, static_cast<int>(w), static_cast<int>(ht), maxval, name);
    h.end_of_header(kind == 4 ? "the height" : "the maxval");
    return read_pnm_binary(h, kind, static_cast<int>(w), static_cast<int>(ht), maxval, name);
}

void write_pnm(const std::filesystem::path& file, const image& img_in, bool pbm) {
    const int want = pbm || img_in.channels() <= 2 ? 1 : 3;
    const sample_type type = pbm || img_in.type() == sample_type::f32 ? sample_type::u8 : img_in.type();
    std::optional<image> keep;
    const image& img = as_needed(img_in, type, want, keep);
    if (img.width() == 0 || img.height() == 0) throw image_error(file_name(file), "cannot write an empty image");

    output_file out(file);
    const char* magic = pbm ? "P4" : want == 1 ? "P5" : "P6";
    std::string header = std::string(magic) + "\n" + std::to_string(img.width()) + " " + std::to_string(img.height()) + "\n";
    if (!pbm) header += img.type() == sample_type::u16 ? "65535\n" : "255\n";
    out.write(header);

    if (pbm) {  // 1 is black; an 8-bit gray below the middle is black
        std::vector<std::uint8_t> packed((static_cast<std::size_t>(img.width()) + 7) / 8);
        for (int y = 0; y < img.height(); ++y) {
            std::fill(packed.begin(), packed.end(), 0);
            const auto row = img.row<std::uint8_t>(y);
            for (int x = 0; x < img.width(); ++x)
                if (row[x] < 128) packed[x >> 3] |= static_cast<std::uint8_t>(0x80 >> (x & 7));
            out.write(packed.data(), packed.size());
        }
    } else if (img.type() == sample_type::u8) {
        out.write(img.row_data(0), img.row_bytes() * img.height());  // rows are contiguous, top first
    } else {  // 16-bit samples are big-endian in the file
        std::vector<std::uint16_t> be(img.row_samples());
        for (int y = 0; y < img.height(); ++y) {
            const auto row = img.row<std::uint16_t>(y);
            for (std::size_t i = 0; i < be.size(); ++i)
                be[i] = std::endian::native == std::endian::big ? row[i] : swap_bytes(row[i]);
            out.write(be.data(), be.size() * 2);
        }
    }
    out.finish();
}

class pnm_row_writer::file : public image_detail::output_file {
    using output_file::output_file;
};

pnm_row_writer::pnm_row_writer(const std::filesystem::path& file_path, int width, int height, int channels)
    : row_bytes_(static_cast<std::size_t>(width) * static_cast<std::size_t>(channels)), rows_left_(height) {
    if (width < 1 || height < 1 || width > max_image_dimension || height > max_image_dimension || (channels != 1 && channels != 3))
        throw image_error(file_name(file_path), "cannot write a " + size_text(width, height) + " PNM with " +
                                                    std::to_string(channels) + " channels");
    out_ = std::make_unique<file>(file_path);
    out_->write(std::string(channels == 1 ? "P5" : "P6") + "\n" + std::to_string(width) + " " +
                std::to_string(height) + "\n255\n");
}

pnm_row_writer::~pnm_row_writer() = default;

void pnm_row_writer::write_row(std::span<const std::uint8_t> row) {
    if (row.size() != row_bytes_ || rows_left_ <= 0)
        throw usage_error("pnm_row_writer: a row of the wrong size, or one row too many");
    out_->write(row.data(), row.size());
    --rows_left_;
}

void pnm_row_writer::finish() {
    if (rows_left_ != 0) throw image_error(out_->name(), std::to_string(rows_left_) + " rows were never written");
    out_->finish();
}

}  // namespace vl
