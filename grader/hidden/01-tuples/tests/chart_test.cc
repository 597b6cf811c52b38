// A chart of stage 01 (grader only): how fast each sample pattern converges. Tagged
// [chart]: it checks nothing and is worth no points; the rubric's [[chart]] draws the
// submission's points over the reference's in report.html.
//
// The "scene" is a picture defined at every point of the image plane (discs, a thin
// line, a fine checkerboard, a gradient), so the chart depends on the sample patterns
// alone: no camera, no objects. Each pixel's colour is the mean of the picture at its n
// sample positions (seeded as the render driver seeds them, vl::pixel_seed); the
// converged picture is the mean over a 16 x 16 grid in every pixel. y is the mean LDR-FLIP
// of each image against the converged one; x is samples per pixel (the cost: rays per
// pixel), never a time. 64 x 48 pixels, so the whole test takes well under a second.
#include "vl/catch.hh"

#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "hidden_support.hh"
#include "vl/flip.hh"
#include "vl/image_io.hh"
#include "vl/render.hh"

using namespace vl;

namespace {

constexpr int width = 64, height = 48;

using rgb = std::array<double, 3>;

/// The picture at image position (x, y) in pixel units, (0, 0) at the lower left; linear RGB.
rgb picture(double x, double y) {
    if (!std::isfinite(x) || !std::isfinite(y)) return {0, 0, 0};  // an offset that is no number
    auto inside = [&](double cx, double cy, double r) { return (x - cx) * (x - cx) + (y - cy) * (y - cy) < r * r; };
    if (inside(18, 30, 11)) return {0.9, 0.25, 0.1};
    if (inside(44, 16, 7.5)) return {0.15, 0.6, 0.95};
    if (inside(52, 37, 3.2)) return {1, 1, 0.85};
    // A line 0.6 pixels wide from (4, 4) towards (60, 20).
    const double along = ((x - 4) * 56 + (y - 4) * 16) / std::hypot(56.0, 16.0);
    const double across = std::abs((x - 4) * 16 - (y - 4) * 56) / std::hypot(56.0, 16.0);
    if (along > 0 && along < std::hypot(56.0, 16.0) && across < 0.3) return {0.95, 0.95, 0.95};
    // A checkerboard of 1.5-pixel squares in the upper right.
    if (x > 30 && y > 26 && x < 46 && y < 44)
        return (static_cast<int>(std::floor(x / 1.5)) + static_cast<int>(std::floor(y / 1.5))) % 2 ? rgb{0.8, 0.8, 0.8}
                                                                                                     : rgb{0.05, 0.05, 0.05};
    const double g = 0.05 + 0.25 * y / height;
    return {g, g, 0.1 + g};
}

/// The image (rows top to bottom, linear float) whose pixel (i, j) is `colour(i, j)`.
template <class F>
image picture_image(F&& colour) {
    image out(width, height, 3, sample_type::f32);
    for (int j = 0; j < height; ++j) {
        const std::span<float> row = out.row<float>(height - 1 - j);
        for (int i = 0; i < width; ++i) {
            const rgb c = colour(i, j);
            for (int ch = 0; ch < 3; ++ch) row[static_cast<std::size_t>(3 * i + ch)] = static_cast<float>(c[static_cast<std::size_t>(ch)]);
        }
    }
    return out;
}

}  // namespace

TEST_CASE("chart: samplers: LDR-FLIP against the converged picture as samples per pixel grow - per pattern", "[01][chart]") {
    const int fine = 16;
    const image converged = picture_image([&](int i, int j) {
        rgb sum{0, 0, 0};
        for (int a = 0; a < fine; ++a)
            for (int b = 0; b < fine; ++b) {
                const rgb c = picture(i + (a + 0.5) / fine, j + (b + 0.5) / fine);
                for (int ch = 0; ch < 3; ++ch) sum[static_cast<std::size_t>(ch)] += c[static_cast<std::size_t>(ch)];
            }
        for (double& v : sum) v /= fine * fine;
        return sum;
    });
    for (const std::string_view name : stage01::sampler_names) {
        // A pattern that is missing or throws (a stub not written yet) is left out from there
        // on, so the others' curves still show.
        try {
        const std::unique_ptr<sampler> pattern = stage01::make_sampler(name);
        if (!pattern) {
            WARN(std::string(name) << " left out of the chart: make_sampler returned nullptr");
            continue;
        }
        // Every pixel's seed, asked of the pattern at once (vl::grading::offsets_for_seeds).
        std::vector<std::uint64_t> seeds;
        for (int j = 0; j < height; ++j)
            for (int i = 0; i < width; ++i) seeds.push_back(pixel_seed(i, j));
        for (int n = 1; n <= 64; n *= 2) {
            const std::vector<sample_offset> fill(static_cast<std::size_t>(n));
            const std::vector<std::vector<sample_offset>> offsets = grading::offsets_for_seeds(*pattern, fill, seeds);
            const image test = picture_image([&](int i, int j) {
                rgb sum{0, 0, 0};
                for (const sample_offset& o : offsets[static_cast<std::size_t>(j * width + i)]) {
                    const rgb c = picture(i + o.dx, j + o.dy);
                    for (int ch = 0; ch < 3; ++ch) sum[static_cast<std::size_t>(ch)] += c[static_cast<std::size_t>(ch)];
                }
                for (double& v : sum) v /= n;
                return sum;
            });
            grading::chart_point(std::string(name), n, flip(converged, test).mean);
        }
        } catch (const std::exception& e) {
            WARN(std::string(name) << " left out of the chart: " << e.what());
        }
    }
}
