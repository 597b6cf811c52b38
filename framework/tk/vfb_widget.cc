// The vfb widget, in the shape of Tk's example widget tkSquare.c: an option table, one
// command procedure that dispatches the widget's subcommands, redisplay deferred to an
// idle handler, and destruction through Tcl_EventuallyFree so that no command or callback
// still running can see freed memory. What is new beside that file is the render: a
// background thread (render_job) watched by a 16 ms timer.
#include "vfb_widget.hh"

#include <tk.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <memory>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "render_job.hh"
#include "thesis_drawing.hh"
#include "vl/heat_map.hh"
#include "vl/vfb.hh"
#include "x_frame.hh"
#include "zoom_painter.hh"

extern "C" const char vfb_bindings_script[];  // vfb_bindings.tcl, compiled in

namespace vl::tk {
namespace {

constexpr int max_pixel_size = 256;
constexpr int render_poll_ms = 16;  // one frame at 60 Hz

// The option record Tk fills in. It is kept apart from the widget so that it stays a
// standard-layout struct, which offsetof (and so Tk_OptionSpec) needs.
struct widget_options {
    int width = 0, height = 0;  // window size in screen pixels; 0 means the buffer's size
    int max_x = 0, max_y = 0;
    Tcl_Obj* storage = nullptr;
    int grid_on = 1, grid_on_at = 7, disk_on = 1, disk_on_at = 7;
    int pixmap_drawing_on = 1, pm_width = 2560, pm_height = 2048;
    XColor* background = nullptr;
    XColor* grid_color = nullptr;
    int view = 0;     // index into view_names
    int drawing = 0;  // index into drawing_names
    int heat_scale = 0;  // index into heat_scale_names
    Tcl_Obj* progress_command = nullptr;
    Tcl_Obj* inspect_command = nullptr;
    Tk_Cursor cursor = nullptr;
};

const char* const view_names[] = {"color", "heat", nullptr};
const char* const drawing_names[] = {"image", "rectangles", nullptr};
const char* const heat_scale_names[] = {"linear", "log", nullptr};
enum { view_color, view_heat };
enum { drawing_image, drawing_rectangles };
enum { heat_linear, heat_log };

// typeMask bits: what a change of the option requires.
enum : int { buffer_changed = 1, geometry_changed = 2, look_changed = 4, heat_changed = 8 };

#define VFB_OPTION(field) static_cast<int>(offsetof(widget_options, field))

// The thesis's options first, with its defaults (User's Manual, "vfb Widget
// Configuration Options"), then the standard and new ones.
const Tk_OptionSpec option_specs[] = {
    {TK_OPTION_INT, "-grid_on", "gridOn", "GridOn", "1", -1, VFB_OPTION(grid_on), 0, nullptr, look_changed},
    {TK_OPTION_INT, "-grid_on_at", "gridOnAt", "GridOnAt", "7", -1, VFB_OPTION(grid_on_at), 0, nullptr, look_changed},
    {TK_OPTION_INT, "-disk_on", "diskOn", "DiskOn", "1", -1, VFB_OPTION(disk_on), 0, nullptr, look_changed},
    {TK_OPTION_INT, "-disk_on_at", "diskOnAt", "DiskOnAt", "7", -1, VFB_OPTION(disk_on_at), 0, nullptr, look_changed},
    {TK_OPTION_INT, "-pixmap_drawing_on", "pixmapDrawingOn", "PixmapDrawingOn", "1", -1,
     VFB_OPTION(pixmap_drawing_on), 0, nullptr, look_changed},
    {TK_OPTION_INT, "-pm_width", "pmWidth", "PmWidth", "2560", -1, VFB_OPTION(pm_width), 0, nullptr, 0},
    {TK_OPTION_INT, "-pm_height", "pmHeight", "PmHeight", "2048", -1, VFB_OPTION(pm_height), 0, nullptr, 0},
    {TK_OPTION_INT, "-maxx", "maxX", "MaxX", "299", -1, VFB_OPTION(max_x), 0, nullptr, buffer_changed | geometry_changed},
    {TK_OPTION_INT, "-maxy", "maxY", "MaxY", "299", -1, VFB_OPTION(max_y), 0, nullptr, buffer_changed | geometry_changed},
    {TK_OPTION_STRING, "-storage", "storage", "Storage", "rgb8", VFB_OPTION(storage), -1, 0, nullptr, buffer_changed},
    {TK_OPTION_PIXELS, "-width", "width", "Width", "0", -1, VFB_OPTION(width), 0, nullptr, geometry_changed},
    {TK_OPTION_PIXELS, "-height", "height", "Height", "0", -1, VFB_OPTION(height), 0, nullptr, geometry_changed},
    {TK_OPTION_COLOR, "-background", "background", "Background", "#000000", -1, VFB_OPTION(background), 0, nullptr,
     look_changed},
    {TK_OPTION_SYNONYM, "-bg", nullptr, nullptr, nullptr, 0, -1, 0, "-background", 0},
    {TK_OPTION_COLOR, "-grid_color", "gridColor", "GridColor", "#4d4d4d", -1, VFB_OPTION(grid_color), 0, nullptr,
     look_changed},
    {TK_OPTION_STRING_TABLE, "-view", "view", "View", "color", -1, VFB_OPTION(view), 0, view_names, look_changed},
    {TK_OPTION_STRING_TABLE, "-drawing", "drawing", "Drawing", "image", -1, VFB_OPTION(drawing), 0, drawing_names,
     look_changed},
    {TK_OPTION_STRING_TABLE, "-heatscale", "heatScale", "HeatScale", "linear", -1, VFB_OPTION(heat_scale), 0,
     heat_scale_names, heat_changed},
    {TK_OPTION_STRING, "-progresscommand", "progressCommand", "Command", "", VFB_OPTION(progress_command), -1,
     TK_OPTION_NULL_OK, nullptr, 0},
    {TK_OPTION_STRING, "-inspectcommand", "inspectCommand", "Command", "", VFB_OPTION(inspect_command), -1,
     TK_OPTION_NULL_OK, nullptr, 0},
    {TK_OPTION_CURSOR, "-cursor", "cursor", "Cursor", "crosshair", -1, VFB_OPTION(cursor), TK_OPTION_NULL_OK, nullptr,
     0},
    {TK_OPTION_END, nullptr, nullptr, nullptr, nullptr, 0, -1, 0, nullptr, 0},
};

#undef VFB_OPTION

// The state of the last render, for `progress`.
struct render_report {
    std::string state = "idle";  // idle, running, done, cancelled, failed
    std::string file, message;
    double seconds = 0;
    double fraction = 0;  // of the pixels, when it stopped
};

// One widget. Owned by Tcl's preserve mechanism: created with new in create_command,
// deleted by free_widget once nothing preserves it.
struct widget {
    widget_options options;
    Tk_Window tkwin = nullptr;  // nullptr once the window is destroyed
    Display* display = nullptr;
    Tcl_Interp* interp = nullptr;
    Tcl_Command command = nullptr;
    Tk_OptionTable option_table = nullptr;

