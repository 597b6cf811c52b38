#pragma once
/// \file
/// \brief A render running in a background thread, watched by the widget's timer.

#include <atomic>
#include <utility>
#include <filesystem>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "vl/registry.hh"
#include "vl/render.hh"
#include "vl/scene.hh"
#include "vl/vfb.hh"
#include "zoom_painter.hh"

namespace vl::tk {

/// \brief One `render FILE` of the widget: the thesis's render_to_vfb, in a thread.
///
/// The render thread never calls Tcl or X: that is what keeps the user interface alive
/// and the shutdown simple. It renders into a buffer of its own and, after each tile,
/// appends the tile's rectangle to a list guarded by a mutex. The widget's timer, in the
/// Tcl thread, takes that list (take_finished_tiles), copies those tiles out of pixels()
/// and redraws them. A finished tile is never written again, so reading it while the
/// workers fill other tiles is safe; the mutex orders the writes before the read.
class render_job {
public:
    /// Reads the scene at once with the pieces in `pieces` (so a bad file is an error of the
    /// `render` command, with its FILE:LINE:COL) and starts rendering it at `width` x
    /// `height` into a buffer in `storage`. Throws vl::file_error for a file render_to_vfb
    /// cannot render. The job keeps its own copy of `pieces`.
    render_job(const registry& pieces, const std::filesystem::path& file, int width, int height,
               std::string_view storage);
    /// Cancels and joins the thread.
    ~render_job();
    render_job(const render_job&) = delete;
    render_job& operator=(const render_job&) = delete;

    /// Asks the workers to stop after their current tile and waits for them.
    void cancel();
    /// True once the thread has finished (rendered, cancelled or failed); then the thread
    /// is joined and stats() and error() may be read.
    bool finished();
    /// Tiles finished since the last call, in virtual pixels.
    std::vector<rect> take_finished_tiles();
    /// Fraction of the pixels rendered so far, 0 to 1.
    double fraction() const;
    /// The render's own buffer: read only the tiles take_finished_tiles() returned.
    const vfb& pixels() const { return pixels_; }
    /// What the render cost (after finished()).
    const render_stats& stats() const { return stats_; }
    /// Why the render failed, or empty (after finished()).
    const std::string& error() const { return error_; }
    /// The file being rendered.
    const std::filesystem::path& file() const { return file_; }

private:
    void run();

    std::filesystem::path file_;
    registry types_;
    scene scene_;
    vfb pixels_;
    std::atomic<bool> cancel_{false};
    std::atomic<bool> done_{false};
    std::atomic<long long> pixels_done_{0};
    std::mutex mutex_;  // guards finished_tiles_
    std::vector<rect> finished_tiles_;
    render_stats stats_;
    std::string error_;
    std::thread thread_;
};

}  // namespace vl::tk
