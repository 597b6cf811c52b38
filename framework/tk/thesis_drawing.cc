#include "thesis_drawing.hh"

#include <algorithm>

namespace vl::tk {

void draw_like_thesis(Display* display, Drawable window, int depth, std::span<const std::uint32_t> colors,
                      int buffer_width, int buffer_height, const view& v, const paint_style& style, bool stamp,
                      int screen_width, int screen_height) {
    const int ps = v.pixel_size;
    const bool grid = style.grid && ps >= min_grid_size;
    const bool disks = style.disks && ps >= min_disk_size;
    const int inset = grid ? 1 : 0, inner = ps - inset;
    const auto sw = static_cast<unsigned>(screen_width), sh = static_cast<unsigned>(screen_height);

    Pixmap canvas = XCreatePixmap(display, window, sw, sh, static_cast<unsigned>(depth));
    GC gc = XCreateGC(display, canvas, 0, nullptr);
    XSetForeground(display, gc, style.background);
    XFillRectangle(display, canvas, gc, 0, 0, sw, sh);

    // The one-bit stamp: ones where the pixel's colour goes, zeros for the background.
    Pixmap shape = None;
    GC shape_gc = nullptr;
    if (stamp && ps > 1) {
        shape = XCreatePixmap(display, window, static_cast<unsigned>(inner), static_cast<unsigned>(inner), 1);
        shape_gc = XCreateGC(display, shape, 0, nullptr);
        XSetForeground(display, shape_gc, 0);
        XFillRectangle(display, shape, shape_gc, 0, 0, static_cast<unsigned>(inner), static_cast<unsigned>(inner));
        XSetForeground(display, shape_gc, 1);
        if (disks)
            XFillArc(display, shape, shape_gc, 0, 0, static_cast<unsigned>(inner), static_cast<unsigned>(inner), 0, 360 * 64);
        else
            XFillRectangle(display, shape, shape_gc, 0, 0, static_cast<unsigned>(inner), static_cast<unsigned>(inner));
        XSetBackground(display, gc, style.background);
    }

    // The visible virtual pixels.
    const int x_first = std::max(0, floor_div(-v.origin_x, ps));
    const int x_last = std::min(buffer_width - 1, floor_div(screen_width - 1 - v.origin_x, ps));
    const int y_first = std::max(0, floor_div(-v.origin_y, ps));
    const int y_last = std::min(buffer_height - 1, floor_div(screen_height - 1 - v.origin_y, ps));
    for (int y = y_first; y <= y_last; ++y) {
        for (int x = x_first; x <= x_last; ++x) {
            const rect r = zoom_painter::to_screen({x, y, x + 1, y + 1}, v, screen_height);
            XSetForeground(display, gc, colors[static_cast<std::size_t>(y) * static_cast<std::size_t>(buffer_width) +
                                               static_cast<std::size_t>(x)]);
            if (ps == 1)
                XDrawPoint(display, canvas, gc, r.x0, r.y0);
            else if (shape != None)
                XCopyPlane(display, shape, canvas, gc, 0, 0, static_cast<unsigned>(inner), static_cast<unsigned>(inner),
                           r.x0 + inset, r.y0 + inset, 1);
            else if (disks)
                XFillArc(display, canvas, gc, r.x0 + inset, r.y0 + inset, static_cast<unsigned>(inner),
                         static_cast<unsigned>(inner), 0, 360 * 64);
            else
                XFillRectangle(display, canvas, gc, r.x0 + inset, r.y0 + inset, static_cast<unsigned>(inner),
                               static_cast<unsigned>(inner));
        }
    }
    if (grid && x_first <= x_last && y_first <= y_last) {
        const rect all = zoom_painter::to_screen({x_first, y_first, x_last + 1, y_last + 1}, v, screen_height);
        XSetForeground(display, gc, style.grid_color);
        for (int x = x_first; x <= x_last; ++x) {
            const int sx = v.origin_x + x * ps;
            XDrawLine(display, canvas, gc, sx, all.y0, sx, all.y1 - 1);
        }
        for (int y = y_first; y <= y_last; ++y) {
            const int sy = screen_height - (v.origin_y + (y + 1) * ps);
            XDrawLine(display, canvas, gc, all.x0, sy, all.x1 - 1, sy);
        }
    }
    XCopyArea(display, canvas, window, gc, 0, 0, sw, sh, 0, 0);
    if (shape != None) {
        XFreeGC(display, shape_gc);
        XFreePixmap(display, shape);
    }
    XFreeGC(display, gc);
    XFreePixmap(display, canvas);
}

}  // namespace vl::tk
