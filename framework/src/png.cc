// PNG files through libpng 1.6 (libpng-manual.txt): the reader (any PNG, expanded to 8 or
// 16 bits) and the writer (8 or 16 bits with an sRGB chunk).
//
// libpng reports an error by calling our error function, which must not return. The
// libpng-manual's way is setjmp/longjmp. A longjmp skips C++ destructors, so it is only
// safe into a frame that holds none ([csetjmp.syn]): each libpng call that can fail runs in
// a small function below whose locals are plain pointers and numbers, with setjmp at its
// top. That function returns false after an error; its caller, holding the RAII objects,
// throws the message the error function saved. Throwing from the error function through
// libpng's C frames instead would need libpng built with unwind tables.
#include "image_file.hh"

#include <png.h>

#include <bit>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <new>

namespace vl {

using namespace image_detail;

namespace {

struct png_messages {
    char error[200] = "libpng error";
};

extern "C" void on_png_error(png_structp png, png_const_charp message) {
    auto* m = static_cast<png_messages*>(png_get_error_ptr(png));
    std::snprintf(m->error, sizeof m->error, "%s", message);
    png_longjmp(png, 1);
}

extern "C" void on_png_warning(png_structp, png_const_charp) {}  // warnings do not stop reading

// A struct libpng made, or std::bad_alloc when it could not make one.
template <class T> T made(T p) {
    if (!p) throw std::bad_alloc();
    return p;
}

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

bool image_detail::has_png_signature(std::span<const std::uint8_t> bytes) {
    return bytes.size() >= 8 && png_sig_cmp(bytes.data(), 0, 8) == 0;
}

image read_png(std::span<const std::uint8_t> bytes, const std::string& name) {
    if (!has_png_signature(bytes))
        throw image_error(name, "not a PNG file (the 8-byte PNG signature is missing)");
    png_messages messages;
    png_read_guard guard;
    guard.png = made(png_create_read_struct(PNG_LIBPNG_VER_STRING, &messages, on_png_error, on_png_warning));
    guard.info = made(png_create_info_struct(guard.png));
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
    guard.png = made(png_create_write_struct(PNG_LIBPNG_VER_STRING, &messages, on_png_error, on_png_warning));
    guard.info = made(png_create_info_struct(guard.png));
    std::vector<png_bytep> rows(static_cast<std::size_t>(img.height()));
    for (int y = 0; y < img.height(); ++y)
        rows[y] = reinterpret_cast<png_bytep>(const_cast<std::byte*>(img.row_data(y)));  // libpng only reads them
    if (!png_write_all(guard.png, guard.info, out.get(), static_cast<png_uint_32>(img.width()),
                       static_cast<png_uint_32>(img.height()), img.type() == sample_type::u16 ? 16 : 8,
                       color_types[img.channels() - 1], rows.data()))
        throw image_error(out.name(), std::string("PNG write failed: ") + messages.error);
    out.finish();
}

}  // namespace vl
