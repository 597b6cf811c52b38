#include "vl/tracer.hh"

namespace vl {

color flat_tracer::trace(const ray& r, int) const {
    const intersection hit = scene_.root->intersect(r);
    return hit.hit() ? hit.object->clr() : scene_.background;
}

color normals_tracer::trace(const ray& r, int) const {
    const intersection hit = scene_.root->intersect(r);
    if (!hit.hit()) return scene_.background;
    const vector n = hit.object->normal(r.t_point(hit.t));
    return {(n.x + 1) / 2, (n.y + 1) / 2, (n.z + 1) / 2};
}

color sky_tracer::sky(const vector& d) {
    const double up = d.y > 0 ? d.y : 0;
    return (1 - up) * WHITE + up * color(0.5, 0.7, 1.0);
}

color sky_tracer::trace(const ray& r, int) const {
    const intersection hit = scene_.root->intersect(r);
    return hit.hit() ? hit.object->clr() : sky(r.direction());
}

}  // namespace vl
