#pragma once
/// \file
/// \brief Stage 03's calls across the connection: the contract's five factories
/// (stage_03.hh) and an object read from scene text (a stand-in's object made again). The
/// composites themselves answer the calls of calls_components.hh (intersect, insert,
/// children_tree, ...); what a test puts into them crosses as a lent object.
#include "channel.hh"

namespace vl::remote::calls_03 {

enum op : op_id {
    make_bounding_sphere,  ///< -> handle
    make_frac_sphere,      ///< point centre, double radius, int depth, double ratio -> handle
    make_box,              ///< point lo, point hi -> handle
    make_transformed,      ///< child (calls_components::child_kind ...), matrix -> handle
    make_bvh,              ///< int leaf_size -> handle
    read_object,           ///< string: one object in the scene format, read by your code's types -> handle
};

/// The longest scene text that crosses with read_object.
inline constexpr std::size_t max_text_bytes = 1 << 20;

}  // namespace vl::remote::calls_03
