#pragma once
/// \file
/// \brief The entry point of the package `vfb`: the vfb widget with every piece this build
/// links.
#include <tcl.h>

extern "C" {
/// Adds the `vfb` widget command to `interp` (vl::tk::vfb_init, framework/tk/vfb_widget.hh,
/// with vl::register_all_pieces); TCL_ERROR, with a message, without Tk 8.6.
int Vfb_Init(Tcl_Interp* interp);
}
