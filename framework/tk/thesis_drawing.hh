#pragma once
/// \file
/// \brief The thesis's way to draw the view: one X request per virtual pixel.

#include <X11/Xlib.h>

#include <cstdint>
#include <span>

#include "zoom_painter.hh"

namespace vl::tk {

/// Draws the whole view as the thesis's vfbDisplay() did, kept so that `-drawing
/// rectangles` can be compared with the image drawing (bench/vfb_redraw): into an
/// off-screen pixmap, for each visible virtual pixel set the foreground colour and draw a
/// point (pixel size 1), a filled rectangle or a filled disk; with `stamp` (the thesis's
/// -pixmap_drawing_on 1) copy a one-bit pixmap of the pixel's shape instead. Then the
/// grid lines, then one copy to the window. Colours are in the visual's pixel format.
void draw_like_thesis(Display* display, Drawable window, int depth, std::span<const std::uint32_t> colors,
                      int buffer_width, int buffer_height, const view& v, const paint_style& style, bool stamp,
                      int screen_width, int screen_height);

}  // namespace vl::tk
