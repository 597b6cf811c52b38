#pragma once
/// \file
/// \brief Hidden scenes: rendered with the submission's pieces and compared with the
/// reference render. Both comparisons are measured, LDR-FLIP (vl/flip.hh) and the 8-bit
/// difference of vl::compare_images; rubric_scene::metric says which decides.
#include <filesystem>
#include <set>
#include <string>

#include "rubric.hh"
#include "sandbox.hh"

namespace vl::grader {

/// \brief How a rendered scene compares with the reference.
struct scene_outcome {
    bool rendered = false, matches = false;
    std::string message;                      ///< why it failed, or the comparison's numbers
    std::filesystem::path image;              ///< the student's render (re-encoded by the grader)
    std::filesystem::path flip_map;           ///< the FLIP error of each pixel, colour-mapped (magma)
    std::filesystem::path highlight;          ///< ImageMagick's highlighted difference, else the grader's own
    double flip_mean = 0, mean_abs = 0;       ///< the two measures, when rendered at the right size
    double seconds = 0;
};

/// \brief One render program of a submission (build_submission.hh): rt with the submitted
/// stage, and the graded stage's oracle less the objects that hold the pieces its scenes
/// grade (oracle.hh).
struct render_program {
    std::filesystem::path program;
    /// The pieces whose reference it does not link (those its scenes grade, and any that
    /// share their code): the submission's in every scene it renders.
    std::set<std::string> withheld_pieces;
};

/// Renders `scene` with `render` (sandboxed; the image comes back through a pipe), keeps
/// the image in `renders` (a folder of the grader's) and compares it with `reference`. The
/// render takes the scene's student_pieces and the pieces it withholds from the submission.
scene_outcome render_and_compare(const render_program& render, const rubric_scene& scene,
                                 const std::filesystem::path& reference, const std::filesystem::path& renders,
                                 const run_limits& limits, const sandbox_capabilities& caps);

}  // namespace vl::grader
