#pragma once
/// \file
/// \brief Every piece this build links, in one registry.
#include "vl/registry.hh"

namespace vl {
/// Registers the framework's pieces and every stage's (reference or student, as built).
void register_all_pieces(registry& r);
}  // namespace vl
