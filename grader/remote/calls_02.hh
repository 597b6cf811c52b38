#pragma once
/// \file
/// \brief Stage 02's calls across the connection: the contract's four factories
/// (stage_02.hh), and what a scene file changes in a shape after it is made. The objects
/// themselves answer the calls of calls_components.hh.
#include <cstddef>

#include "channel.hh"

namespace vl::remote::calls_02 {

enum op : op_id {
    make_sphere,    ///< point centre, double radius -> handle
    make_plane,     ///< point on the plane, vector normal -> handle
    make_triangle,  ///< point a, b, c -> handle
    make_polygon,   ///< vector of points -> handle
    adopt,          ///< handle into, handle from: the object `from` takes the place of `into`
    set_surface,    ///< handle, surface
};

/// The most vertices a polygon crosses with.
inline constexpr std::size_t max_vertices = 1 << 16;

}  // namespace vl::remote::calls_02
