// The vfb widget's screen colours and redisplay: the cache of the buffer's pixels (and of
// the heat map) as 32-bit screen values, the requests that collect damage for the idle
// redraw (display_widget, in vfb_widget.cc), the paint style of the current zoom, and the
// two view changes, zooming about a point and keeping the buffer in sight.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "vfb_widget_internal.hh"
#include "vl/heat_map.hh"

namespace vl::tk::widget_internal {
namespace {

std::uint32_t pack_linear(const widget* w, double r, double g, double b) {
    return w->frame->pack(linear_to_srgb8(r), linear_to_srgb8(g), linear_to_srgb8(b));
}

std::uint32_t pack_xcolor(const widget* w, const XColor* c) {
    return w->frame->pack(static_cast<std::uint8_t>(c->red >> 8), static_cast<std::uint8_t>(c->green >> 8),
                          static_cast<std::uint8_t>(c->blue >> 8));
}

}  // namespace

// Brings the screen colours of virtual pixels `r` up to date with the buffer.
void refresh_colors(widget* w, rect r) {
    vfb& p = *w->pixels;
    r = r.clipped({0, 0, p.width(), p.height()});
    const auto width = static_cast<std::size_t>(p.width());
    if (p.holds<rgb8_storage>()) {  // the default storage keeps sRGB bytes: no conversion
        const auto cells = p.cells<rgb8_storage>();
        for (int y = r.y0; y < r.y1; ++y)
            for (int x = r.x0; x < r.x1; ++x) {
                const std::size_t i = static_cast<std::size_t>(y) * width + static_cast<std::size_t>(x);
                w->colors[i] = w->frame->pack(cells[i].r, cells[i].g, cells[i].b);
            }
        return;
    }
    for (int y = r.y0; y < r.y1; ++y)
        for (int x = r.x0; x < r.x1; ++x) {
            const vfb_pixel px = p.get_pixel(x, y);
            w->colors[static_cast<std::size_t>(y) * width + static_cast<std::size_t>(x)] =
                pack_linear(w, px.r(), px.g(), px.b());
        }
}

// The heat map's colours from the last render's counts, as rt --heatmap draws them.
void refresh_heat_colors(widget* w) {
    w->heat_colors.assign(w->colors.size(), pack_linear(w, 0, 0, 0));
    if (w->tests.size() != w->colors.size()) return;
    const std::uint32_t most = *std::max_element(w->tests.begin(), w->tests.end());
    const bool log_scale = w->options.heat_scale == heat_log;
    for (std::size_t i = 0; i < w->tests.size(); ++i) {
        const color c = heat_color(heat_fraction(w->tests[i], most, log_scale));
        w->heat_colors[i] = pack_linear(w, c.r, c.g, c.b);
    }
}

// Asks for screen pixels `r` to be repainted when Tk is idle (tkSquare's pattern: many
// changes, one redraw).
void schedule_redraw(widget* w, rect r) {
    if (!w->tkwin) return;
    w->damage = w->damage.united(r);
    if (!w->redraw_pending) {
        Tcl_DoWhenIdle(display_widget, w);
        w->redraw_pending = true;
    }
}

void schedule_full_redraw(widget* w) { schedule_redraw(w, {0, 0, screen_width(w), screen_height(w)}); }

void schedule_virtual_redraw(widget* w, rect virtual_pixels) {
    schedule_redraw(w, zoom_painter::to_screen(virtual_pixels, w->v, screen_height(w)));
}

paint_style current_style(const widget* w) {
    const widget_options& o = w->options;
    // The thesis draws the grid and disks when pixel_size is *greater than* -grid_on_at
    // and -disk_on_at.
    return {o.grid_on != 0 && w->v.pixel_size > o.grid_on_at, o.disk_on != 0 && w->v.pixel_size > o.disk_on_at,
            pack_xcolor(w, o.background), pack_xcolor(w, o.grid_color)};
}

// Zooms to `size`, keeping the virtual point under screen point (sx, sy) where it is.
void zoom_about(widget* w, int size, double sx, double sy) {
    view& v = w->v;
    const double up = screen_height(w) - sy;
    const double ux = (sx - v.origin_x) / v.pixel_size, uy = (up - v.origin_y) / v.pixel_size;
    v.origin_x = static_cast<int>(std::lround(sx - ux * size));
    v.origin_y = static_cast<int>(std::lround(up - uy * size));
    v.pixel_size = size;
    schedule_full_redraw(w);
}

// Keeps at least part of the buffer on the screen, however far a drag goes.
void keep_in_view(widget* w) {
    view& v = w->v;
    const int bw = w->pixels->width() * v.pixel_size, bh = w->pixels->height() * v.pixel_size;
    v.origin_x = std::clamp(v.origin_x, std::min(0, 16 - bw), std::max(0, screen_width(w) - 16));
    v.origin_y = std::clamp(v.origin_y, std::min(0, 16 - bh), std::max(0, screen_height(w) - 16));
}

}  // namespace vl::tk::widget_internal
