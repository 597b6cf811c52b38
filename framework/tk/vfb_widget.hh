#pragma once
/// \file
/// \brief The vfb Tk widget: `vfb pathName -maxx X -maxy Y ?option value ...?`.
///
/// Vfb_Init adds the `vfb` command and the widget's class bindings to an interpreter that
/// has Tk, and provides the package `vfb`. `vfbsh` calls it from its Tcl_AppInit; a
/// plain wish gets it with `package require vfb` (the loadable module, built from the same
/// objects against the Tcl and Tk stubs). The commands and options are documented in
/// docs/ta-guide.md and in the option table and command list of vfb_widget.cc.
#include <tcl.h>

extern "C" {
/// Adds the `vfb` widget command to `interp`; TCL_ERROR (with a message) without Tk 8.6.
int Vfb_Init(Tcl_Interp* interp);
}

/// The package's version, as `package require vfb` reports it.
#define VFB_PACKAGE_VERSION "1.0"