    std::unique_ptr<vfb> pixels;
    std::vector<std::uint32_t> colors;       // pixels as screen colours, vfb order
    std::vector<std::uint32_t> tests;        // the last render's tests per pixel, or empty
    std::vector<std::uint32_t> heat_colors;  // tests as screen colours

    view v;
    zoom_painter painter;
    std::unique_ptr<x_frame> frame;
    GC gc = nullptr;
    bool redraw_pending = false;
    rect damage;  // screen pixels to repaint at the next redraw

    std::shared_ptr<const registry> pieces;  // what `render` renders with (vfb_init's)
    std::unique_ptr<render_job> job;
    Tcl_TimerToken timer = nullptr;
    bool exit_handler = false;
    render_report report;
};

void display_widget(ClientData data);
void stop_render(widget* w);
void copy_finished_tiles(widget* w);

int screen_width(const widget* w) { return Tk_IsMapped(w->tkwin) ? Tk_Width(w->tkwin) : Tk_ReqWidth(w->tkwin); }
int screen_height(const widget* w) { return Tk_IsMapped(w->tkwin) ? Tk_Height(w->tkwin) : Tk_ReqHeight(w->tkwin); }

// A linear colour as Tk writes it, "#rrggbb" in sRGB.
Tcl_Obj* srgb_hex(double r, double g, double b) {
    char hex[8];
    std::snprintf(hex, sizeof hex, "#%02x%02x%02x", linear_to_srgb8(r), linear_to_srgb8(g), linear_to_srgb8(b));
    return Tcl_NewStringObj(hex, -1);
}

int set_error(Tcl_Interp* interp, const std::string& message) {
    Tcl_SetObjResult(interp, Tcl_NewStringObj(message.c_str(), -1));
    return TCL_ERROR;
}

// ---- colours and redisplay ----

std::uint32_t pack_linear(const widget* w, double r, double g, double b) {
    return w->frame->pack(linear_to_srgb8(r), linear_to_srgb8(g), linear_to_srgb8(b));
}

std::uint32_t pack_xcolor(const widget* w, const XColor* c) {
    return w->frame->pack(static_cast<std::uint8_t>(c->red >> 8), static_cast<std::uint8_t>(c->green >> 8),
                          static_cast<std::uint8_t>(c->blue >> 8));
}

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

void display_widget(ClientData data) {
    auto* w = static_cast<widget*>(data);
    w->redraw_pending = false;
    const rect area = std::exchange(w->damage, {});
    if (!w->tkwin || !Tk_IsMapped(w->tkwin)) return;
    const int sw = Tk_Width(w->tkwin), sh = Tk_Height(w->tkwin);
    const std::vector<std::uint32_t>& colors = w->options.view == view_heat ? w->heat_colors : w->colors;
    const paint_style style = current_style(w);
    if (w->options.drawing == drawing_rectangles || !w->frame->supported()) {
        draw_like_thesis(w->display, Tk_WindowId(w->tkwin), Tk_Depth(w->tkwin), colors, w->pixels->width(),
                         w->pixels->height(), w->v, style, w->options.pixmap_drawing_on != 0, sw, sh);
        return;
    }
    rect todo = area;
    if (w->frame->width() != sw || w->frame->height() != sh) {
        w->frame->resize(sw, sh);
        todo = {0, 0, sw, sh};  // a new image holds nothing yet
    }
    if (!w->gc) {
        XGCValues values;
        values.graphics_exposures = False;
        w->gc = Tk_GetGC(w->tkwin, GCGraphicsExposures, &values);
    }
    w->painter.paint(colors, w->pixels->width(), w->pixels->height(), w->v, style, w->frame->pixels(),
                     w->frame->width(), sw, sh, todo);
    w->frame->put(Tk_WindowId(w->tkwin), w->gc, todo);
}

// ---- the view ----

void request_geometry(widget* w) {
    // Without -width or -height the window fits the buffer at pixel size 1; zooming
    // changes what the window shows, not its size.
    const int width = w->options.width > 0 ? w->options.width : w->pixels->width();
    const int height = w->options.height > 0 ? w->options.height : w->pixels->height();
    Tk_GeometryRequest(w->tkwin, std::min(width, 32767), std::min(height, 32767));
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

// ---- configuration ----

// Applies the options after Tk_SetOptions; on error the caller restores the old ones.
int apply_options(Tcl_Interp* interp, widget* w, int mask) {
    const widget_options& o = w->options;
    for (const auto& [name, value, least] : {std::tuple{"-grid_on_at", o.grid_on_at, 0},
                                            std::tuple{"-disk_on_at", o.disk_on_at, 0},
                                            std::tuple{"-pm_width", o.pm_width, 1},
                                            std::tuple{"-pm_height", o.pm_height, 1},
                                            std::tuple{"-maxx", o.max_x, 0}, std::tuple{"-maxy", o.max_y, 0},
                                            std::tuple{"-width", o.width, 0}, std::tuple{"-height", o.height, 0}})
        if (value < least)
            return set_error(interp, std::string("vfb: ") + name + " must be " + std::to_string(least) +
                                         " or more, not " + std::to_string(value));
    if ((mask & buffer_changed) || !w->pixels) {
        if (w->job) return set_error(interp, "vfb: cannot change -maxx, -maxy or -storage while a render runs (cancel it first)");
        try {
            auto fresh = std::make_unique<vfb>(o.max_x, o.max_y, Tcl_GetString(o.storage));
            w->pixels = std::move(fresh);
        } catch (const std::exception& e) {
            return set_error(interp, std::string("vfb: ") + e.what());
        }
        w->colors.assign(static_cast<std::size_t>(w->pixels->width()) * static_cast<std::size_t>(w->pixels->height()), 0);
        w->tests.clear();
    }
    return TCL_OK;
}

int configure(Tcl_Interp* interp, widget* w, int objc, Tcl_Obj* const objv[]) {
    Tk_SavedOptions saved;
    int mask = 0;
    if (Tk_SetOptions(interp, reinterpret_cast<char*>(&w->options), w->option_table, objc, objv, w->tkwin, &saved,
                      &mask) != TCL_OK)
        return TCL_ERROR;
    const bool new_buffer = (mask & buffer_changed) || !w->pixels;
    if (apply_options(interp, w, mask) != TCL_OK) {
        Tk_RestoreSavedOptions(&saved);
        return TCL_ERROR;
    }
    Tk_FreeSavedOptions(&saved);
    if (new_buffer) refresh_colors(w, {0, 0, w->pixels->width(), w->pixels->height()});
    if (new_buffer || (mask & heat_changed)) refresh_heat_colors(w);
    if (new_buffer || (mask & geometry_changed)) request_geometry(w);
    schedule_full_redraw(w);
    return TCL_OK;
}

// ---- the render ----

// Calls -progresscommand with the progress dictionary appended, at global level.
void call_script_option(widget* w, Tcl_Obj* script, Tcl_Obj* argument) {
    Tcl_IncrRefCount(argument);
    if (script && Tcl_GetCharLength(script) > 0) {
        Tcl_Obj* call = Tcl_DuplicateObj(script);
        Tcl_IncrRefCount(call);
        if (Tcl_ListObjAppendElement(w->interp, call, argument) != TCL_OK ||
            Tcl_EvalObjEx(w->interp, call, TCL_EVAL_GLOBAL) != TCL_OK)
            Tcl_BackgroundException(w->interp, TCL_ERROR);
        Tcl_DecrRefCount(call);
    }
    Tcl_DecrRefCount(argument);
}

Tcl_Obj* progress_dict(const widget* w) {
    Tcl_Obj* d = Tcl_NewDictObj();
    auto put = [&](const char* key, Tcl_Obj* value) { Tcl_DictObjPut(nullptr, d, Tcl_NewStringObj(key, -1), value); };
    const double fraction = w->job ? w->job->fraction() : w->report.fraction;
    put("state", Tcl_NewStringObj(w->report.state.c_str(), -1));
    put("fraction", Tcl_NewDoubleObj(fraction));
    put("seconds", Tcl_NewDoubleObj(w->report.seconds));
    put("file", Tcl_NewStringObj(w->report.file.c_str(), -1));
    put("message", Tcl_NewStringObj(w->report.message.c_str(), -1));
    return d;
}

void exit_during_render(ClientData data) {
    // `exit` while rendering: stop the workers before the process tears down what they use.
    auto* w = static_cast<widget*>(data);
    w->exit_handler = false;
    if (w->job) w->job->cancel();
}

// Copies tiles the render finished into the widget's buffer and marks them for redraw.
void copy_finished_tiles(widget* w) {
    for (const rect& r : w->job->take_finished_tiles()) {
        const vfb& from = w->job->pixels();
        image tile(r.x1 - r.x0, r.y1 - r.y0, 3, sample_type::f32);
        for (int y = r.y0; y < r.y1; ++y) {
            float* row = tile.row<float>(r.y1 - 1 - y).data();  // image rows run top to bottom
            for (int x = r.x0; x < r.x1; ++x, row += 3) {
                const vfb_pixel p = from.get_pixel(x, y);
                row[0] = static_cast<float>(p.r()), row[1] = static_cast<float>(p.g()), row[2] = static_cast<float>(p.b());
            }
        }
        w->pixels->from_image(tile, r.x0, r.y0);  // replaces, whatever the storage's z rule
        refresh_colors(w, r);
        if (w->options.view == view_color) schedule_virtual_redraw(w, r);
    }
}

// Ends the render (finished or cancelled): last tiles, statistics, report.
void stop_render(widget* w) {
    if (!w->job) return;
    w->job->cancel();  // a no-op when it has finished; joins the thread either way
    copy_finished_tiles(w);
    const render_stats& st = w->job->stats();
    w->report.seconds = st.seconds;
    w->report.fraction = w->job->fraction();
    w->report.message = w->job->error();
    w->report.state = !w->report.message.empty() ? "failed" : st.cancelled ? "cancelled" : "done";
    if (w->report.state == "done" && st.tests_per_pixel.size() == w->colors.size()) {
        w->tests = st.tests_per_pixel;
        refresh_heat_colors(w);
        if (w->options.view == view_heat) schedule_full_redraw(w);
    }
    w->job.reset();
    if (w->timer) Tcl_DeleteTimerHandler(w->timer);
    w->timer = nullptr;
    if (w->exit_handler) Tcl_DeleteExitHandler(exit_during_render, w);
    w->exit_handler = false;
}

void watch_render(ClientData data) {
    auto* w = static_cast<widget*>(data);
    w->timer = nullptr;
    if (!w->job) return;
    copy_finished_tiles(w);
    if (w->job->finished())
        stop_render(w);
    else
        w->timer = Tcl_CreateTimerHandler(render_poll_ms, watch_render, w);
    Tcl_Preserve(w);  // the progress command may destroy the widget
    call_script_option(w, w->options.progress_command, progress_dict(w));
    Tcl_Release(w);
}

// ---- the subcommands ----

using subcommand = int (*)(widget*, Tcl_Interp*, int, Tcl_Obj* const[]);

int wrong_args(Tcl_Interp* interp, Tcl_Obj* const objv[], const char* message) {
    Tcl_WrongNumArgs(interp, 2, objv, *message ? message : nullptr);
    return TCL_ERROR;
}

int get_ints(Tcl_Interp* interp, Tcl_Obj* const objv[], int n, int* out) {
    for (int k = 0; k < n; ++k)
        if (Tcl_GetIntFromObj(interp, objv[k], &out[k]) != TCL_OK) return TCL_ERROR;
    return TCL_OK;
}

int refuse_while_rendering(widget* w, Tcl_Interp* interp, const char* what) {
    if (!w->job) return TCL_OK;
    return set_error(interp, std::string(what) + ": a render is running (use cancel or wait first)");
}

int cmd_set_min(widget* w, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[], bool horizontal) {
    if (objc > 3) return wrong_args(interp, objv, "?vfb_coordinate?");
    int& origin = horizontal ? w->v.origin_x : w->v.origin_y;
    const int size = horizontal ? w->pixels->width() : w->pixels->height();
    if (objc == 3) {
        int m = 0;
        if (Tcl_GetIntFromObj(interp, objv[2], &m) != TCL_OK) return TCL_ERROR;
        if (m < -size || m >= size)
            return set_error(interp, std::string(Tcl_GetString(objv[1])) + ": " + std::to_string(m) + " is outside " +
                                         std::to_string(-size) + ".." + std::to_string(size - 1));
        origin = -m * w->v.pixel_size;
        schedule_full_redraw(w);
    }
    Tcl_SetObjResult(interp, Tcl_NewIntObj(floor_div(-origin, w->v.pixel_size)));
    return TCL_OK;
}
int cmd_set_min_x(widget* w, Tcl_Interp* i, int c, Tcl_Obj* const v[]) { return cmd_set_min(w, i, c, v, true); }
int cmd_set_min_y(widget* w, Tcl_Interp* i, int c, Tcl_Obj* const v[]) { return cmd_set_min(w, i, c, v, false); }

int cmd_virtual_x(widget* w, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
    if (objc != 3) return wrong_args(interp, objv, "tk_x");
    int x = 0;
    if (Tk_GetPixelsFromObj(interp, w->tkwin, objv[2], &x) != TCL_OK) return TCL_ERROR;
    Tcl_SetObjResult(interp, Tcl_NewIntObj(floor_div(x - w->v.origin_x, w->v.pixel_size)));
    return TCL_OK;
}

int cmd_virtual_y(widget* w, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
    if (objc != 3) return wrong_args(interp, objv, "tk_y");
    int y = 0;
    if (Tk_GetPixelsFromObj(interp, w->tkwin, objv[2], &y) != TCL_OK) return TCL_ERROR;
    Tcl_SetObjResult(interp, Tcl_NewIntObj(floor_div(screen_height(w) - 1 - y - w->v.origin_y, w->v.pixel_size)));
    return TCL_OK;
}

int cmd_get_pixel(widget* w, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
    if (objc != 4) return wrong_args(interp, objv, "vfb_x vfb_y");
    int xy[2];
    if (get_ints(interp, objv + 2, 2, xy) != TCL_OK) return TCL_ERROR;
    try {
        const vfb_pixel p = w->pixels->get_pixel(xy[0], xy[1]);
        Tcl_Obj* rgb[3] = {Tcl_NewDoubleObj(p.r()), Tcl_NewDoubleObj(p.g()), Tcl_NewDoubleObj(p.b())};
        Tcl_SetObjResult(interp, Tcl_NewListObj(3, rgb));
        return TCL_OK;
    } catch (const std::exception& e) {
        return set_error(interp, std::string("get_pixel: ") + e.what());
    }
}

int cmd_put_pixel(widget* w, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
    if (objc != 8) return wrong_args(interp, objv, "vfb_x vfb_y z r g b");
    int xy[2];
    double zrgb[4];
    if (get_ints(interp, objv + 2, 2, xy) != TCL_OK) return TCL_ERROR;
    for (int k = 0; k < 4; ++k)
        if (Tcl_GetDoubleFromObj(interp, objv[4 + k], &zrgb[k]) != TCL_OK) return TCL_ERROR;
    try {
        w->pixels->put_pixel(xy[0], xy[1], vfb_pixel(zrgb[0], zrgb[1], zrgb[2], zrgb[3]));
    } catch (const std::exception& e) {
        return set_error(interp, std::string("put_pixel: ") + e.what());
    }
    const rect r{xy[0], xy[1], xy[0] + 1, xy[1] + 1};
    refresh_colors(w, r);
    schedule_virtual_redraw(w, r);
    return TCL_OK;
}

int cmd_pixel_size(widget* w, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
    if (objc > 3) return wrong_args(interp, objv, "?size?");
    if (objc == 3) {
        int size = 0;
        if (Tk_GetPixelsFromObj(interp, w->tkwin, objv[2], &size) != TCL_OK) return TCL_ERROR;
        if (size < 1 || size > max_pixel_size)
            return set_error(interp, "pixel_size: " + std::to_string(size) + " is outside 1.." + std::to_string(max_pixel_size));
        // As in the thesis, the lowest row and leftmost column shown stay where they are.
        const int min_x = floor_div(-w->v.origin_x, w->v.pixel_size), min_y = floor_div(-w->v.origin_y, w->v.pixel_size);
        w->v = {size, -min_x * size, -min_y * size};
        schedule_full_redraw(w);
    }
    Tcl_SetObjResult(interp, Tcl_NewIntObj(w->v.pixel_size));
    return TCL_OK;
}

int cmd_zoom(widget* w, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
    if (objc != 3 && objc != 5) return wrong_args(interp, objv, "size ?tk_x tk_y?");
    int size = 0;
    if (Tk_GetPixelsFromObj(interp, w->tkwin, objv[2], &size) != TCL_OK) return TCL_ERROR;
    if (size < 1 || size > max_pixel_size)
        return set_error(interp, "zoom: " + std::to_string(size) + " is outside 1.." + std::to_string(max_pixel_size));
    double at[2] = {screen_width(w) / 2.0, screen_height(w) / 2.0};
    for (int k = 0; objc == 5 && k < 2; ++k)
        if (Tcl_GetDoubleFromObj(interp, objv[3 + k], &at[k]) != TCL_OK) return TCL_ERROR;
    zoom_about(w, size, at[0], at[1]);
    Tcl_SetObjResult(interp, Tcl_NewIntObj(size));
    return TCL_OK;
}

int cmd_pan(widget* w, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
    if (objc != 4) return wrong_args(interp, objv, "dx dy");
    int d[2];
    if (get_ints(interp, objv + 2, 2, d) != TCL_OK) return TCL_ERROR;
    w->v.origin_x += d[0];
    w->v.origin_y -= d[1];  // screen y grows downwards, virtual y upwards
    keep_in_view(w);
    schedule_full_redraw(w);
    return TCL_OK;
}

int cmd_clear(widget* w, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
    if (objc != 2) return wrong_args(interp, objv, "");
    if (refuse_while_rendering(w, interp, "clear") != TCL_OK) return TCL_ERROR;
    w->pixels->clear();
    w->tests.clear();
    refresh_colors(w, {0, 0, w->pixels->width(), w->pixels->height()});
    refresh_heat_colors(w);
    schedule_full_redraw(w);
    return TCL_OK;
}

int cmd_load(widget* w, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
    if (objc != 3 && objc != 5) return wrong_args(interp, objv, "file ?vfb_x1 vfb_y1?");
    if (refuse_while_rendering(w, interp, "load") != TCL_OK) return TCL_ERROR;
    int at[2] = {0, 0};
    if (objc == 5 && get_ints(interp, objv + 3, 2, at) != TCL_OK) return TCL_ERROR;
    try {
        w->pixels->load(Tcl_GetString(objv[2]), at[0], at[1]);
    } catch (const std::exception& e) {
        return set_error(interp, std::string("load: ") + e.what());
    }
    w->tests.clear();
    refresh_colors(w, {0, 0, w->pixels->width(), w->pixels->height()});
    refresh_heat_colors(w);
    schedule_full_redraw(w);
    return TCL_OK;
}

int cmd_save(widget* w, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
    if (objc != 3) return wrong_args(interp, objv, "file");
    try {
        w->pixels->save(Tcl_GetString(objv[2]));
    } catch (const std::exception& e) {
        return set_error(interp, std::string("save: ") + e.what());
    }
    return TCL_OK;
}

int cmd_render(widget* w, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
    if (objc != 3) return wrong_args(interp, objv, "file");
    if (refuse_while_rendering(w, interp, "render") != TCL_OK) return TCL_ERROR;
    try {
        w->job = std::make_unique<render_job>(*w->pieces, Tcl_GetString(objv[2]), w->pixels->width(), w->pixels->height(),
                                              w->pixels->storage_name());
    } catch (const std::exception& e) {
        return set_error(interp, std::string("render: ") + e.what());
    }
    w->report = {"running", Tcl_GetString(objv[2]), "", 0, 0};
    w->timer = Tcl_CreateTimerHandler(render_poll_ms, watch_render, w);
    Tcl_CreateExitHandler(exit_during_render, w);
    w->exit_handler = true;
    return TCL_OK;
}

int cmd_progress(widget* w, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
    if (objc != 2) return wrong_args(interp, objv, "");
    Tcl_SetObjResult(interp, progress_dict(w));
    return TCL_OK;
}

int cmd_cancel(widget* w, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
    if (objc != 2) return wrong_args(interp, objv, "");
    if (w->job) {
        stop_render(w);
        Tcl_Preserve(w);
        call_script_option(w, w->options.progress_command, progress_dict(w));
        Tcl_Release(w);
    }
    return TCL_OK;
}

int cmd_wait(widget* w, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
    if (objc != 2) return wrong_args(interp, objv, "");
    // The caller preserves w; events (and so the render's timer) run until the render ends.
    while (w->job && w->tkwin) Tcl_DoOneEvent(TCL_ALL_EVENTS);
    if (!w->tkwin) return set_error(interp, "wait: the widget was destroyed during the render");
    if (w->report.state == "failed") return set_error(interp, "render: " + w->report.message);
    Tcl_SetObjResult(interp, progress_dict(w));
    return TCL_OK;
}

// heat_legend ?steps?: what the heat map's legend shows, as a dictionary: min and max, the
// fewest and most tests of a pixel in the last render (both 0 before one); scale, linear or
// log (-heatscale); colors, `steps` (default 64) colours "#rrggbb" from the bottom of the
// scale (0 tests) to the top (max); ticks, five {count fraction} pairs for labels, at 0, a
// quarter, ..., all of the scale, with count the whole number of tests there.
int cmd_heat_legend(widget* w, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
    if (objc != 2 && objc != 3) return wrong_args(interp, objv, "?steps?");
    int steps = 64;
    if (objc == 3 && Tcl_GetIntFromObj(interp, objv[2], &steps) != TCL_OK) return TCL_ERROR;
    if (steps < 2 || steps > 4096)
        return set_error(interp, "heat_legend: steps must be 2 to 4096, not " + std::to_string(steps));
    const bool log_scale = w->options.heat_scale == heat_log;
    std::uint32_t least = 0, most = 0;
    if (!w->tests.empty()) {
        const auto [lo, hi] = std::minmax_element(w->tests.begin(), w->tests.end());
        least = *lo;
        most = *hi;
    }
    Tcl_Obj* colors = Tcl_NewListObj(0, nullptr);
    for (int i = 0; i < steps; ++i) {
        const color c = heat_color(static_cast<double>(i) / (steps - 1));
        Tcl_ListObjAppendElement(nullptr, colors, srgb_hex(c.r, c.g, c.b));
    }
    Tcl_Obj* ticks = Tcl_NewListObj(0, nullptr);
    for (int i = 0; i <= 4; ++i) {
        const double f = i / 4.0;
        Tcl_Obj* pair[2] = {Tcl_NewWideIntObj(heat_count(f, most, log_scale)), Tcl_NewDoubleObj(f)};
        Tcl_ListObjAppendElement(nullptr, ticks, Tcl_NewListObj(2, pair));
    }
    Tcl_Obj* d = Tcl_NewDictObj();
    auto put = [&](const char* key, Tcl_Obj* value) { Tcl_DictObjPut(nullptr, d, Tcl_NewStringObj(key, -1), value); };
    put("min", Tcl_NewWideIntObj(least));
    put("max", Tcl_NewWideIntObj(most));
    put("scale", Tcl_NewStringObj(heat_scale_names[w->options.heat_scale], -1));
    put("colors", colors);
    put("ticks", ticks);
    Tcl_SetObjResult(interp, d);
    return TCL_OK;
}

int cmd_inspect(widget* w, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
    if (objc != 4) return wrong_args(interp, objv, "tk_x tk_y");
    int xy[2];
    for (int k = 0; k < 2; ++k)
        if (Tk_GetPixelsFromObj(interp, w->tkwin, objv[2 + k], &xy[k]) != TCL_OK) return TCL_ERROR;
    const int x = floor_div(xy[0] - w->v.origin_x, w->v.pixel_size);
    const int y = floor_div(screen_height(w) - 1 - xy[1] - w->v.origin_y, w->v.pixel_size);
    Tcl_Obj* d = Tcl_NewDictObj();
    if (w->pixels->contains(x, y)) {
        const vfb_pixel p = w->pixels->get_pixel(x, y);
        const std::size_t i = static_cast<std::size_t>(y) * static_cast<std::size_t>(w->pixels->width()) + static_cast<std::size_t>(x);
        auto put = [&](const char* key, Tcl_Obj* value) { Tcl_DictObjPut(nullptr, d, Tcl_NewStringObj(key, -1), value); };
        put("x", Tcl_NewIntObj(x));
        put("y", Tcl_NewIntObj(y));
        put("r", Tcl_NewDoubleObj(p.r()));
        put("g", Tcl_NewDoubleObj(p.g()));
        put("b", Tcl_NewDoubleObj(p.b()));
        put("srgb", srgb_hex(p.r(), p.g(), p.b()));
        // Intersection and bounding-volume tests for this pixel in the last render, or {}.
        put("tests", i < w->tests.size() ? Tcl_NewWideIntObj(w->tests[i]) : Tcl_NewObj());
    }
    Tcl_SetObjResult(interp, d);
    return TCL_OK;
}

int cmd_redraw(widget* w, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
    if (objc != 2) return wrong_args(interp, objv, "");
    // Paints the whole window now and waits for the X server: what bench/vfb_redraw times.
    if (w->redraw_pending) Tcl_CancelIdleCall(display_widget, w);
    w->redraw_pending = false;
    w->damage = {0, 0, screen_width(w), screen_height(w)};
    display_widget(w);
    XSync(w->display, False);
    return TCL_OK;
}

int cmd_cget(widget* w, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
    if (objc != 3) return wrong_args(interp, objv, "option");
    Tcl_Obj* value = Tk_GetOptionValue(interp, reinterpret_cast<char*>(&w->options), w->option_table, objv[2], w->tkwin);
    if (!value) return TCL_ERROR;
    Tcl_SetObjResult(interp, value);
    return TCL_OK;
}

int cmd_configure(widget* w, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
    if (objc <= 3) {
        Tcl_Obj* info = Tk_GetOptionInfo(interp, reinterpret_cast<char*>(&w->options), w->option_table,
                                         objc == 3 ? objv[2] : nullptr, w->tkwin);
        if (!info) return TCL_ERROR;
        Tcl_SetObjResult(interp, info);
        return TCL_OK;
    }
    return configure(interp, w, objc - 2, objv + 2);
}

// The subcommands, sorted: the thesis's, then configure/cget, then the new ones.
struct named_subcommand {
    const char* name;
    subcommand run;
};
const named_subcommand subcommands[] = {
    {"cancel", cmd_cancel},       {"cget", cmd_cget},         {"clear", cmd_clear},
    {"configure", cmd_configure}, {"get_pixel", cmd_get_pixel}, {"heat_legend", cmd_heat_legend},
    {"inspect", cmd_inspect},
    {"load", cmd_load},           {"pan", cmd_pan},           {"pixel_size", cmd_pixel_size},
    {"progress", cmd_progress},   {"put_pixel", cmd_put_pixel}, {"redraw", cmd_redraw},
    {"render", cmd_render},       {"save", cmd_save},         {"set_min_x", cmd_set_min_x},
    {"set_min_y", cmd_set_min_y}, {"virtual_x", cmd_virtual_x}, {"virtual_y", cmd_virtual_y},
    {"wait", cmd_wait},           {"zoom", cmd_zoom},         {nullptr, nullptr},
};

// The thesis's vfbWidgetCmd(): one procedure for every subcommand.
int widget_command(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
    auto* w = static_cast<widget*>(data);
    if (objc < 2) {
        Tcl_WrongNumArgs(interp, 1, objv, "option ?arg ...?");
        return TCL_ERROR;
    }
    int index = 0;
    if (Tcl_GetIndexFromObjStruct(interp, objv[1], subcommands, sizeof(named_subcommand), "option", 0, &index) != TCL_OK)
        return TCL_ERROR;
    Tcl_Preserve(w);
    int result = TCL_OK;
    if (!w->tkwin) {
        result = set_error(interp, "vfb: the widget has been destroyed");
    } else {
        try {
            result = subcommands[index].run(w, interp, objc, objv);
        } catch (const std::exception& e) {  // e.g. out of memory: an error, never a crash
            result = set_error(interp, std::string(Tcl_GetString(objv[1])) + ": " + e.what());
        }
    }
    Tcl_Release(w);
    return result;
}

// ---- life and death ----

void free_widget(char* data) {
    auto* w = reinterpret_cast<widget*>(data);
    delete w;
}

void event_proc(ClientData data, XEvent* event) {
    auto* w = static_cast<widget*>(data);
    switch (event->type) {
    case Expose:
        schedule_redraw(w, {event->xexpose.x, event->xexpose.y, event->xexpose.x + event->xexpose.width,
                            event->xexpose.y + event->xexpose.height});
        break;
    case ConfigureNotify:
        keep_in_view(w);
        schedule_full_redraw(w);
        break;
    case DestroyNotify:
        if (w->tkwin) {
            // The thesis's known problem 3 was a crash here. Order matters: stop the render
            // thread, then free the X resources while the display is open, then forget the
            // window and the command; the memory goes when nothing preserves it any more.
            stop_render(w);
            w->frame.reset();
            if (w->gc) Tk_FreeGC(w->display, w->gc);
            w->gc = nullptr;
            Tk_FreeConfigOptions(reinterpret_cast<char*>(&w->options), w->option_table, w->tkwin);
            w->tkwin = nullptr;
            Tcl_DeleteCommandFromToken(w->interp, w->command);
        }
        if (w->redraw_pending) Tcl_CancelIdleCall(display_widget, w);
        w->redraw_pending = false;
        Tcl_EventuallyFree(w, free_widget);
        break;
    default:
        break;
    }
}

// `rename .v {}` or deleting the interpreter: destroy the window, which does the rest.
void command_deleted(ClientData data) {
    auto* w = static_cast<widget*>(data);
    if (w->tkwin) Tk_DestroyWindow(w->tkwin);
}

// `vfb pathName ?-option value ...?`
// `data` is the registry vfb_init made, shared by every widget it creates.
int create_command(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
    if (objc < 2) {
        Tcl_WrongNumArgs(interp, 1, objv, "pathName ?-option value ...?");
        return TCL_ERROR;
    }
    Tk_Window main_window = Tk_MainWindow(interp);
    if (!main_window) return TCL_ERROR;
    Tk_Window tkwin = Tk_CreateWindowFromPath(interp, main_window, Tcl_GetString(objv[1]), nullptr);
    if (!tkwin) return TCL_ERROR;
    Tk_SetClass(tkwin, "Vfb");

    auto* w = new widget;
    w->pieces = *static_cast<const std::shared_ptr<const registry>*>(data);
    w->tkwin = tkwin;
    w->display = Tk_Display(tkwin);
    w->interp = interp;
    w->option_table = Tk_CreateOptionTable(interp, option_specs);
    w->frame = std::make_unique<x_frame>(w->display, Tk_Visual(tkwin), Tk_Depth(tkwin));
    w->command = Tcl_CreateObjCommand(interp, Tk_PathName(tkwin), widget_command, w, command_deleted);
    Tk_CreateEventHandler(tkwin, ExposureMask | StructureNotifyMask, event_proc, w);
    Tk_SetWindowBackgroundPixmap(tkwin, None);  // we paint every pixel: no flash of background

    if (Tk_InitOptions(interp, reinterpret_cast<char*>(&w->options), w->option_table, tkwin) != TCL_OK ||
        configure(interp, w, objc - 2, objv + 2) != TCL_OK) {
        Tk_DestroyWindow(tkwin);
        return TCL_ERROR;
    }
    Tcl_SetObjResult(interp, Tcl_NewStringObj(Tk_PathName(tkwin), -1));
    return TCL_OK;
}

}  // namespace

int vfb_init(Tcl_Interp* interp, void (*register_pieces)(registry&)) {
    if (!Tcl_InitStubs(interp, "8.6", 0) || !Tk_InitStubs(interp, "8.6", 0)) return TCL_ERROR;
    // The registry lives as long as the `vfb` command; each widget keeps it too, for the
    // renders it may still start after the command is gone.
    auto pieces = std::make_unique<std::shared_ptr<const registry>>();
    try {
        auto r = std::make_shared<registry>();
        register_pieces(*r);
        *pieces = std::move(r);
    } catch (const std::exception& e) {
        return set_error(interp, std::string("vfb: the pieces cannot be registered: ") + e.what());
    }
    Tcl_CreateObjCommand(interp, "vfb", create_command, pieces.release(), [](ClientData data) {
        delete static_cast<std::shared_ptr<const registry>*>(data);
    });
    if (Tcl_EvalEx(interp, vfb_bindings_script, -1, TCL_EVAL_GLOBAL) != TCL_OK) return TCL_ERROR;
    return Tcl_PkgProvide(interp, "vfb", VFB_PACKAGE_VERSION);
}

}  // namespace vl::tk
