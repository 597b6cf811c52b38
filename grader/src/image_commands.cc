// The subcommands about images: imgdiff (one render against another), calibrate-thresholds
// (the FLIP spread of the hidden scenes and the thresholds it suggests) and tradeoff (runs
// the framework's tradeoff program).
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>

#include "commands.hh"
#include "image_compare.hh"
#include "thresholds.hh"
#include "vl/flip.hh"
#include "vl/image_io.hh"
#include "vl/ssim.hh"

namespace vl::grader {

namespace fs = std::filesystem;

namespace {

/// Reads the image `file` for imgdiff; `role` ("reference" or "test") names it in errors.
vl::image read_for_imgdiff(const std::string& file, const char* role) {
    try {
        return vl::read_image(file);
    } catch (const vl::image_error& e) {
        throw grader_error(std::string("cannot read the ") + role + " image: " + e.what() +
                           " (give the path of a PNG, PPM, PGM, PBM or PFM file)");
    }
}

}  // namespace

/// `calibrate-thresholds ASSIGNMENT [--calibration DIR] [--renderer PATH]... [--out DIR]`: the FLIP spread of
/// each hidden scene over its legitimate renders and the thresholds it suggests
/// (thresholds.hh); prints one line per render and one per scene, and writes them to
/// OUT/thresholds.tsv.
int calibrate_thresholds_command(const installation& in, arguments args) {
    std::string calibration = take_option(args, "--calibration");
    std::string out = take_option(args, "--out");
    std::vector<fs::path> renderers;
    for (std::string r = take_option(args, "--renderer"); !r.empty(); r = take_option(args, "--renderer")) {
        if (!fs::is_regular_file(r)) throw command_line_error{"--renderer " + r + ": no such program"};
        renderers.push_back(fs::absolute(r));
    }
    expect_count(args, 1);
    const vl::grader::stage_info& stage = in.find_stage(args[0]);
    if (calibration.empty()) calibration = (in.grader_build_dir / "calibration" / stage.name).string();
    if (out.empty()) out = (in.grader_build_dir / "thresholds" / stage.name).string();
    const auto spreads = vl::grader::measure_spread(in, stage, calibration, out, renderers);
    std::ofstream tsv(fs::path(out) / "thresholds.tsv");
    tsv << "scene\tvariation\tflip_mean\tfraction_over\n";
    for (const auto& sp : spreads) {
        for (const auto& v : sp.variations) {
            if (!v.problem.empty()) {
                std::printf("scene=%s variation=\"%s\" not measured: %s\n", sp.id.c_str(), v.name.c_str(), v.problem.c_str());
                continue;
            }
            std::printf("scene=%s variation=\"%s\" flip_mean=%.5f fraction_over=%.5f\n", sp.id.c_str(), v.name.c_str(),
                        v.flip_mean, v.fraction_over);
            tsv << sp.id << '\t' << v.name << '\t' << v.flip_mean << '\t' << v.fraction_over << '\n';
        }
        std::printf("scene=%s spread: flip_mean<=%.5f fraction_over<=%.5f -> max_flip_mean = %g, max_fraction_over = %g"
                    " (the rubric has metric=%s, max_flip_mean=%g, max_fraction_over=%g)\n",
                    sp.id.c_str(), sp.max_flip_mean, sp.max_fraction_over, sp.suggested_flip_mean, sp.suggested_fraction,
                    sp.metric.c_str(), sp.current_max_flip_mean, sp.current_max_fraction_over);
    }
    std::printf("written: %s\n", (fs::path(out) / "thresholds.tsv").string().c_str());
    return 0;
}

/// `imgdiff REF TEST [--map OUT.png] [--ppd N]`: LDR-FLIP, SSIM and the largest 8-bit
/// difference of TEST against REF, on one line (docs/image-metrics.md explains them).
int imgdiff_command(arguments args) {
    const std::string map = take_option(args, "--map");
    const std::string ppd_text = take_option(args, "--ppd");
    expect_count(args, 2);
    vl::flip_options options;
    if (!ppd_text.empty()) {
        char* end = nullptr;
        options.pixels_per_degree = std::strtod(ppd_text.c_str(), &end);
        if (end == ppd_text.c_str() || *end != '\0' || !(options.pixels_per_degree > 0) ||
            !std::isfinite(options.pixels_per_degree))
            throw command_line_error{"--ppd needs a positive number of pixels per degree, not '" + ppd_text + "'"};
    }
    const vl::image reference = read_for_imgdiff(args[0], "reference");
    const vl::image test = read_for_imgdiff(args[1], "test");
    if (reference.width() != test.width() || reference.height() != test.height())
        throw grader_error("the images differ in size: the reference " + args[0] + " is " +
                           std::to_string(reference.width()) + " x " + std::to_string(reference.height()) +
                           " pixels and the test " + args[1] + " is " + std::to_string(test.width()) + " x " +
                           std::to_string(test.height()) +
                           " pixels; imgdiff compares images pixel by pixel: render the test at the reference's size");
    const vl::flip_result f = vl::flip(reference, test, options);
    const vl::ssim_result s = vl::ssim(reference, test);
    const vl::image_difference d = vl::compare_images(reference, test);
    if (!map.empty()) {
        try {
            vl::write_image(map, vl::flip_error_map(f));
        } catch (const vl::image_error& e) {
            throw grader_error(std::string("cannot write the error map: ") + e.what());
        }
    }
    std::printf("flip_mean=%.6f ssim=%.6f max_abs=%d flip_weighted_median=%.6f flip_weighted_q1=%.6f "
                "flip_weighted_q3=%.6f flip_max=%.6f mean_abs=%.4f\n",
                f.mean, s.mean, d.max_abs, f.weighted_median, f.weighted_quartile_1, f.weighted_quartile_3, f.max,
                d.mean_abs);
    return 0;
}

/// `tradeoff ...`: runs the tradeoff program this build made (framework/apps/tradeoff,
/// beside the grader's build folder), which knows its own options (`tradeoff --help`).
int tradeoff_command(arguments args) {
    char self[4096];
    const ssize_t n = readlink("/proc/self/exe", self, sizeof self - 1);
    if (n <= 0) throw grader_error("cannot find the grader's own program (/proc/self/exe) to find tradeoff beside it");
    self[n] = '\0';
    const fs::path program = fs::path(self).parent_path().parent_path() / "framework" / "apps" / "tradeoff";
    if (access(program.c_str(), X_OK) != 0)
        throw grader_error(program.string() + " is missing: build it with tools/setup (or cmake --build build/default "
                           "--target tradeoff)");
    std::vector<char*> argv{const_cast<char*>(program.c_str())};
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    std::fflush(stdout);
    execv(program.c_str(), argv.data());
    throw grader_error("cannot run " + program.string() + ": " + std::strerror(errno));
}

}  // namespace vl::grader
