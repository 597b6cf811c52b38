#include "woop.hh"

#include <cmath>
#include <utility>

namespace vl::stage02 {

namespace {

double component(const vector& v, int k) { return k == 0 ? v.x : k == 1 ? v.y : v.z; }

}  // namespace

sheared_ray::sheared_ray(const ray& r) : origin_(r.origin()) {
    const vector& d = r.direction();
    const double ax = std::fabs(d.x), ay = std::fabs(d.y), az = std::fabs(d.z);
    kz_ = ax > ay ? (ax > az ? 0 : 2) : (ay > az ? 1 : 2);
    kx_ = (kz_ + 1) % 3;
    ky_ = (kx_ + 1) % 3;
    if (component(d, kz_) < 0) std::swap(kx_, ky_);  // keep the winding
    const double dz = component(d, kz_);
    sx_ = component(d, kx_) / dz;
    sy_ = component(d, ky_) / dz;
    sz_ = 1 / dz;
}

sheared_vertex sheared_ray::operator()(const point& p) const {
    const vector a = p - origin_;
    const double az = component(a, kz_);
    return {component(a, kx_) - sx_ * az, component(a, ky_) - sy_ * az, sz_ * az};
}

std::optional<double> woop_distance(const sheared_vertex& a, const sheared_vertex& b, const sheared_vertex& c) {
    const double u = edge_function(c, b), v = edge_function(a, c), w = edge_function(b, a);
    if ((u < 0 || v < 0 || w < 0) && (u > 0 || v > 0 || w > 0)) return std::nullopt;
    const double det = u + v + w;
    if (det == 0) return std::nullopt;  // the ray lies in the triangle's plane
    return (u * a.z + v * b.z + w * c.z) / det;
}

}  // namespace vl::stage02
