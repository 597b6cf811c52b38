// The bounding volume hierarchy: see stage_03.hh for what each function must do, and
// README.md for hints. Adding children, reading, writing and building the tree once at
// the first ray (safely, from several threads) are done; build(), find_intersection()
// and the box are yours. The node layout below is a suggestion: change it as you like.
#include <atomic>
#include <cstdint>
#include <mutex>
#include <ostream>
#include <vector>

#include "bounding_sphere.hh"
#include "stage_03.hh"
#include "vl/bounds.hh"
#include "vl/not_implemented.hh"
#include "vl/scene_reader.hh"
#include "vl/shape_params.hh"

namespace vl::stage03 {

namespace {

/// \brief A binary tree of boxes over the children, built with the surface area
/// heuristic on the first ray after a change, walked near-first.
class bvh final : public rtab_composite {
public:
    explicit bvh(int leaf_size) : leaf_size_(leaf_size) {}

    std::string type_name() const override { return "BVH"; }

    void insert(std::unique_ptr<rtab_component> child) override {
        if (child && child.get() != this && !finite_box(*child))
            throw usage_error("BVH cannot hold " + child->type_name() +
                              ": its box is unknown (it is unbounded or empty), so no box can hold it;"
                              " put it beside the BVH in a LIST");
        if (child.get() == this) throw usage_error("BVH: a composite cannot contain itself");
        std::lock_guard lock(build_mutex_);
        rtab_composite::insert(std::move(child));
        built_.store(false, std::memory_order_release);
    }
    void delete_all_children() override {
        std::lock_guard lock(build_mutex_);
        rtab_composite::delete_all_children();
        built_.store(false, std::memory_order_release);
    }

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

    void read(scene_reader& in) override {
        leaf_size_ = shapes::read_bvh_leaf_size(in, leaf_size_);
        while (!in.accept('}')) in.read_child(*this);
    }
    void write(std::ostream& s) const override {
        s << "BVH { leaf_size " << leaf_size_ << '\n';
        for (const auto& c : children_) s << "  " << *c << '\n';
        s << '}';
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

    /// Builds the tree the first time a ray needs it after a change (done: the lock makes
    /// it safe when several threads arrive at once).
    void ensure_built() const {
        if (built_.load(std::memory_order_acquire)) return;
        std::lock_guard lock(build_mutex_);
        if (built_.load(std::memory_order_relaxed)) return;
        build();
        built_.store(true, std::memory_order_release);
    }

    void build() const {
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

    int leaf_size_;
    mutable std::mutex build_mutex_;
    mutable std::atomic<bool> built_{false};
    mutable std::vector<node> nodes_;                  // the tree, root first (made by build())
    mutable std::vector<const rtab_component*> order_;  // the children as the leaves hold them
};

}  // namespace

std::unique_ptr<rtab_composite> make_bvh(int leaf_size) {
    if (leaf_size < 1 || leaf_size > 64)
        throw usage_error("make_bvh: leaf_size must be from 1 to 64, not " + std::to_string(leaf_size));
    return std::make_unique<bvh>(leaf_size);
}

}  // namespace vl::stage03
