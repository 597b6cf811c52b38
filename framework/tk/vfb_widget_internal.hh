#pragma once
/// \file
/// \brief The vfb widget's private header: the widget record and what its files share.
///
/// The widget is built the way Tk's example widget tkSquare.c is, in five files that share
/// this header (none of it is for use outside them; the public face is vfb_widget.hh):
///   vfb_widget.cc            create, destroy, the widget command's dispatch and display
///   vfb_widget_options.cc    the option table and configuration
///   vfb_widget_redisplay.cc  the screen colour cache, redisplay requests and the view
///   vfb_widget_render.cc     the render thread's glue: its timer, exit handler and report
///   vfb_widget_commands.cc   the subcommands and their table
#include <tk.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "render_job.hh"
#include "vl/registry.hh"
#include "vl/vfb.hh"
#include "x_frame.hh"
#include "zoom_painter.hh"

namespace vl::tk::widget_internal {

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

inline constexpr const char* view_names[] = {"color", "heat", nullptr};
inline constexpr const char* drawing_names[] = {"image", "rectangles", nullptr};
inline constexpr const char* heat_scale_names[] = {"linear", "log", nullptr};
enum { view_color, view_heat };
enum { drawing_image, drawing_rectangles };
enum { heat_linear, heat_log };

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

inline int screen_width(const widget* w) { return Tk_IsMapped(w->tkwin) ? Tk_Width(w->tkwin) : Tk_ReqWidth(w->tkwin); }
inline int screen_height(const widget* w) { return Tk_IsMapped(w->tkwin) ? Tk_Height(w->tkwin) : Tk_ReqHeight(w->tkwin); }

inline int set_error(Tcl_Interp* interp, const std::string& message) {
    Tcl_SetObjResult(interp, Tcl_NewStringObj(message.c_str(), -1));
    return TCL_ERROR;
}

// ---- vfb_widget.cc ----

// The idle handler that repaints the damaged part of the window.
void display_widget(ClientData data);

// ---- vfb_widget_options.cc ----

// The widget's options, for Tk_CreateOptionTable.
extern const Tk_OptionSpec option_specs[];
// Sets the options objv[0..objc) and brings the buffer, colours and geometry up to date;
// on error leaves the old options and the result holds the message.
int configure(Tcl_Interp* interp, widget* w, int objc, Tcl_Obj* const objv[]);

// ---- vfb_widget_redisplay.cc ----

// Brings the screen colours of virtual pixels `r` up to date with the buffer.
void refresh_colors(widget* w, rect r);
// The heat map's colours from the last render's counts, as rt --heatmap draws them.
void refresh_heat_colors(widget* w);
// Asks for screen pixels `r` to be repainted when Tk is idle (tkSquare's pattern: many
// changes, one redraw).
void schedule_redraw(widget* w, rect r);
void schedule_full_redraw(widget* w);
void schedule_virtual_redraw(widget* w, rect virtual_pixels);
// How the pixels look at the current zoom, in the screen's colours.
paint_style current_style(const widget* w);
// Zooms to `size`, keeping the virtual point under screen point (sx, sy) where it is.
void zoom_about(widget* w, int size, double sx, double sy);
// Keeps at least part of the buffer on the screen, however far a drag goes.
void keep_in_view(widget* w);

// ---- vfb_widget_render.cc ----

// Starts rendering `file` in the background, watched by a timer; TCL_ERROR, with the
// message, when the file cannot be read.
int start_render(widget* w, Tcl_Interp* interp, const char* file);
// Ends the render (finished or cancelled): last tiles, statistics, report.
void stop_render(widget* w);
// The progress dictionary of `progress`, `wait` and -progresscommand.
Tcl_Obj* progress_dict(const widget* w);
// Calls -progresscommand with the progress dictionary appended, at global level.
void notify_progress(widget* w);

// ---- vfb_widget_commands.cc ----

// One subcommand: `pathName name ?arg ...?` with the whole command line in objv.
using subcommand = int (*)(widget*, Tcl_Interp*, int, Tcl_Obj* const[]);
struct named_subcommand {
    const char* name;
    subcommand run;
};
// The subcommands, sorted by name, ending with {nullptr, nullptr} (for
// Tcl_GetIndexFromObjStruct).
extern const named_subcommand subcommands[];

}  // namespace vl::tk::widget_internal
