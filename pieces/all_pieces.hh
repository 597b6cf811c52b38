#pragma once
/// \file
/// \brief Every piece this build links, in one registry: the framework's and every stage's.
#include "vl/registry.hh"

namespace vl {

/// Registers the framework's pieces, then every stage's (reference or student, as built),
/// in the order of the top level's vl_stage() lines. The build generates it from
/// all_pieces.cc.in: for each stage NN-name it includes the contract header
/// assignments/NN-name/stage_NN.hh and calls vl::stageNN::register_stage_NN.
void register_all_pieces(registry& r);

/// A new registry holding every piece this build links.
inline registry all_pieces() {
    registry r;
    register_all_pieces(r);
    return r;
}

}  // namespace vl
