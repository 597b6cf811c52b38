#pragma once
/// \file
/// \brief Checks and measures of convex planar polygons, for the objects built of them
/// (stage 02's POLYGON, stage 03's box). Reading input right is not the lesson: these are
/// shared so every polygon refuses bad vertices with the same clear message.

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "vl/tuples.hh"

namespace vl {

/// \brief Why a list of points is not a convex planar polygon: the vertex at fault
/// (counted from 0) and what is wrong, for a factory's error or the scene reader's.
struct polygon_problem {
    std::size_t vertex = 0;  ///< the vertex to point at
    std::string message;     ///< what is wrong, naming vertices from 1
};

/// What is wrong with `vertices` as a convex planar polygon, or nothing: fewer than 3
/// vertices, a non-finite vertex, a repeated vertex, no area, not planar (off the plane by
/// more than 1e-6 of the polygon's box diagonal) or not convex (by the same tolerance).
std::optional<polygon_problem> find_polygon_problem(const std::vector<point>& vertices);

/// The mean of the vertices.
point centroid_of(const std::vector<point>& vertices);

/// The polygon's normal by Newell's method (Sutherland, Sproull and Schumacker 1974;
/// Glassner, Graphics Gems III, "Newell's method"): the sum of the cross products of
/// consecutive vertices about `centroid`. Its length is twice the area, and it points to
/// the side from which the vertices wind counter-clockwise; unlike the cross product of
/// two edges it does not depend on which vertices are picked.
vector newell_normal(const std::vector<point>& vertices, const point& centroid);

}  // namespace vl
