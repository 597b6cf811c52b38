#pragma once
/// \file
/// \brief The rt program (`rt SCENE -o OUT.png ...`, see `rt --help`) as a function of the
/// pieces it renders with.
#include "vl/registry.hh"

namespace vl {

/// Runs rt's command line: reads the scene with `pieces`, renders it with them and writes
/// the image (and the heat map and statistics the options ask for). Returns the exit
/// status: 0, or 1 after one line on stderr that says what went wrong. The framework
/// knows no stage; rt's main() (pieces/rt.cc) passes every declared stage's pieces.
int rt_main(int argc, char** argv, const registry& pieces);

}  // namespace vl
