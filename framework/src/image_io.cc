// Image files: PNM (netpbm.sourceforge.net/doc/pnm.html), PFM
// (www.pauldebevec.com/Research/HDR/PFM), and PNG through libpng 1.6 (libpng-manual.txt).
//
// Every reader follows the same rule: read the header, check each number it gives against
// what this reader takes *and* against the bytes the file really has, and only then
// allocate. A 20-byte file claiming to be 60000 x 60000 is an error message, not a
// 10 GB allocation.
#include "vl/image_io.hh"

#include "vl/pixel.hh"

#include <fcntl.h>
#include <png.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <bit>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <memory>
#include <optional>

namespace vl {

// ---------------------------------------------------------------------------------------
// vl::image

image::image(int width, int height, int channels, sample_type type)
    : width_(width), height_(height), channels_(channels), type_(type) {
    if (width < 0 || height < 0 || width > max_image_dimension || height > max_image_dimension ||
        std::int64_t{width} * height > max_image_pixels)
        throw std::invalid_argument("vl::image: size " + std::to_string(width) + " x " +
                                    std::to_string(height) + " is outside what an image may be");
    if (channels < 1 || channels > 4)
        throw std::invalid_argument("vl::image: channels must be 1 to 4, not " + std::to_string(channels));
    bytes_.resize(row_bytes() * static_cast<std::size_t>(height));
}

std::size_t image::row_offset(int y) const {
    if (y < 0 || y >= height_)
        throw std::out_of_range("vl::image: row " + std::to_string(y) + " is outside 0.." +
                                std::to_string(height_ - 1));
    return static_cast<std::size_t>(y) * row_samples();
}

namespace {

// ---------------------------------------------------------------------------------------
// Files: read whole, write whole rows.

struct file_closer {
    void operator()(std::FILE* f) const { std::fclose(f); }
};
using file_ptr = std::unique_ptr<std::FILE, file_closer>;

std::string file_name(const std::filesystem::path& file) { return file.string(); }

// A whole file's bytes. A regular file is mapped into memory (POSIX mmap), which costs no
// copy: reading a 50 MB PPM touches its bytes once, on the way into the image. Anything
// else (a pipe, /dev/stdin) is read in large chunks.
class file_bytes {
public:
    explicit file_bytes(const std::filesystem::path& file) : name_(file_name(file)) {
        std::error_code ec;
        if (std::filesystem::is_directory(file, ec)) throw image_error(name_, "is a directory, not an image file");
        const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
        if (fd < 0) throw image_error(name_, std::string("cannot open: ") + std::strerror(errno));
        struct stat st {};
        if (::fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && st.st_size > 0) {
            void* p = ::mmap(nullptr, static_cast<std::size_t>(st.st_size), PROT_READ, MAP_PRIVATE | MAP_POPULATE, fd, 0);
            if (p != MAP_FAILED) {
                mapped_ = {static_cast<const std::uint8_t*>(p), static_cast<std::size_t>(st.st_size)};
                ::close(fd);
                return;
            }
        }
        read_chunks(fd);
        ::close(fd);
    }
    ~file_bytes() {
        if (!mapped_.empty()) ::munmap(const_cast<std::uint8_t*>(mapped_.data()), mapped_.size());
    }
    file_bytes(const file_bytes&) = delete;
    file_bytes& operator=(const file_bytes&) = delete;

    std::span<const std::uint8_t> bytes() const { return mapped_.empty() ? std::span<const std::uint8_t>(read_) : mapped_; }

private:
    void read_chunks(int fd) {
        std::size_t used = 0;
        for (std::size_t chunk = std::size_t{1} << 20;; chunk = std::min(chunk * 2, std::size_t{1} << 28)) {
            read_.resize(used + chunk);
            const ::ssize_t got = ::read(fd, read_.data() + used, chunk);
            if (got < 0) {
                if (errno == EINTR) continue;
                throw image_error(name_, std::string("read failed: ") + std::strerror(errno));
            }
            if (got == 0) break;
            used += static_cast<std::size_t>(got);
        }
        read_.resize(used);
    }

