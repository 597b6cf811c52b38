// The scene-file name of stage 04's tracer: done, nothing to change here.
#include "stage_04.hh"

namespace vl::stage04 {

void register_stage_04(registry& r) {
    r.add_tracer("whitted", [](const scene& s) { return make_whitted_tracer(s); });
}

}  // namespace vl::stage04
