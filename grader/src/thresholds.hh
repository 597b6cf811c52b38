#pragma once
/// \file
/// \brief calibrate-thresholds: how far legitimate renders of each hidden scene stray from
/// the reference render, measured with LDR-FLIP, and the threshold that follows.
///
/// A scene's threshold must pass every correct render and fail a wrong one. The
/// legitimate variations are the reference rendered with two threads, with other seeds
/// of the random samplers and by the reference renderers of other builds (another
/// optimisation level or compiler: --renderer), and the renders of the stage's correct alternative
/// calibration cases (grader/tests/submissions/NN-name/alt-* and correct-*: written from
/// the contract alone, with other formulas and other rounding). The suggested
/// max_flip_mean is twice the largest FLIP mean among them, and at least 0.04 (rounding
/// alone, one level off at every pixel of a flat gray, costs 0.03); the suggested
/// max_fraction_over is twice the largest share of pixels over the scene's
/// flip_pixel_level (0.1, about 6 levels of a mid gray), and at least 0.005 (an edge may
/// move by a pixel when a compiler contracts a multiply-add differently). The mean
/// catches a difference spread over the image, the share a local one (a highlight of the
/// wrong colour, a shifted edge).
#include <filesystem>
#include <string>
#include <vector>

#include "install.hh"

namespace vl::grader {

/// \brief One legitimate render of a scene against the reference's.
struct threshold_variation {
    std::string name;          ///< "threads 2", "seed 1", or the calibration case's name
    double flip_mean = 0;      ///< LDR-FLIP mean against the reference render
    double fraction_over = 0;  ///< of the pixels whose FLIP error is over the scene's flip_pixel_level
    std::string problem;       ///< why it could not be measured, or ""
};

/// \brief The spread of one scene and the thresholds it suggests.
struct scene_spread {
    std::string id, title, metric;
    double current_max_flip_mean = 0, current_max_fraction_over = 0;
    std::vector<threshold_variation> variations;
    double max_flip_mean = 0, max_fraction_over = 0;        ///< over the variations measured
    double suggested_flip_mean = 0, suggested_fraction = 0;  ///< what the rubric should say
};

/// Measures every scene of `stage`'s rubric. Renders go to `out`; the alternatives'
/// renders are read from `calibration` (the calibrate command's output folders, one per
/// case: run the stage's calibration first). Throws grader_error when the reference
/// renderer fails.
/// `other_renderers` are reference renderers of other builds (another compiler, -O0),
/// each one more variation.
std::vector<scene_spread> measure_spread(const installation& in, const stage_info& stage,
                                         const std::filesystem::path& calibration, const std::filesystem::path& out,
                                         const std::vector<std::filesystem::path>& other_renderers = {});

}  // namespace vl::grader
