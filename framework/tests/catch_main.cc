// The Catch2 main() shared by every test executable (compiled once). Students need not read it.
#define CATCH_CONFIG_MAIN
#include "vl/catch.hh"
