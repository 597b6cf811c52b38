#include "scenes.hh"

#include <algorithm>
#include <cstdlib>
#include <sstream>

#include "external.hh"
#include "image_compare.hh"
#include "install.hh"
#include "safe_files.hh"
#include "vl/flip.hh"
#include "vl/image_io.hh"

namespace vl::grader {

namespace fs = std::filesystem;

namespace {

vl::image as_rgb8(const vl::image& img) { return convert_channels(convert_samples(img, sample_type::u8), 3); }

/// Black where the images agree, brighter where they differ (4x the largest channel
/// difference, so a difference of 64 levels is white): the highlight when ImageMagick is
/// missing.
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

scene_outcome render_and_compare(const render_program& render, const rubric_scene& scene, const fs::path& reference,
                                 const fs::path& renders, const run_limits& limits, const sandbox_capabilities& caps) {
    scene_outcome o;
    const std::string stem = scene.id;
    const std::string scene_inside = "/vl/scene/" + scene.file.filename().string();
    run_request rq;
    // A public scene comes with its folder (read-only), so its `include`s of the stage's
    // public parts resolve; the students have that folder anyway. A hidden scene comes
    // alone: no other hidden scene is visible to the submission's code.
    if (scene.is_public)
        rq.mounts = {{render.program, "/vl/bin/render", false}, {scene.file.parent_path(), "/vl/scene", false}};
    else
        rq.mounts = {{render.program, "/vl/bin/render", false}, {scene.file, scene_inside, false}};
    // The image goes to a pipe: out.png is a link to fd 3, so nothing is written to disk.
    rq.symlinks = {{"/proc/self/fd/3", "/scratch/out.png"}};
    rq.argv = {"/vl/bin/render", scene_inside, "-o", "/scratch/out.png", "--threads", "1"};
    rq.environment = child_environment("/scratch");
    // Which pieces are the submission's (hidden/common/graded_pieces.cc): the scene's, and
    // those whose reference this program does not link (which share code with them); the
    // others are the reference's, so the scene depends only on its own category's code.
    if (!scene.student_pieces.empty()) {
        std::set<std::string> named(scene.student_pieces.begin(), scene.student_pieces.end());
        named.insert(render.withheld_pieces.begin(), render.withheld_pieces.end());
        std::string pieces;
        for (const std::string& p : named) pieces += (pieces.empty() ? "" : " ") + p;
        rq.environment.push_back("VL_GRADED_PIECES=" + pieces);
    }
    rq.limits = limits;
    rq.report_fd = true;
    const run_result r = run(rq, caps);
    o.seconds = r.seconds;
    if (!r.started) throw grader_error("the sandbox could not run the renderer: " + r.error);
    if (r.exit_code == 120 && r.output.find("grader: VL_GRADED_PIECES") != std::string::npos)
        throw grader_error(scene.file.string() + ": the render program stopped on the grader's own mistake in the "
                           "rubric's student_pieces: " + r.output_head(300));
    if (!r.succeeded() || r.report.empty() || r.report_overflow) {
        o.message = "the render " + (r.report_overflow ? std::string("wrote an image larger than ") +
                                                             std::to_string(limits.report_bytes >> 20) + " MiB"
                                                       : r.describe(rq.limits.wall_seconds));
        // A hidden scene's render had the hidden file to read: what it printed could be the
        // scene itself, so the report says how it ended and quotes none of it.
        if (scene.is_public)
            o.message += "; the end of what your program printed:\n" + r.output_tail(500);
        else
            o.message += " (what a render of a hidden scene prints is not shown)";
        return o;
    }
    // The renderer's bytes are decoded here and only the grader's own encoding of them is
    // kept: nothing downstream (the report, ImageMagick) ever reads a submission's bytes.
    vl::image mine;
    try {
        const fs::path raw = renders / (stem + ".rendered.png");
        write_new_file(raw, r.report);
        mine = read_image(raw);
        fs::remove(raw);
    } catch (const vl::image_error& e) {
        o.message = std::string("the render wrote an unreadable image: ") + e.what();
        return o;
    }
    o.image = renders / (stem + ".png");
    write_image(o.image, as_rgb8(mine));
    o.rendered = true;
    const vl::image theirs = read_image(reference);
    const image_difference d = compare_images(mine, theirs, scene.threshold_levels);
    if (!d.same_size) {
        o.message = "the image has the wrong size: " + d.summary;
        return o;
    }
    const vl::flip_result f = vl::flip(theirs, mine);
    std::size_t over = 0;
    for (const float e : f.error) over += e > scene.flip_pixel_level;
    const double flip_over = f.error.empty() ? 0 : static_cast<double>(over) / static_cast<double>(f.error.size());
    o.flip_mean = f.mean;
    o.mean_abs = d.mean_abs;
    o.flip_map = renders / (stem + ".flip.png");
    write_image(o.flip_map, vl::flip_error_map(f));
    o.highlight = renders / (stem + ".highlight.png");
    if (!highlight_difference(reference, o.image, o.highlight).empty()) write_image(o.highlight, difference_image(mine, theirs));
    std::ostringstream s;
    s.precision(3);
    if (scene.metric == "flip") {
        o.matches = f.mean <= scene.max_flip_mean && flip_over <= scene.max_fraction_over;
        s << "FLIP mean " << f.mean << " (allowed: " << scene.max_flip_mean << "), " << 100 * flip_over
          << "% of pixels with FLIP error over " << scene.flip_pixel_level << " (allowed: " << 100 * scene.max_fraction_over
          << "%); " << d.summary;
    } else {
        o.matches = d.mean_abs <= scene.max_mean_difference && d.fraction_over <= scene.max_fraction_over;
        s << d.summary << " (allowed: mean " << scene.max_mean_difference << ", " << 100 * scene.max_fraction_over
          << "% of pixels); FLIP mean " << f.mean;
    }
    o.message = s.str();
    return o;
}

}  // namespace vl::grader
