#pragma once
/// \file
/// \brief How far apart two renders are: the check behind the public scenes' reference
/// images (the grader adds perceptual metrics on top).
#include <filesystem>
#include <string>

#include "vl/image_io.hh"
#include "vl/registry.hh"

namespace vl {

/// \brief Per-pixel differences between two images of the same size, in 8-bit levels.
struct image_difference {
    bool same_size = false;       ///< false: nothing else is meaningful
    double mean_abs = 0;          ///< mean absolute difference over all samples
    int max_abs = 0;              ///< largest absolute difference of any sample
    double fraction_over = 0;     ///< fraction of pixels with a sample differing by more than the threshold
    /// One line for a test report: sizes, mean, max and the fraction over the threshold.
    std::string summary;
};

/// Compares `a` and `b` as 8-bit RGB; `threshold` is in 8-bit levels.
image_difference compare_images(const image& a, const image& b, int threshold = 8);

/// True when a render matches its reference closely enough that only round-off differs:
/// mean difference under 0.5 levels and under 0.5% of pixels more than 8 levels apart
/// (edges may move by a pixel when a compiler contracts a multiply-add differently).
bool renders_match(const image_difference& d);

/// Renders `scene_file` with the pieces in `types` (the scene's own size and samples) and
/// compares it with the PNG `reference`. The stages' public tests pass every piece their
/// build links (vl::all_pieces(), pieces/all_pieces.hh).
image_difference compare_render(const std::filesystem::path& scene_file, const std::filesystem::path& reference,
                                const registry& types);

}  // namespace vl
