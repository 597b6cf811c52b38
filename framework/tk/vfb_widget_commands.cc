// The vfb widget's subcommands, `pathName subcommand ?arg ...?`: the thesis's (the view,
// pixels, files and render), configure and cget, and the new ones (heat_legend, inspect,
// progress, cancel, wait, redraw), and their table, which widget_command in vfb_widget.cc
// dispatches from. Each takes the widget, the interpreter and the whole command line.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <string>

#include "vfb_widget_internal.hh"
#include "vl/heat_map.hh"

namespace vl::tk::widget_internal {
namespace {

constexpr int max_pixel_size = 256;

// A linear colour as Tk writes it, "#rrggbb" in sRGB.
Tcl_Obj* srgb_hex(double r, double g, double b) {
    char hex[8];
    std::snprintf(hex, sizeof hex, "#%02x%02x%02x", linear_to_srgb8(r), linear_to_srgb8(g), linear_to_srgb8(b));
    return Tcl_NewStringObj(hex, -1);
}

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

// After the whole buffer has changed (clear, load): the last render's counts no longer
// describe it, and every pixel is redrawn.
void show_new_contents(widget* w) {
    w->tests.clear();
    refresh_colors(w, {0, 0, w->pixels->width(), w->pixels->height()});
    refresh_heat_colors(w);
    schedule_full_redraw(w);
}

int cmd_clear(widget* w, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
    if (objc != 2) return wrong_args(interp, objv, "");
    if (refuse_while_rendering(w, interp, "clear") != TCL_OK) return TCL_ERROR;
    w->pixels->clear();
    show_new_contents(w);
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
    show_new_contents(w);
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
    return start_render(w, interp, Tcl_GetString(objv[2]));
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
        notify_progress(w);
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

}  // namespace

// The subcommands, sorted: the thesis's, then configure/cget, then the new ones.
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

}  // namespace vl::tk::widget_internal
