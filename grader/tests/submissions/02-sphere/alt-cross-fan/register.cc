// The scene-file names of stage 02's objects: done, nothing to change here.
#include "stage_02.hh"

namespace vl::stage02 {

void register_stage_02(registry& r) {
    r.add("SPHERE", [] { return make_sphere(point(0, 0, 0), 1); });
    r.add("PLANE", [] { return make_plane(point(0, 0, 0), vector(0, 1, 0)); });
    r.add("TRIANGLE", [] { return make_triangle(point(0, 0, 0), point(1, 0, 0), point(0, 1, 0)); });
    r.add("POLYGON", [] {
        return make_polygon({point(0, 0, 0), point(1, 0, 0), point(1, 1, 0), point(0, 1, 0)});
    });
}

}  // namespace vl::stage02
