// The vfb widget's glue to the render thread (render_job): starting a render, the 16 ms
// timer that copies the finished tiles into the widget's buffer and calls
// -progresscommand, the exit handler that stops the workers when the process exits during
// a render, and the report (`progress`) of how the last render ended.
#include <exception>
#include <memory>
#include <string>

#include "vfb_widget_internal.hh"

namespace vl::tk::widget_internal {
namespace {

constexpr int render_poll_ms = 16;  // one frame at 60 Hz

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

// ---------------------------------------------------------------------------------------
// exit_during_render --
//
//     The exit handler of a running render (Tcl_CreateExitHandler): `exit` while
//     rendering must stop the workers before the process tears down what they use.
//
// Arguments:
//     data   the widget (widget*) whose render is running.
//
// Results:
//     None.
//
// Side effects:
//     Cancels the render and joins its thread. The handler is gone once it has run, so
//     stop_render must not delete it again.
// ---------------------------------------------------------------------------------------
void exit_during_render(ClientData data) {
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

}  // namespace

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

void notify_progress(widget* w) {
    Tcl_Preserve(w);  // the progress command may destroy the widget
    call_script_option(w, w->options.progress_command, progress_dict(w));
    Tcl_Release(w);
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

namespace {

// ---------------------------------------------------------------------------------------
// watch_render --
//
//     The render's timer handler (Tcl_CreateTimerHandler), every render_poll_ms while the
//     render runs: shows what the workers have finished and reports the progress.
//
// Arguments:
//     data   the widget (widget*) whose render runs.
//
// Results:
//     None.
//
// Side effects:
//     Copies the finished tiles into the widget's buffer and schedules their redraw. When
//     the render has finished it ends it (stop_render: report, heat map, exit handler);
//     otherwise the timer is set again. Then -progresscommand is called, which may do
//     anything, including destroying the widget (it is preserved for the call).
// ---------------------------------------------------------------------------------------
void watch_render(ClientData data) {
    auto* w = static_cast<widget*>(data);
    w->timer = nullptr;
    if (!w->job) return;
    copy_finished_tiles(w);
    if (w->job->finished())
        stop_render(w);
    else
        w->timer = Tcl_CreateTimerHandler(render_poll_ms, watch_render, w);
    notify_progress(w);
}

}  // namespace

int start_render(widget* w, Tcl_Interp* interp, const char* file) {
    try {
        w->job = std::make_unique<render_job>(*w->pieces, file, w->pixels->width(), w->pixels->height(),
                                              w->pixels->storage_name());
    } catch (const std::exception& e) {
        return set_error(interp, std::string("render: ") + e.what());
    }
    w->report = {"running", file, "", 0, 0};
    w->timer = Tcl_CreateTimerHandler(render_poll_ms, watch_render, w);
    Tcl_CreateExitHandler(exit_during_render, w);
    w->exit_handler = true;
    return TCL_OK;
}

}  // namespace vl::tk::widget_internal
