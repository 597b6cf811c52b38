// The bounding volume hierarchy: see stage_03.hh for what each function must do, and
// README.md for hints. build(), find_intersection() and the box are yours. The rest is
// done in the base class, vl::shapes::bvh_base (framework/include/vl/composite_bases.hh):
// leaf_size_, insert() and its refusals, delete_all_children(), reading and writing BVH,
// the checks of make_bvh(), and ensure_built(), which calls your build() once at the
// first ray after a change, safely when several threads arrive at once. The node layout
// below is a suggestion: change it as you like.
#include <cstdint>
#include <vector>

#include "stage_03.hh"
#include "vl/bounds.hh"
#include "vl/composite_bases.hh"
#include "vl/not_implemented.hh"

namespace vl::stage03 {

namespace {

/// \brief A binary tree of boxes over the children, built with the surface area
/// heuristic on the first ray after a change, walked near-first.
class bvh final : public shapes::bvh_base {
public:
    explicit bvh(int leaf_size) : bvh_base(leaf_size) {}

    point min_point() const override {
        ensure_built();
        // TODO: the lower corner of the root's box (NaN_point when there are no children).
        throw not_implemented_error();
    }
    point max_point() const override {
        ensure_built();
        // TODO: the upper corner of the root's box.
        throw not_implemented_error();
    }

private:
    /// One node of the tree, all nodes in one vector (a suggestion).
    struct node {
        point lo, hi;             // the node's box: the union of its children's boxes
        std::uint32_t first = 0;  // a leaf: its children are order_[first, first + count)
        std::uint32_t count = 0;  // 0 for an inner node
        std::uint32_t left = 0;   // an inner node: its two children in nodes_
        std::uint32_t right = 0;
    };

    /// Builds the tree over children_: called by ensure_built() (under its lock) the
    /// first time a ray needs the tree after a change.
    void build() const override {
        nodes_.clear();
        order_.clear();
        // TODO: build the tree over children_ (their boxes: min_point(), max_point()).
        // - A node's box is the union of its children's boxes.
        // - Split with the surface area heuristic: for each axis, sort the node's children
        //   by box centre, and for each split i, cost = area(left i) * i + area(rest) *
        //   (n - i); take the cheapest. README.md explains the cost and when to stop.
        // - A node of more than leaf_size_ children is always split; children whose
        //   centres are all alike are split by count (never recurse forever).
        throw not_implemented_error();
    }

    intersection find_intersection([[maybe_unused]] const ray& r) const override {
        ensure_built();
        // TODO: the root's box first (vl::hits_box(): a miss costs that one test), then
        // near-first: at an inner node test both children's boxes with the best hit so far
        // as t_max (a ray_span gives where each is entered), visit the nearer first, skip
        // one whose box starts beyond the best hit. A leaf intersects each child once.
        // Return the nearest hit, composite_only(this) when the root box was entered for
        // nothing, none() on a miss.
        throw not_implemented_error();
    }

    mutable std::vector<node> nodes_;                  // the tree, root first (made by build())
    mutable std::vector<const rtab_component*> order_;  // the children as the leaves hold them
};

}  // namespace

std::unique_ptr<rtab_composite> make_bvh(int leaf_size) {
    return shapes::bvh_base::make<bvh>(leaf_size);
}

}  // namespace vl::stage03