    std::string name_;
    std::span<const std::uint8_t> mapped_;
    std::vector<std::uint8_t> read_;
};

// Opens for writing; closes on destruction. finish() reports a failed final flush.
class output_file {
public:
    explicit output_file(const std::filesystem::path& file) : name_(file_name(file)), f_(std::fopen(file.c_str(), "wb")) {
        if (!f_) throw image_error(name_, std::string("cannot create: ") + std::strerror(errno));
        // A larger buffer turns row-sized writes into fewer system calls; 64 KB stays below
        // malloc's mmap threshold, so it is reused memory, not fresh pages every time.
        std::setvbuf(f_.get(), nullptr, _IOFBF, std::size_t{1} << 16);
    }
    std::FILE* get() const { return f_.get(); }
    const std::string& name() const { return name_; }
    void write(const void* data, std::size_t n) {
        if (n != 0 && std::fwrite(data, 1, n, f_.get()) != n) fail();
    }
    void write(std::string_view s) { write(s.data(), s.size()); }
    void finish() {
        if (std::fclose(f_.release()) != 0) fail();
    }
    [[noreturn]] void fail() const {
        throw image_error(name_, std::string("write failed: ") + std::strerror(errno) + " (is the disk full?)");
    }

private:
    std::string name_;
    file_ptr f_;
};

std::string size_text(std::int64_t w, std::int64_t h) { return std::to_string(w) + " x " + std::to_string(h); }

// The checks every reader makes before allocating.
void check_size(const std::string& name, std::int64_t w, std::int64_t h) {
    if (w < 1 || h < 1) throw image_error(name, "the image is " + size_text(w, h) + "; it needs at least one pixel");
    if (w > max_image_dimension || h > max_image_dimension)
        throw image_error(name, "the image is " + size_text(w, h) + "; this reader takes at most " +
                                    std::to_string(max_image_dimension) + " pixels in each direction");
    if (w * h > max_image_pixels)
        throw image_error(name, "the image is " + size_text(w, h) + ", more than the " +
                                    std::to_string(max_image_pixels) + " pixels this reader takes");
}

std::uint16_t swap_bytes(std::uint16_t v) { return static_cast<std::uint16_t>((v >> 8) | (v << 8)); }

// ---------------------------------------------------------------------------------------
// PNM

bool pnm_space(std::uint8_t c) { return c == ' ' || c == '\t' || c == '\n' || c == '\v' || c == '\f' || c == '\r'; }
bool digit(std::uint8_t c) { return c >= '0' && c <= '9'; }

// Reads the text tokens of a PNM or PFM header; '#' starts a comment up to the line's end.
class header_reader {
public:
    header_reader(std::span<const std::uint8_t> bytes, std::size_t pos, const std::string& name)
        : bytes_(bytes), pos_(pos), name_(name) {}

    void skip_space_and_comments() {
        while (pos_ < bytes_.size()) {
            if (pnm_space(bytes_[pos_])) {
                ++pos_;
            } else if (bytes_[pos_] == '#') {
                while (pos_ < bytes_.size() && bytes_[pos_] != '\n' && bytes_[pos_] != '\r') ++pos_;
            } else {
                break;
            }
        }
    }

    // A decimal number of at most `max`; `what` names it in messages ("the width").
    std::int64_t number(const char* what, std::int64_t max) {
        skip_space_and_comments();
        if (pos_ >= bytes_.size()) throw image_error(name_, std::string("the header ends before ") + what + " (the file is truncated)");
        if (bytes_[pos_] == '-') throw image_error(name_, std::string(what) + " is negative");
        if (!digit(bytes_[pos_]))
            throw image_error(name_, std::string(what) + " is not a number (found " + describe(bytes_[pos_]) + ")");
        std::int64_t v = 0;
        while (pos_ < bytes_.size() && digit(bytes_[pos_])) {
            v = v * 10 + (bytes_[pos_++] - '0');
            if (v > max) throw image_error(name_, std::string(what) + " is larger than " + std::to_string(max));
        }
        if (pos_ < bytes_.size() && !pnm_space(bytes_[pos_]) && bytes_[pos_] != '#')
            throw image_error(name_, std::string(what) + " is followed by " + describe(bytes_[pos_]) + ", not white space");
        return v;
    }

