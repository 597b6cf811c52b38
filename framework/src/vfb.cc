// The virtual frame buffer: construction by storage name, whole-row load and save.
#include "vl/vfb.hh"

#include "vl/image_io.hh"

#include <algorithm>
#include <cmath>
#include <optional>

namespace vl {

vfb_range_error::vfb_range_error(vfb_int x, vfb_int y, vfb_int max_x, vfb_int max_y)
    : usage_error("vfb: pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") is outside (0, 0)..(" +
                  std::to_string(max_x) + ", " + std::to_string(max_y) + ")") {}

namespace {

// One entry per built-in storage: its name and how to make a buffer of it.
struct storage_entry {
    std::string_view name;
    std::unique_ptr<detail::storage_interface> (*make)(std::size_t pixels);
};

template <class S> std::unique_ptr<detail::storage_interface> make_storage(std::size_t pixels) {
    return std::make_unique<detail::storage_model<S>>(pixels);
}

constexpr storage_entry storages[] = {
    {bw_storage::name, make_storage<bw_storage>},
    {gray8_storage::name, make_storage<gray8_storage>},
    {rgb8_storage::name, make_storage<rgb8_storage>},
    {rgb_float_storage::name, make_storage<rgb_float_storage>},
    {zbuffer_storage::name, make_storage<zbuffer_storage>},
    {rgba_storage::name, make_storage<rgba_storage>},
    {antialiased_storage<2>::name, make_storage<antialiased_storage<2>>},
    {antialiased_storage<3>::name, make_storage<antialiased_storage<3>>},
    {antialiased_storage<4>::name, make_storage<antialiased_storage<4>>},
};

}  // namespace

std::size_t vfb::checked_pixels(vfb_int max_x, vfb_int max_y) {
    // The same limits as an image file, so that every buffer can be saved and loaded.
    if (max_x < 0 || max_y < 0 || max_x >= max_image_dimension || max_y >= max_image_dimension ||
        (std::int64_t{max_x} + 1) * (std::int64_t{max_y} + 1) > max_image_pixels)
        throw usage_error("vfb: cannot make a buffer with max_x " + std::to_string(max_x) + " and max_y " +
                          std::to_string(max_y) + "; each must be 0 to " + std::to_string(max_image_dimension - 1) +
                          " and the pixels at most " + std::to_string(max_image_pixels));
    return static_cast<std::size_t>(max_x + 1) * static_cast<std::size_t>(max_y + 1);
}

vfb::vfb(vfb_int max_x, vfb_int max_y, std::unique_ptr<detail::storage_interface> storage)
    : max_x_(max_x), max_y_(max_y), storage_(std::move(storage)) {}

vfb::vfb(vfb_int max_x, vfb_int max_y) : vfb(with_storage<storage_class>(max_x, max_y)) {}

vfb::vfb(vfb_int max_x, vfb_int max_y, std::string_view storage) : max_x_(max_x), max_y_(max_y) {
    const std::size_t pixels = checked_pixels(max_x, max_y);
    for (const auto& s : storages)
        if (s.name == storage) {
            storage_ = s.make(pixels);
            return;
        }
    std::string known;
    for (const auto& s : storages) known += (known.empty() ? "" : ", ") + std::string(s.name);
    throw usage_error("vfb: unknown pixel storage '" + std::string(storage) + "' (known: " + known + ")");
}

vfb::~vfb() = default;

std::vector<std::string_view> vfb::storage_names() {
    std::vector<std::string_view> names;
    for (const auto& s : storages) names.push_back(s.name);
    return names;
}

void vfb::put_pixel(const vfb_pixel& p) {
    if (!p.has_position())
        throw usage_error("vfb::put_pixel: this pixel has no coordinates; use put_pixel(x, y, pixel)");
    const double fx = std::floor(p.x()), fy = std::floor(p.y());
    // Compare as doubles first: a huge or NaN coordinate must not overflow an int.
    if (!(fx >= 0 && fy >= 0 && fx <= max_x_ && fy <= max_y_))
        throw vfb_range_error(std::isfinite(fx) && std::abs(fx) < 2e9 ? static_cast<vfb_int>(fx) : -1,
                              std::isfinite(fy) && std::abs(fy) < 2e9 ? static_cast<vfb_int>(fy) : -1, max_x_, max_y_);
    put_pixel(static_cast<vfb_int>(fx), static_cast<vfb_int>(fy), p);
}

image vfb::to_image(sample_type type, int channels) const {
    if (channels == 0) channels = storage_->natural_channels();
    image img(width(), height(), channels, type == sample_type::u8 ? sample_type::u8 : sample_type::f32);
    const auto w = static_cast<std::size_t>(width());
    for (int y = 0; y < height(); ++y) {
        // Image row 0 is the top; buffer row 0 is the bottom.
        const std::size_t first = static_cast<std::size_t>(max_y_ - y) * w;
        if (type == sample_type::u8)
            storage_->read_srgb8(first, w, channels, img.row<std::uint8_t>(y).data());
        else
            storage_->read_linear(first, w, channels, img.row<float>(y).data());
    }
    return type == sample_type::u16 ? convert_samples(img, sample_type::u16) : img;
}

void vfb::from_image(const image& img_in, vfb_int x1, vfb_int y1) {
    // Clip: image column i goes to x1 + i, image row r (from the top) to y1 + height - 1 - r.
    const std::int64_t x_begin = std::max<std::int64_t>(0, x1);
    const std::int64_t x_end = std::min<std::int64_t>(std::int64_t{x1} + img_in.width(), width());
    const std::int64_t y_begin = std::max<std::int64_t>(0, y1);
    const std::int64_t y_end = std::min<std::int64_t>(std::int64_t{y1} + img_in.height(), height());
    if (x_begin >= x_end || y_begin >= y_end) return;  // nothing overlaps

    // 16-bit samples go through linear float; 8-bit and float ones are used as they are.
    std::optional<image> converted;
    if (img_in.type() == sample_type::u16) converted = convert_samples(img_in, sample_type::f32);
    const image& img = converted ? *converted : img_in;
    const int c = img.channels();
    const auto n = static_cast<std::size_t>(x_end - x_begin);
    const auto column = static_cast<std::size_t>(x_begin - x1) * c;
    for (std::int64_t y = y_begin; y < y_end; ++y) {
        const int r = static_cast<int>(std::int64_t{y1} + img.height() - 1 - y);
        const std::size_t first = static_cast<std::size_t>(y) * static_cast<std::size_t>(width()) +
                                  static_cast<std::size_t>(x_begin);
        if (img.type() == sample_type::u8)
            storage_->write_srgb8(first, n, c, img.row<std::uint8_t>(r).data() + column);
        else
            storage_->write_linear(first, n, c, img.row<float>(r).data() + column);
    }
}

void vfb::load(const std::filesystem::path& file, vfb_int x1, vfb_int y1) { from_image(read_image(file), x1, y1); }

void vfb::save(const std::filesystem::path& file) const {
    std::string ext = file.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
    const int natural = storage_->natural_channels();
    if (ext == ".ppm" || ext == ".pgm" || (ext == ".pnm" && (natural == 1 || natural == 3))) {
        // Stream rows from the top (the buffer's last row) into the file: no copy of the
        // whole buffer, and for 8-bit storages each row is one memcpy and one fwrite.
        const int channels = ext == ".pgm" || (ext == ".pnm" && natural == 1) ? 1 : 3;
        const auto w = static_cast<std::size_t>(width());
        std::vector<std::uint8_t> row(w * static_cast<std::size_t>(channels));
        pnm_row_writer out(file, width(), height(), channels);
        for (int y = max_y_; y >= 0; --y) {
            storage_->read_srgb8(static_cast<std::size_t>(y) * w, w, channels, row.data());
            out.write_row(row);
        }
        out.finish();
    } else if (ext == ".pfm") {
        write_image(file, to_image(sample_type::f32, natural == 1 ? 1 : 3));
    } else if (ext == ".pbm") {
        write_image(file, to_image(sample_type::u8, 1));
    } else if (ext == ".pnm") {
        write_image(file, to_image(sample_type::u8, natural == 1 ? 1 : 3));
    } else {
        write_image(file, to_image(sample_type::u8, natural));  // PNG, or write_image names the problem
    }
}

}  // namespace vl
