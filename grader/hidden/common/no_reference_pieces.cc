// The reference renderer's vl::graded::register_reference_pieces (graded_pieces.cc): it
// registers nothing, since every stage that program links is the reference already, and
// graded_pieces.cc takes what this registry lacks from the linked code. A submission's
// render program links a stage's oracle entry instead (reference_pieces.cc.in).
#include "vl/registry.hh"

namespace vl::graded {

void register_reference_pieces(registry&) {}

}  // namespace vl::graded
