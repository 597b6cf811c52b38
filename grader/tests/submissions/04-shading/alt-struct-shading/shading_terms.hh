#pragma once
// The terms of stage_04.hh's sum, each a free function of a hit record, so each can be
// read (and tested) against its line of the contract on its own.
#include <optional>

#include "vl/rt_base_objects.hh"
#include "vl/scene.hh"

namespace vl::stage04::terms {

/// Everything the terms need to know about one surface point.
struct hit_record {
    const rtab_component* object = nullptr;
    point where;       ///< P
    vector facing;     ///< N, negated when the ray started inside
    vector incoming;   ///< d, the unit direction of the ray that hit
    bool exiting = false;  ///< the ray started inside the object
};

/// The hit record of `r` in `s`, or nothing when no primitive is hit.
std::optional<hit_record> find_hit(const scene& s, const ray& r);

/// A ray leaving the surface along `dir`, started off the surface on the side it goes to.
ray departing(const hit_record& h, const vector& dir);

/// ambient * c * kdr.
color ambient_term(const scene& s, const hit_record& h);
/// True when nothing lies between P and the light.
bool light_visible(const scene& s, const hit_record& h, const point& light_position);
/// kdr max(0, N.L) (c * Lc) for a light in front of the surface, else black.
color diffuse_term(const hit_record& h, const color_point& light);
/// ksr max(0, N.H)^n (c * Lc) for a light in front of the surface, else black.
color highlight_term(const hit_record& h, const color_point& light);

/// The mirror direction d - 2 (d.N) N.
vector mirror(const hit_record& h);

/// What refraction at the surface does: F, and the transmitted direction unless the light
/// is totally internally reflected.
struct fresnel_split {
    double reflectance = 1;
    std::optional<vector> transmitted;
};
fresnel_split split(const hit_record& h);

}  // namespace vl::stage04::terms