    // A non-blank token (for the PFM scale, which is a decimal fraction).
    std::string_view token(const char* what) {
        skip_space_and_comments();
        const std::size_t start = pos_;
        while (pos_ < bytes_.size() && !pnm_space(bytes_[pos_]) && pos_ - start < 64) ++pos_;
        if (start == pos_) throw image_error(name_, std::string("the header ends before ") + what + " (the file is truncated)");
        return {reinterpret_cast<const char*>(bytes_.data()) + start, pos_ - start};
    }

    // The single white-space byte that ends a header before binary samples.
    void end_of_header(const char* after) {
        if (pos_ >= bytes_.size()) throw image_error(name_, "the file ends after the header: no samples (truncated)");
        if (!pnm_space(bytes_[pos_]))
            throw image_error(name_, std::string("expected one white-space byte after ") + after + ", found " + describe(bytes_[pos_]));
        ++pos_;
    }

    void advance() { ++pos_; }
    std::size_t left() const { return bytes_.size() - pos_; }
    const std::uint8_t* here() const { return bytes_.data() + pos_; }

    static std::string describe(std::uint8_t c) {
        if (c >= 0x21 && c < 0x7f) return std::string("'") + static_cast<char>(c) + "'";
        char hex[8];
        std::snprintf(hex, sizeof hex, "0x%02x", c);
        return std::string("byte ") + hex;
    }

private:
    std::span<const std::uint8_t> bytes_;
    std::size_t pos_;
    const std::string& name_;
};

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

// ---------------------------------------------------------------------------------------
// PNG through libpng.
//
// libpng reports an error by calling our error function, which must not return. The
// libpng-manual's way is setjmp/longjmp. A longjmp skips C++ destructors, so it is only
// safe into a frame that holds none ([csetjmp.syn]): each libpng call that can fail runs in
// a small function below whose locals are plain pointers and numbers, with setjmp at its
// top. That function returns false after an error; its caller, holding the RAII objects,
// throws the message the error function saved. Throwing from the error function through
// libpng's C frames instead would need libpng built with unwind tables.

struct png_messages {
    char error[200] = "libpng error";
};

extern "C" void on_png_error(png_structp png, png_const_charp message) {
    auto* m = static_cast<png_messages*>(png_get_error_ptr(png));
    std::snprintf(m->error, sizeof m->error, "%s", message);
    png_longjmp(png, 1);
}

extern "C" void on_png_warning(png_structp, png_const_charp) {}  // warnings do not stop reading

struct png_memory_source {
    const std::uint8_t* data;
    std::size_t size;
    std::size_t pos;
};

extern "C" void read_png_bytes(png_structp png, png_bytep out, png_size_t n) {
    auto* src = static_cast<png_memory_source*>(png_get_io_ptr(png));
    if (n > src->size - src->pos) png_error(png, "the file is truncated");
    std::memcpy(out, src->data + src->pos, n);
    src->pos += n;
}

struct png_read_header {
    png_uint_32 width = 0, height = 0;
    int bit_depth = 0, channels = 0;
    std::size_t row_bytes = 0;
};

bool png_read_info_and_set_transforms(png_structp png, png_infop info, png_read_header* h) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_read_info(png, info);
    const int color_type = png_get_color_type(png, info);
    const int depth = png_get_bit_depth(png, info);
    if (color_type == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(png);
    if (color_type == PNG_COLOR_TYPE_GRAY && depth < 8) png_set_expand_gray_1_2_4_to_8(png);
    if (png_get_valid(png, info, PNG_INFO_tRNS)) png_set_tRNS_to_alpha(png);
    if (depth == 16 && std::endian::native == std::endian::little) png_set_swap(png);  // PNG is big-endian
    png_set_interlace_handling(png);
    png_read_update_info(png, info);
    h->width = png_get_image_width(png, info);
    h->height = png_get_image_height(png, info);
    h->bit_depth = png_get_bit_depth(png, info);
    h->channels = png_get_channels(png, info);
    h->row_bytes = png_get_rowbytes(png, info);
    return true;
}

bool png_read_all_rows(png_structp png, png_bytepp rows) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_read_image(png, rows);
    png_read_end(png, nullptr);
    return true;
}

struct png_read_guard {
    png_structp png = nullptr;
    png_infop info = nullptr;
    ~png_read_guard() { png_destroy_read_struct(&png, &info, nullptr); }
};

// ---------------------------------------------------------------------------------------
// PFM

std::endian pfm_byte_order(double scale) { return scale < 0 ? std::endian::little : std::endian::big; }

}  // namespace

