#pragma once
/// \file
/// \brief The render driver: tiles x threads x samples, into any vfb.

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <vector>

#include "vl/registry.hh"
#include "vl/scene.hh"
#include "vl/stats.hh"
#include "vl/vfb.hh"

namespace vl {

/// \brief How to render (not what: that is the scene).
struct render_options {
    int threads = 0;       ///< worker threads; 0 means one per core
    /// Mixed into every pixel's seed (pixel_seed): another seed draws other random samples
    /// of the same image; 0 is the default image.
    std::uint64_t seed = 0;
    int tile_size = 16;    ///< tiles are tile_size x tile_size pixels
    bool progress = true;  ///< a progress bar on stderr, only when it is a terminal and the render takes over a second
    const std::atomic<bool>* cancel = nullptr;  ///< when set and it becomes true, workers stop after their current tile
    /// Called from worker threads after each finished tile with its pixel rectangle
    /// [x0, x1) x [y0, y1); it must be thread-safe and must not block (the Tk widget
    /// marks the rectangle dirty).
    std::function<void(int x0, int y0, int x1, int y1)> on_tile;
};

/// \brief What a render cost.
struct render_stats {
    intersection_counts counts;       ///< summed over all threads
    std::uint64_t primary_rays = 0;   ///< camera rays (pixels x samples)
    double seconds = 0;               ///< wall-clock time
    int threads = 0;                  ///< threads used
    bool cancelled = false;           ///< stopped early by render_options::cancel
    int width = 0;                    ///< image width in pixels
    int height = 0;                   ///< image height in pixels
    /// Intersection and bounding-volume tests per pixel, row by row from the BOTTOM row
    /// (index `x + y * width`, as vfb coordinates): the heat map's data.
    std::vector<std::uint32_t> tests_per_pixel;
};

/// Renders `s` into `out` (its size is the image size; the scene's own size is only a
/// suggestion to whoever made `out`). Each pixel's samples use a seed fixed by the pixel's
/// coordinates, so the image is bit-identical for any thread count and tile size.
/// Throws vl::usage_error when the scene names a piece `types` does not have.
render_stats render(const scene& s, const registry& types, vfb& out, const render_options& options = {});

/// The seed of pixel (x, y): a SplitMix64 hash of its coordinates and of `image_seed`
/// (render_options::seed; Steele, Lea and Flood 2014), so neighbouring pixels get
/// unrelated random sequences.
std::uint64_t pixel_seed(int x, int y, std::uint64_t image_seed = 0);

/// The thesis's `render_to_vfb`: reads `file` and renders it into `out`, choosing the
/// client by the file's extension (`.ray_trace`: ray trace with the scene's tracer).
/// Throws vl::file_error for an unknown extension or a malformed file.
render_stats render_to_vfb(const std::filesystem::path& file, const registry& types, vfb& out,
                           const render_options& options = {});

}  // namespace vl
