#include "image_compare.hh"

#include <cstdlib>
#include <sstream>

#include "vl/registry.hh"
#include "vl/render.hh"

namespace vl {

image_difference compare_images(const image& a, const image& b, int threshold) {
    image_difference d;
    std::ostringstream s;
    if (a.width() != b.width() || a.height() != b.height()) {
        s << "sizes differ: " << a.width() << "x" << a.height() << " and " << b.width() << "x" << b.height();
        d.summary = s.str();
        return d;
    }
    d.same_size = true;
    const image x = convert_channels(convert_samples(a, sample_type::u8), 3);
    const image y = convert_channels(convert_samples(b, sample_type::u8), 3);
    const auto p = x.samples<std::uint8_t>(), q = y.samples<std::uint8_t>();
    std::uint64_t sum = 0, over = 0;
    for (std::size_t i = 0; i < p.size(); i += 3) {
        bool pixel_over = false;
        for (std::size_t c = 0; c < 3; ++c) {
            const int diff = std::abs(int(p[i + c]) - int(q[i + c]));
            sum += static_cast<std::uint64_t>(diff);
            d.max_abs = std::max(d.max_abs, diff);
            pixel_over = pixel_over || diff > threshold;
        }
        over += pixel_over;
    }
    const double pixels = static_cast<double>(p.size() / 3);
    d.mean_abs = p.empty() ? 0 : static_cast<double>(sum) / static_cast<double>(p.size());
    d.fraction_over = p.empty() ? 0 : static_cast<double>(over) / pixels;
    s << a.width() << "x" << a.height() << ": mean difference " << d.mean_abs << " levels, max " << d.max_abs
      << ", " << 100 * d.fraction_over << "% of pixels more than " << threshold << " levels apart";
    d.summary = s.str();
    return d;
}

bool renders_match(const image_difference& d) { return d.same_size && d.mean_abs < 0.5 && d.fraction_over < 0.005; }

image_difference compare_render(const std::filesystem::path& scene_file, const std::filesystem::path& reference,
                                const registry& types) {
    const scene s = read_scene(scene_file, types);
    vfb out(s.width - 1, s.height - 1, "rgb8");
    render_options o;
    o.progress = false;
    render(s, types, out, o);
    return compare_images(out.to_image(), read_image(reference));
}

}  // namespace vl
