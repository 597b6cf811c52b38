#include "shading_terms.hh"

#include <cmath>

namespace vl::stage04::terms {

namespace {

/// The light's direction from P, a unit vector.
vector towards(const hit_record& h, const point& light_position) { return (light_position - h.where).unit(); }

/// Whether a light at `light_position` is in front of the surface (N.L > 0).
bool in_front(const hit_record& h, const point& light_position) {
    return h.facing * towards(h, light_position) > 0;
}

}  // namespace

std::optional<hit_record> find_hit(const scene& s, const ray& r) {
    const intersection i = s.root->intersect(r);
    if (!i.hit()) return std::nullopt;
    hit_record h;
    h.object = i.object;
    h.where = r.t_point(i.t);
    h.incoming = r.direction();
    h.exiting = i.object->contains(r.origin());
    const vector outward = i.object->normal(h.where);
    h.facing = h.exiting ? -1.0 * outward : outward;
    return h;
}

ray departing(const hit_record& h, const vector& dir) {
    // Relative to the distance of P from the origin (at least 1): that bounds the size of
    // every coordinate, so the offset is above their round-off anywhere.
    const point& p = h.where;
    const double size = std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z);
    const double lift = 1e-9 * (size > 1 ? size : 1.0);
    const double side = dir * h.facing > 0 ? 1.0 : -1.0;
    return ray(p + (side * lift) * h.facing, dir);
}

color ambient_term(const scene& s, const hit_record& h) {
    return h.object->kdr() * (h.object->clr() * s.ambient);
}

bool light_visible(const scene& s, const hit_record& h, const point& light_position) {
    const ray probe = departing(h, towards(h, light_position));
    const double distance = (light_position - probe.origin()).length();
    const intersection i = s.root->intersect(probe);
    return !(i.hit() && i.t < distance);
}

color diffuse_term(const hit_record& h, const color_point& light) {
    if (!in_front(h, light.pnt())) return BLACK;
    const double lambert = h.facing * towards(h, light.pnt());
    return (h.object->kdr() * lambert) * (light.clr() * h.object->clr());
}

color highlight_term(const hit_record& h, const color_point& light) {
    if (!in_front(h, light.pnt())) return BLACK;
    const vector half = (towards(h, light.pnt()) + (-1.0 * h.incoming)).unit();
    const double c = h.facing * half;
    return (h.object->ksr() * std::pow(c < 0 ? 0.0 : c, h.object->n())) * (light.clr() * h.object->clr());
}

vector mirror(const hit_record& h) {
    const double along = h.incoming * h.facing;
    return h.incoming - (2 * along) * h.facing;
}

fresnel_split split(const hit_record& h) {
    const double ior = h.object->ior();
    const double from = h.exiting ? ior : 1.0;
    const double to = h.exiting ? 1.0 : ior;
    const double ratio = from / to;
    const double cos_in = -(h.incoming * h.facing);
    const double sin2_out = ratio * ratio * (1 - cos_in * cos_in);
    fresnel_split out;
    if (sin2_out > 1) return out;  // beyond the critical angle
    const double cos_out = std::sqrt(1 - sin2_out);
    const double r0 = std::pow((to - from) / (to + from), 2);
    const double lower_side_cos = to >= from ? cos_in : cos_out;
    out.reflectance = r0 + (1 - r0) * std::pow(1 - lower_side_cos, 5);
    out.transmitted = ratio * h.incoming + (ratio * cos_in - cos_out) * h.facing;
    return out;
}

}  // namespace vl::stage04::terms