// ---------------------------------------------------------------------------------------
// Readers

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

image read_png(std::span<const std::uint8_t> bytes, const std::string& name) {
    if (bytes.size() < 8 || png_sig_cmp(bytes.data(), 0, 8) != 0)
        throw image_error(name, "not a PNG file (the 8-byte PNG signature is missing)");
    png_messages messages;
    png_read_guard guard;
    guard.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &messages, on_png_error, on_png_warning);
    if (!guard.png) throw std::bad_alloc();
    guard.info = png_create_info_struct(guard.png);
    if (!guard.info) throw std::bad_alloc();
    png_memory_source source{bytes.data(), bytes.size(), 0};
    png_set_read_fn(guard.png, &source, read_png_bytes);
    // libpng's own limits, before it allocates anything for the header's sizes.
    png_set_user_limits(guard.png, max_image_dimension, max_image_dimension);

    png_read_header h;
    if (!png_read_info_and_set_transforms(guard.png, guard.info, &h))
        throw image_error(name, std::string("bad PNG: ") + messages.error);
    check_size(name, h.width, h.height);
    if ((h.bit_depth != 8 && h.bit_depth != 16) || h.channels < 1 || h.channels > 4 ||
        h.row_bytes != std::size_t{h.width} * h.channels * (h.bit_depth / 8))
        throw image_error(name, "unsupported PNG layout (" + std::to_string(h.bit_depth) + " bits, " +
                                    std::to_string(h.channels) + " channels)");
    // Deflate expands at most 1032:1 (zlib's technical details), so a file cannot hold
    // more raw bytes than that; refuse before allocating for a header that claims more.
    const std::uint64_t raw = (std::uint64_t{h.row_bytes} + 1) * h.height;
    if (raw / 1032 > bytes.size() + 1024)
        throw image_error(name, "truncated: the header promises " + size_text(h.width, h.height) +
                                    " pixels, more than a " + std::to_string(bytes.size()) + "-byte file can hold");

    image img(static_cast<int>(h.width), static_cast<int>(h.height), h.channels,
              h.bit_depth == 16 ? sample_type::u16 : sample_type::u8);
    std::vector<png_bytep> rows(h.height);
    for (png_uint_32 y = 0; y < h.height; ++y) rows[y] = reinterpret_cast<png_bytep>(img.row_data(static_cast<int>(y)));
    if (!png_read_all_rows(guard.png, rows.data())) throw image_error(name, std::string("bad PNG: ") + messages.error);
    return img;
}

image read_image(std::span<const std::uint8_t> bytes, const std::string& name) {
    if (bytes.empty()) throw image_error(name, "the file is empty");
    if (bytes.size() >= 8 && png_sig_cmp(bytes.data(), 0, 8) == 0) return read_png(bytes, name);
    if (bytes.size() >= 2 && bytes[0] == 'P' && (bytes[1] == 'F' || bytes[1] == 'f')) return read_pfm(bytes, name);
    if (bytes.size() >= 2 && bytes[0] == 'P' && bytes[1] >= '1' && bytes[1] <= '6') return read_pnm(bytes, name);
    throw image_error(name, "not an image this reader knows: expected PNM (P1-P6), PFM (PF, Pf) or PNG, but the file starts with " +
                                header_reader::describe(bytes[0]));
}

image read_image(const std::filesystem::path& file) {
    const file_bytes contents(file);
    return read_image(contents.bytes(), file_name(file));
}

// ---------------------------------------------------------------------------------------
// Conversions

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
    if (channels < 1 || channels > 4) throw std::invalid_argument("vl::convert_channels: channels must be 1 to 4");
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

// ---------------------------------------------------------------------------------------
// Writers

namespace {

// `img` with the given sample type and channel count: `img` itself when it has them (no
// copy of a 50 MB image just to write it), else a converted copy kept in `keep`.
const image& as_needed(const image& img, sample_type type, int channels, std::optional<image>& keep) {
    if (img.type() == type && img.channels() == channels) return img;
    keep = convert_channels(img.type() == type ? img : convert_samples(img, type), channels);
    return *keep;
}

}  // namespace

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

