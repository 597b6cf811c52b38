// vfbsh: the windowing shell with the vfb widget built in (the thesis's `vfbsh`).
//
//   vfbsh ?script.tcl? ?arg ...?    as wish; without a script, an interactive prompt
//
// It is wish plus one line: Vfb_Init (vfb_package.cc), which gives the widget every piece
// this build links. The widget's objects are the ones the loadable package
// (`package require vfb`) is made of.
#include <tk.h>

#include "vfb_package.hh"

namespace {

int app_init(Tcl_Interp* interp) {
    if (Tcl_Init(interp) == TCL_ERROR || Tk_Init(interp) == TCL_ERROR) return TCL_ERROR;
    // `package require vfb` in vfbsh finds the widget that is already here.
    Tcl_StaticPackage(interp, "Vfb", Vfb_Init, nullptr);
    if (Vfb_Init(interp) == TCL_ERROR) return TCL_ERROR;
    Tcl_SetVar(interp, "tcl_rcFileName", "~/.vfbshrc", TCL_GLOBAL_ONLY);
    return TCL_OK;
}

}  // namespace

int main(int argc, char** argv) {
    Tk_Main(argc, argv, app_init);
    return 0;
}
