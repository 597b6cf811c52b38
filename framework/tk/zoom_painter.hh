#pragma once
/// \file
/// \brief Paints a zoomed view of the frame buffer into 32-bit screen pixels, without X.

#include <cstdint>
#include <span>
#include <vector>

namespace vl::tk {

/// \brief A rectangle of screen or virtual pixels, [x0, x1) x [y0, y1).
struct rect {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    bool empty() const { return x0 >= x1 || y0 >= y1; }
    /// The smallest rectangle holding both (an empty one adds nothing).
    rect united(const rect& r) const;
    /// The part that lies inside `r`.
    rect clipped(const rect& r) const;
};

/// \brief Where the buffer sits on the screen, and how large a virtual pixel is.
///
/// Virtual pixel (x, y) covers screen columns `origin_x + x * pixel_size` and the next
/// pixel_size - 1, and, counting rows **up from the bottom** of the window,
/// `origin_y + y * pixel_size` and the next ones: (0, 0) is at the lower left, as in the
/// thesis, and the view stays anchored at the bottom when the window grows.
struct view {
    int pixel_size = 1;
    int origin_x = 0;
    int origin_y = 0;
};

/// \brief How the virtual pixels look: colours are 32-bit values in the screen's format.
struct paint_style {
    bool grid = false;          ///< a one-pixel line along the top and left of every pixel
    bool disks = false;         ///< each pixel a filled disk on the background
    std::uint32_t background = 0;
    std::uint32_t grid_color = 0;
};

/// The smallest pixel sizes at which a grid and disks can be seen at all, whatever the
/// widget's -grid_on_at and -disk_on_at say (a grid at size 1 or 2 would hide the image).
inline constexpr int min_grid_size = 3, min_disk_size = 4;

/// \brief Paints the screen from a copy of the buffer's colours (one 32-bit value per
/// virtual pixel, bottom row first, as vfb indexes them).
///
/// It writes each screen pixel once, by runs: a virtual pixel becomes a std::fill_n of
/// pixel_size values, and a screen row equal to the one above it (the same virtual row,
/// the same slice of the disk) is one memcpy. This is what makes a full redraw take
/// milliseconds where the thesis's one-X-request-per-pixel drawing took seconds.
class zoom_painter {
public:
    /// Paints the part `area` of a screen of `screen_width` x `screen_height` pixels into
    /// `screen` (top row first, `stride` pixels per row). `colors` holds
    /// `buffer_width * buffer_height` values.
    void paint(std::span<const std::uint32_t> colors, int buffer_width, int buffer_height, const view& v,
               const paint_style& style, std::uint32_t* screen, int stride, int screen_width, int screen_height,
               rect area);

    /// The screen rectangle that virtual pixels `r` cover on a window `screen_height` tall.
    static rect to_screen(const rect& r, const view& v, int screen_height);

private:
    void make_disk(int inner);
    static void paint_plain_row(const std::uint32_t* row, int buffer_width, const view& v, std::uint32_t* out,
                                const rect& area, std::uint32_t background);
    // disk_[j] is the half-open span of columns that row j of the disk covers.
    std::vector<std::pair<int, int>> disk_;
    int disk_inner_ = -1;
    std::vector<int> painted_rows_;
    std::vector<std::uint32_t> cell_mask_, cell_fixed_;
};

/// `a / b` rounded towards minus infinity (b > 0), for screen positions left of the buffer.
constexpr int floor_div(int a, int b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }

}  // namespace vl::tk
