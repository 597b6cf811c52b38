#include "flat.hh"

#include <algorithm>
#include <cmath>
#include <utility>

namespace vl::stage02 {

namespace {

double get(const vector& v, int k) { return k == 0 ? v.x : k == 1 ? v.y : v.z; }

}  // namespace

void flat_loop::set_loop(std::vector<point> loop, const vector& normal) {
    loop_ = std::move(loop);
    normal_ = normal.unit();
    low_ = high_ = loop_.front();
    for (const point& p : loop_) {
        low_ = point(std::min(low_.x, p.x), std::min(low_.y, p.y), std::min(low_.z, p.z));
        high_ = point(std::max(high_.x, p.x), std::max(high_.y, p.y), std::max(high_.z, p.z));
    }
}

intersection flat_loop::find_intersection(const ray& r) const {
    const vector& d = r.direction();
    int kz = 0;
    if (std::fabs(d.y) > std::fabs(get(d, kz))) kz = 1;
    if (std::fabs(d.z) > std::fabs(get(d, kz))) kz = 2;
    const int kx = (kz + 1) % 3, ky = (kz + 2) % 3;
    const double sx = get(d, kx) / get(d, kz), sy = get(d, ky) / get(d, kz);
    const auto sheared = [&](const point& p, double& x, double& y) {
        const vector q = p - r.origin();
        x = get(q, kx) - sx * get(q, kz);
        y = get(q, ky) - sy * get(q, kz);
    };
    bool below = false, above = false;
    double px = 0, py = 0;
    sheared(loop_.back(), px, py);
    for (const point& p : loop_) {
        double qx = 0, qy = 0;
        sheared(p, qx, qy);
        const double e = px * qy - py * qx;  // edge (previous -> p); exactly minus (p -> previous)
        below = below || e < 0;
        above = above || e > 0;
        px = qx;
        py = qy;
    }
    if (below == above) return intersection::none();  // outside, or the ray runs in the plane
    const double cosine = d * normal_;
    if (cosine == 0) return intersection::none();
    const double t = ((loop_.front() - r.origin()) * normal_) / cosine;
    if (std::isfinite(t) && t > std::fabs(zero_t())) return intersection::at(t, this);
    return intersection::none();
}

}  // namespace vl::stage02
