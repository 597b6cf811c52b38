#pragma once
/// \file
/// \brief The vfb Tk widget: `vfb pathName -maxx X -maxy Y ?option value ...?`.
///
/// vfb_init adds the `vfb` command and the widget's class bindings to an interpreter that
/// has Tk, and provides the package `vfb`. The widget renders with the pieces it is given
/// there: the framework knows no stage, so whoever links the stages calls it. In this
/// build that is `Vfb_Init` in pieces/vfb_package.cc, which hands it every declared stage's
/// pieces: `vfbsh` calls Vfb_Init from its Tcl_AppInit, and a plain wish gets it with
/// `package require vfb` (the loadable module, built from the same objects against the Tcl
/// and Tk stubs). The commands and options are documented in docs/ta-guide.md and in the
/// option table of vfb_widget_options.cc and the command list of vfb_widget_commands.cc.
#include <tcl.h>

#include "vl/registry.hh"

namespace vl::tk {

/// Adds the `vfb` widget command to `interp`, whose `render` subcommand renders with the
/// pieces `register_pieces` binds into a new registry (called once, here). TCL_ERROR, with
/// a message, without Tk 8.6 or when `register_pieces` throws.
int vfb_init(Tcl_Interp* interp, void (*register_pieces)(registry&));

}  // namespace vl::tk

/// The package's version, as `package require vfb` reports it.
#define VFB_PACKAGE_VERSION "1.0"
