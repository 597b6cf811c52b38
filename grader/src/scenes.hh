#pragma once
/// \file
/// \brief Hidden scenes: rendered with the submission's pieces and compared with the
/// reference render. The comparison is the per-pixel difference of vl::compare_images;
/// perceptual metrics (FLIP, SSIM), intersection budgets and stability sweeps plug in
/// through rubric_scene::metric.
#include <filesystem>
#include <string>

#include "rubric.hh"
#include "sandbox.hh"

namespace vl::grader {

/// \brief How a rendered scene compares with the reference.
struct scene_outcome {
    bool rendered = false, matches = false;
    std::string message;                      ///< why it failed, or the comparison's numbers
    std::filesystem::path image, difference;  ///< the student's render and the difference image
    double seconds = 0;
};

/// Renders `scene` with `render_program` (sandboxed; the image comes back through a pipe),
/// keeps the image in `renders` (a folder of the grader's) and compares it with `reference`.
scene_outcome render_and_compare(const std::filesystem::path& render_program, const rubric_scene& scene,
                                 const std::filesystem::path& reference, const std::filesystem::path& renders,
                                 const run_limits& limits, const sandbox_capabilities& caps);

}  // namespace vl::grader
