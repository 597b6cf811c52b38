// The vfb widget's options: the table Tk_SetOptions reads (the thesis's options, then the
// standard and new ones) and configuration, which checks the values, makes a new buffer
// when -maxx, -maxy or -storage change and asks for the window size the options imply.
#include <algorithm>
#include <cstddef>
#include <exception>
#include <memory>
#include <string>
#include <tuple>
#include <utility>

#include "vfb_widget_internal.hh"

namespace vl::tk::widget_internal {
namespace {

// typeMask bits: what a change of the option requires.
enum : int { buffer_changed = 1, geometry_changed = 2, look_changed = 4, heat_changed = 8 };

}  // namespace

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

namespace {

// Asks Tk for the window size the options imply.
void request_geometry(widget* w) {
    // Without -width or -height the window fits the buffer at pixel size 1; zooming
    // changes what the window shows, not its size.
    const int width = w->options.width > 0 ? w->options.width : w->pixels->width();
    const int height = w->options.height > 0 ? w->options.height : w->pixels->height();
    Tk_GeometryRequest(w->tkwin, std::min(width, 32767), std::min(height, 32767));
}

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

}  // namespace

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

}  // namespace vl::tk::widget_internal
