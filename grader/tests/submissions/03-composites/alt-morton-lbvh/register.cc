// The scene-file names of stage 03's objects: done, nothing to change here.
#include "stage_03.hh"

namespace vl::stage03 {

void register_stage_03(registry& r) {
    r.add("BOUNDSPH", [] { return make_bounding_sphere(); });
    r.add("FRACSPH", [] { return make_frac_sphere(point(0, 0, 0), 1, 3, 0.4); });
    r.add("BOX", [] { return make_box(point(0, 0, 0), point(1, 1, 1)); });
    r.add("TRANSFORM", [] { return make_transformed(nullptr, IDENTITY); });
    r.add("BVH", [] { return make_bvh(4); });
}

}  // namespace vl::stage03
