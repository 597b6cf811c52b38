// The vfb widget, in the shape of Tk's example widget tkSquare.c: an option table, one
// command procedure that dispatches the widget's subcommands, redisplay deferred to an
// idle handler, and destruction through Tcl_EventuallyFree so that no command or callback
// still running can see freed memory. What is new beside that file is the render: a
// background thread (render_job) watched by a 16 ms timer.
//
// This file holds the procedures of the widget's life, as tkSquare.c does: the `vfb`
// command that creates a widget, the widget command that dispatches its subcommands, the
// event handler, the command's delete procedure, the display procedure and the free
// procedure. The rest is in the files vfb_widget_internal.hh lists.
#include "vfb_widget.hh"

#include <tk.h>

#include <exception>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "thesis_drawing.hh"
#include "vfb_widget_internal.hh"

extern "C" const char vfb_bindings_script[];  // vfb_bindings.tcl, compiled in

namespace vl::tk::widget_internal {
namespace {

// Procedures defined later in this file.
int widget_command(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]);
void event_proc(ClientData data, XEvent* event);
void command_deleted(ClientData data);
void free_widget(char* data);

// ---------------------------------------------------------------------------------------
// create_command --
//
//     The `vfb` command, `vfb pathName ?-option value ...?`: creates a vfb widget.
//
// Arguments:
//     data    the registry vfb_init made (a std::shared_ptr<const registry>*), shared by
//             every widget the command creates.
//     interp  the interpreter, which must have Tk.
//     objc, objv
//             the command line, `vfb` included.
//
// Results:
//     A standard Tcl result: the widget's path name, or an error when the window cannot be
//     made or an option is wrong (then no window is left behind).
//
// Side effects:
//     Makes the window, of class Vfb, and its command `pathName`, sets up the event handler
//     and the options (a buffer of -maxx x -maxy in -storage) and schedules the first
//     redraw.
// ---------------------------------------------------------------------------------------
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

// ---------------------------------------------------------------------------------------
// widget_command --
//
//     The widget's command, `pathName subcommand ?arg ...?`: one procedure for every
//     subcommand, like the thesis's vfbWidgetCmd() and tkSquare's SquareWidgetObjCmd.
//
// Arguments:
//     data    the widget (widget*).
//     interp  the interpreter.
//     objc, objv
//             the command line, pathName included.
//
// Results:
//     A standard Tcl result: the subcommand's, or an error for an unknown subcommand, a
//     widget whose window is already destroyed or an exception the subcommand threw (out
//     of memory, say), which becomes an error message instead of a crash.
//
// Side effects:
//     Whatever the subcommand does (vfb_widget_commands.cc). The widget is preserved for
//     the call, so a subcommand that runs events or scripts may destroy it safely.
// ---------------------------------------------------------------------------------------
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

// ---------------------------------------------------------------------------------------
// event_proc --
//
//     The widget's event handler, for Expose and the StructureNotify events.
//
// Arguments:
//     data    the widget (widget*).
//     event   the X event.
//
// Results:
//     None.
//
// Side effects:
//     Expose schedules a redraw of the exposed part and ConfigureNotify one of the whole
//     window, after keeping the buffer in view. DestroyNotify takes the widget apart: it
//     stops a render, frees the X resources and the options, deletes the widget command
//     and cancels a pending redraw; the memory is freed (free_widget) once nothing
//     preserves the widget any more.
// ---------------------------------------------------------------------------------------
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

// ---------------------------------------------------------------------------------------
// command_deleted --
//
//     The widget command's delete procedure: the command is going (`rename .v {}`, or the
//     interpreter is deleted) while the window may still be there.
//
// Arguments:
//     data    the widget (widget*).
//
// Results:
//     None.
//
// Side effects:
//     Destroys the window, unless it is already being destroyed; its DestroyNotify
//     (event_proc) does the rest.
// ---------------------------------------------------------------------------------------
void command_deleted(ClientData data) {
    auto* w = static_cast<widget*>(data);
    if (w->tkwin) Tk_DestroyWindow(w->tkwin);
}

}  // namespace

// ---------------------------------------------------------------------------------------
// display_widget --
//
//     The widget's display procedure, run as an idle handler (Tcl_DoWhenIdle, from
//     schedule_redraw) so that many changes make one redraw; `redraw` calls it at once.
//
// Arguments:
//     data    the widget (widget*).
//
// Results:
//     None.
//
// Side effects:
//     Repaints the part of the window damaged since the last redraw (the whole window
//     when its size changed): into the shared-memory image by zoom_painter and then onto
//     the screen, or, with -drawing rectangles or without the image, with X rectangles
//     as the thesis did. Nothing is drawn while the window is not mapped.
// ---------------------------------------------------------------------------------------
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

namespace {

// ---------------------------------------------------------------------------------------
// free_widget --
//
//     The widget's free procedure, called by Tcl_EventuallyFree (from event_proc) once
//     nothing preserves the widget any more.
//
// Arguments:
//     data    the widget (widget*).
//
// Results:
//     None.
//
// Side effects:
//     Deletes the widget record and what it owns (the buffer and its colours).
// ---------------------------------------------------------------------------------------
void free_widget(char* data) {
    auto* w = reinterpret_cast<widget*>(data);
    delete w;
}

// ---------------------------------------------------------------------------------------
// delete_pieces --
//
//     The `vfb` command's delete procedure: the command is gone, and with it its hold on
//     the registry; widgets still alive keep their own.
//
// Arguments:
//     data    the registry vfb_init made (a std::shared_ptr<const registry>*).
//
// Results:
//     None.
//
// Side effects:
//     Deletes the command's shared pointer to the registry.
// ---------------------------------------------------------------------------------------
void delete_pieces(ClientData data) { delete static_cast<std::shared_ptr<const registry>*>(data); }

}  // namespace
}  // namespace vl::tk::widget_internal

namespace vl::tk {

// ---------------------------------------------------------------------------------------
// vfb_init --
//
//     Adds the widget to an interpreter (Vfb_Init, in pieces/vfb_package.cc, calls it when
//     the package is loaded or vfbsh starts).
//
// Arguments:
//     interp           an interpreter with Tk 8.6.
//     register_pieces  binds the pieces `render` renders with into a registry.
//
// Results:
//     A standard Tcl result; an error without Tk 8.6, when register_pieces throws or when
//     the class bindings fail.
//
// Side effects:
//     Creates the `vfb` command, which owns the registry, runs the class bindings
//     (vfb_bindings.tcl) and provides the package `vfb`.
// ---------------------------------------------------------------------------------------
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
        return widget_internal::set_error(interp, std::string("vfb: the pieces cannot be registered: ") + e.what());
    }
    Tcl_CreateObjCommand(interp, "vfb", widget_internal::create_command, pieces.release(), widget_internal::delete_pieces);
    if (Tcl_EvalEx(interp, vfb_bindings_script, -1, TCL_EVAL_GLOBAL) != TCL_OK) return TCL_ERROR;
    return Tcl_PkgProvide(interp, "vfb", VFB_PACKAGE_VERSION);
}

}  // namespace vl::tk
