#include "vl/bounds.hh"

#include <algorithm>
#include <cmath>

#include "vl/stats.hh"

namespace vl {

bool hits_box(const ray& r, const point& lo, const point& hi, double t_max, ray_span* span) {
    ++detail::thread_tallies.bounding_volume;
    const double o[3] = {r.origin().x, r.origin().y, r.origin().z};
    const double d[3] = {r.direction().x, r.direction().y, r.direction().z};
    const double a[3] = {lo.x, lo.y, lo.z};
    const double b[3] = {hi.x, hi.y, hi.z};
    double t0 = 0, t1 = t_max;
    for (int k = 0; k < 3; ++k) {
        if (d[k] == 0) {  // parallel to this slab: inside it or never
            if (!(a[k] <= o[k] && o[k] <= b[k])) return false;
            continue;
        }
        const double inv = 1.0 / d[k];
        double near = (a[k] - o[k]) * inv, far = (b[k] - o[k]) * inv;
        if (near > far) std::swap(near, far);
        t0 = std::max(t0, near);
        t1 = std::min(t1, far);
        if (t0 > t1) return false;
    }
    if (span) *span = {t0, t1};
    return t1 > 0;
}

bool hits_sphere(const ray& r, const point& center, double radius) {
    ++detail::thread_tallies.bounding_volume;
    // The ray misses when the centre is farther than the radius from the ray's line, or
    // when the sphere lies wholly behind the origin.
    const vector oc = center - r.origin();
    const double along = oc * r.direction();
    const double r2 = radius * radius;
    const double dist2 = (oc - along * r.direction()) * (oc - along * r.direction());
    if (dist2 > r2) return false;
    return along >= 0 || oc * oc <= r2;
}

}  // namespace vl
