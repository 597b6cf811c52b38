#include "all_pieces.hh"

#include "stage_01.hh"
#include "stage_02.hh"
#include "stage_03.hh"

namespace vl {

void register_all_pieces(registry& r) {
    register_framework(r);
    stage01::register_stage_01(r);
    stage02::register_stage_02(r);
    stage03::register_stage_03(r);
}

}  // namespace vl