class pnm_row_writer::file : public output_file {
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
        throw std::logic_error("pnm_row_writer: a row of the wrong size, or one row too many");
    out_->write(row.data(), row.size());
    --rows_left_;
}

void pnm_row_writer::finish() {
    if (rows_left_ != 0) throw image_error(out_->name(), std::to_string(rows_left_) + " rows were never written");
    out_->finish();
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

namespace {

extern "C" void write_png_bytes(png_structp png, png_bytep data, png_size_t n) {
    if (std::fwrite(data, 1, n, static_cast<std::FILE*>(png_get_io_ptr(png))) != n) png_error(png, "write failed (is the disk full?)");
}
extern "C" void flush_png(png_structp) {}

struct png_write_guard {
    png_structp png = nullptr;
    png_infop info = nullptr;
    ~png_write_guard() { png_destroy_write_struct(&png, &info); }
};

bool png_write_all(png_structp png, png_infop info, std::FILE* f, png_uint_32 w, png_uint_32 h, int depth,
                   int color_type, png_bytepp rows) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_set_write_fn(png, f, write_png_bytes, flush_png);
    png_set_IHDR(png, info, w, h, depth, color_type, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
                 PNG_FILTER_TYPE_DEFAULT);
    // The samples are sRGB-encoded (see vl::linear_to_srgb): say so, so viewers do not guess.
    png_set_sRGB_gAMA_and_cHRM(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
    // Speed over the last few percent of size: the "up" filter and a fast zlib level write
    // a 16-megapixel render in a fraction of a second and still compress it well.
    png_set_filter(png, 0, PNG_FILTER_UP);
    png_set_compression_level(png, 2);
    png_write_info(png, info);
    if (depth == 16 && std::endian::native == std::endian::little) png_set_swap(png);
    png_write_image(png, rows);
    png_write_end(png, nullptr);
    return true;
}

}  // namespace

void write_png(const std::filesystem::path& file, const image& img_in) {
    std::optional<image> keep;
    const image& img =
        as_needed(img_in, img_in.type() == sample_type::f32 ? sample_type::u8 : img_in.type(), img_in.channels(), keep);
    if (img.width() == 0 || img.height() == 0) throw image_error(file_name(file), "cannot write an empty image");
    static constexpr int color_types[] = {PNG_COLOR_TYPE_GRAY, PNG_COLOR_TYPE_GRAY_ALPHA, PNG_COLOR_TYPE_RGB,
                                          PNG_COLOR_TYPE_RGB_ALPHA};
    output_file out(file);
    png_messages messages;
    png_write_guard guard;
    guard.png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &messages, on_png_error, on_png_warning);
    if (!guard.png) throw std::bad_alloc();
    guard.info = png_create_info_struct(guard.png);
    if (!guard.info) throw std::bad_alloc();
    std::vector<png_bytep> rows(static_cast<std::size_t>(img.height()));
    for (int y = 0; y < img.height(); ++y)
        rows[y] = reinterpret_cast<png_bytep>(const_cast<std::byte*>(img.row_data(y)));  // libpng only reads them
    if (!png_write_all(guard.png, guard.info, out.get(), static_cast<png_uint_32>(img.width()),
                       static_cast<png_uint_32>(img.height()), img.type() == sample_type::u16 ? 16 : 8,
                       color_types[img.channels() - 1], rows.data()))
        throw image_error(out.name(), std::string("PNG write failed: ") + messages.error);
    out.finish();
}

void write_image(const std::filesystem::path& file, const image& img) {
    std::string ext = file.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (ext == ".ppm" && img.channels() <= 2) {
        write_pnm(file, convert_channels(img, 3));
    } else if (ext == ".ppm" || ext == ".pnm") {
        write_pnm(file, img);
    } else if (ext == ".pgm" && img.channels() != 1) {
        write_pnm(file, convert_channels(img, 1));
    } else if (ext == ".pgm") {
        write_pnm(file, img);
    } else if (ext == ".pbm") {
        write_pnm(file, img, true);
    } else if (ext == ".png") {
        write_png(file, img);
    } else if (ext == ".pfm") {
        write_pfm(file, img);
    } else {
        throw image_error(file_name(file), "unknown image extension '" + ext +
                                               "': use .png, .ppm, .pgm, .pbm, .pnm or .pfm");
    }
}

}  // namespace vl
