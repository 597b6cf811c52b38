// Vfb_Init: what Tcl's `load` calls in a plain wish (`package require vfb`) and vfbsh calls
// at start-up. It hands the widget (framework/tk) every piece this build links, for its
// `render` subcommand.
#include "vfb_package.hh"

#include "all_pieces.hh"
#include "vfb_widget.hh"

int Vfb_Init(Tcl_Interp* interp) { return vl::tk::vfb_init(interp, vl::register_all_pieces); }
