#pragma once
/// \file
/// \brief The calls on a ray-traceable object (vl::rtab_component) across the
/// connection, for every stage whose pieces are objects: one operation per virtual member
/// a piece may override. The first argument is always the object's handle.
///
/// An intersection crosses as its t and the object hit, named by handle: an object is
/// never named by its address, so nothing either end sends is ever used as a pointer.
#include "channel.hh"

namespace vl::remote::calls_components {

/// Operation numbers from here up are the components'; a stage's own calls stay below.
inline constexpr op_id first = 128;

enum op : op_id {
    intersect = first,  ///< ray -> double t, handle of the object hit (0: none)
    normal,             ///< point -> vector
    contains,           ///< point -> bool
    min_point,          ///< -> point
    max_point,          ///< -> point
    bounding_ball,      ///< -> point centre, double radius
    zero_t,             ///< -> double
    type_name,          ///< -> string
    write,              ///< -> string: what write() wrote
    surface_values,     ///< -> color clr, double kdr, ksr, kdt, kst, n, ior
    intersect_each,     ///< (no object first) vector of handles, vector of rays -> per ray, per object: double t, handle hit
    end,
};

/// Every operation number is below this: the size of a handler table.
inline constexpr op_id table_size = 256;

/// The most objects, and the most rays, one intersect_each asks (the answer must fit a frame).
inline constexpr std::size_t max_batch = 1 << 16;

/// The longest text write() may answer with.
inline constexpr std::size_t max_written_bytes = 1 << 20;

}  // namespace vl::remote::calls_components
