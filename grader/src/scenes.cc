#include "scenes.hh"

#include <algorithm>
#include <cstdlib>
#include <sstream>

#include "image_compare.hh"
#include "vl/image_io.hh"

namespace vl::grader {

namespace fs = std::filesystem;

namespace {

vl::image as_rgb8(const vl::image& img) { return convert_channels(convert_samples(img, sample_type::u8), 3); }

/// Black where the images agree, brighter where they differ (4x the largest channel
/// difference, so a difference of 64 levels is white).
vl::image difference_image(const vl::image& a, const vl::image& b) {
    const vl::image x = as_rgb8(a), y = as_rgb8(b);
    vl::image d(x.width(), x.height(), 3, sample_type::u8);
    const auto p = x.samples<std::uint8_t>(), q = y.samples<std::uint8_t>();
    auto out = d.samples<std::uint8_t>();
    for (std::size_t i = 0; i < p.size(); i += 3) {
        int most = 0;
        for (std::size_t c = 0; c < 3; ++c) most = std::max(most, std::abs(int(p[i + c]) - int(q[i + c])));
        const auto v = static_cast<std::uint8_t>(std::min(255, 4 * most));
        out[i] = v;
        out[i + 1] = static_cast<std::uint8_t>(v / 2);
        out[i + 2] = static_cast<std::uint8_t>(v / 4);
    }
    return d;
}

}  // namespace

scene_outcome render_and_compare(const fs::path& render_program, const rubric_scene& scene, const fs::path& reference,
                                 const fs::path& work, const run_limits& limits, const sandbox_capabilities& caps) {
    scene_outcome o;
    fs::create_directories(work);
    give_to_sandbox(work, caps);
    const std::string stem = scene.file.stem().string();
    o.image = work / (stem + ".png");
    run_request rq;
    rq.argv = {render_program.string(), scene.file.string(), "-o", o.image.string(), "--threads", "1"};
    rq.cwd = work;
    rq.output = work / (stem + ".log");
    rq.environment = child_environment(work);
    rq.limits = limits;
    const run_result r = run(rq, caps);
    o.seconds = r.seconds;
    if (!r.succeeded() || !fs::exists(o.image)) {
        o.message = "the render " + r.describe(rq.limits.wall_seconds) + ":\n" + read_head(rq.output, 1500);
        o.image.clear();
        return o;
    }
    try {
        const vl::image mine = read_image(o.image), theirs = read_image(reference);
        const image_difference d = compare_images(mine, theirs, scene.threshold_levels);
        o.rendered = true;
        if (!d.same_size) {
            o.message = "the image has the wrong size: " + d.summary;
            return o;
        }
        o.difference = work / (stem + ".difference.png");
        write_image(o.difference, difference_image(mine, theirs));
        o.matches = d.mean_abs <= scene.max_mean_difference && d.fraction_over <= scene.max_fraction_over;
        std::ostringstream s;
        s << d.summary << " (allowed: mean " << scene.max_mean_difference << ", "
          << 100 * scene.max_fraction_over << "% of pixels)";
        o.message = s.str();
    } catch (const std::exception& e) {
        o.rendered = false;
        o.message = std::string("the render wrote an unreadable image: ") + e.what();
    }
    return o;
}

}  // namespace vl::grader
