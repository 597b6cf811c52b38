// Reference: the bounding volume hierarchy (see assignments/03-composites/stage_03.hh).
#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <mutex>
#include <ostream>
#include <vector>

#include "bounding_sphere.hh"
#include "stage_03.hh"
#include "vl/bounds.hh"
#include "vl/scene_reader.hh"

namespace vl::stage03 {

namespace {

constexpr double no_limit = 1e300;   // hits_box's t_max when nothing has been hit yet
constexpr double traversal_cost = 1;  // a node's two box tests, in units of one child test
constexpr int max_tree_depth = 60;    // deeper than this, split by count (always balanced)

struct box3 {
    point lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
    void grow(const box3& b) {
        lo = point(std::fmin(lo.x, b.lo.x), std::fmin(lo.y, b.lo.y), std::fmin(lo.z, b.lo.z));
        hi = point(std::fmax(hi.x, b.hi.x), std::fmax(hi.y, b.hi.y), std::fmax(hi.z, b.hi.z));
    }
    /// Half the surface area (the factor 2 cancels in every ratio).
    double half_area() const {
        const vector e = hi - lo;
        return e.x * e.y + e.y * e.z + e.z * e.x;
    }
};

double axis_of(const point& p, int axis) { return axis == 0 ? p.x : axis == 1 ? p.y : p.z; }

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
        return nodes_.empty() ? NaN_point : nodes_.front().bounds.lo;
    }
    point max_point() const override {
        ensure_built();
        return nodes_.empty() ? NaN_point : nodes_.front().bounds.hi;
    }

    void read(scene_reader& in) override {
        in.expect('{', "after BVH");
        if (in.peek().type == token::kind::word && in.peek().text == "leaf_size") {
            in.next();
            leaf_size_ = in.read_int("leaf_size of BVH", 1, 64);
        }
        while (!in.accept('}')) in.read_child(*this);
    }
    void write(std::ostream& s) const override {
        s << "BVH { leaf_size " << leaf_size_ << '\n';
        for (const auto& c : children_) s << "  " << *c << '\n';
        s << '}';
    }

private:
    struct node {
        box3 bounds;
        std::uint32_t first = 0;  // a leaf: its children are order_[first, first + count)
        std::uint32_t count = 0;  // 0 for an inner node
        std::uint32_t right = 0;  // an inner node: its left child is the next node, this its right
    };
    struct item {
        box3 bounds;
        point centre;
        const rtab_component* object;
    };

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
        if (children_.empty()) return;
        std::vector<item> items;
        items.reserve(children_.size());
        for (const auto& c : children_) {
            item it{{c->min_point(), c->max_point()}, {}, c.get()};
            it.centre = point((it.bounds.lo.x + it.bounds.hi.x) / 2, (it.bounds.lo.y + it.bounds.hi.y) / 2,
                              (it.bounds.lo.z + it.bounds.hi.z) / 2);
            items.push_back(it);
        }
        nodes_.reserve(2 * items.size());
        std::vector<double> right_area(items.size() + 1);
        build_node(items, 0, items.size(), 0, right_area);
        order_.reserve(items.size());
        for (const item& it : items) order_.push_back(it.object);
    }

    /// Builds the subtree of items[begin, end) at nodes_.back() + 1; returns its index.
    std::uint32_t build_node(std::vector<item>& items, std::size_t begin, std::size_t end, int depth,
                             std::vector<double>& right_area) const {
        const auto index = static_cast<std::uint32_t>(nodes_.size());
        nodes_.emplace_back();
        box3 bounds, centres;
        for (std::size_t i = begin; i < end; ++i) {
            bounds.grow(items[i].bounds);
            centres.grow({items[i].centre, items[i].centre});
        }
        nodes_[index].bounds = bounds;
        const std::size_t n = end - begin;
        auto make_leaf = [&] {
            nodes_[index].first = static_cast<std::uint32_t>(begin);
            nodes_[index].count = static_cast<std::uint32_t>(n);
            return index;
        };
        if (n == 1) return make_leaf();

        // The cheapest split by the surface area heuristic, over the three axes.
        const double area = bounds.half_area();
        double best_cost = INFINITY;
        int best_axis = -1;
        std::size_t best_split = 0;
        for (int axis = 0; axis < 3 && depth < max_tree_depth; ++axis) {
            if (axis_of(centres.lo, axis) == axis_of(centres.hi, axis)) continue;  // all centres alike here
            sort_along(items, begin, end, axis);
            box3 right;
            for (std::size_t i = n; i > 0; --i) {
                right.grow(items[begin + i - 1].bounds);
                right_area[i - 1] = right.half_area();
            }
            box3 left;
            for (std::size_t i = 1; i < n; ++i) {  // left: the first i items
                left.grow(items[begin + i - 1].bounds);
                const double weighted = left.half_area() * static_cast<double>(i) +
                                        right_area[i] * static_cast<double>(n - i);
                const double cost = traversal_cost + (area > 0 ? weighted / area : static_cast<double>(n));
                const bool nearer_middle = cost == best_cost && best_axis == axis &&
                                           std::abs(static_cast<double>(i) - static_cast<double>(n) / 2) <
                                               std::abs(static_cast<double>(best_split) - static_cast<double>(n) / 2);
                if (cost < best_cost || nearer_middle) {
                    best_cost = cost;
                    best_axis = axis;
                    best_split = i;
                }
            }
        }
        if (n <= static_cast<std::size_t>(leaf_size_) && !(best_cost < static_cast<double>(n))) return make_leaf();
        if (best_axis < 0) {
            best_split = n / 2;  // every centre alike, or too deep: split by count
        } else {
            sort_along(items, begin, end, best_axis);
        }
        build_node(items, begin, begin + best_split, depth + 1, right_area);
        nodes_[index].right = build_node(items, begin + best_split, end, depth + 1, right_area);
        return index;
    }

    static void sort_along(std::vector<item>& items, std::size_t begin, std::size_t end, int axis) {
        std::sort(items.begin() + static_cast<std::ptrdiff_t>(begin), items.begin() + static_cast<std::ptrdiff_t>(end),
                  [axis](const item& a, const item& b) { return axis_of(a.centre, axis) < axis_of(b.centre, axis); });
    }

    intersection find_intersection(const ray& r) const override {
        ensure_built();
        if (nodes_.empty()) return intersection::none();
        ray_span span;
        if (!hits_box(r, nodes_.front().bounds.lo, nodes_.front().bounds.hi, no_limit, &span))
            return intersection::none();
        struct entry {
            std::uint32_t node;
            double t_near;
        };
        std::array<entry, 2 * max_tree_depth + 8> stack;
        std::size_t top = 0;
        stack[top++] = {0, span.t_near};
        intersection best = intersection::none();
        while (top > 0) {
            const entry e = stack[--top];
            if (best.hit() && e.t_near > best.t) continue;  // its box starts beyond the best hit
            const node& nd = nodes_[e.node];
            if (nd.count > 0) {
                for (std::uint32_t k = nd.first; k < nd.first + nd.count; ++k) {
                    const intersection i = order_[k]->intersect(r);
                    if (i.nearer_than(best)) best = i;
                }
                continue;
            }
            const double t_max = best.hit() ? best.t : no_limit;
            const std::uint32_t left = e.node + 1, right = nd.right;
            ray_span sl, sr;
            const bool hit_left = hits_box(r, nodes_[left].bounds.lo, nodes_[left].bounds.hi, t_max, &sl);
            const bool hit_right = hits_box(r, nodes_[right].bounds.lo, nodes_[right].bounds.hi, t_max, &sr);
            if (hit_left && hit_right) {
                const bool left_first = sl.t_near <= sr.t_near;
                stack[top++] = left_first ? entry{right, sr.t_near} : entry{left, sl.t_near};  // the far one waits
                stack[top++] = left_first ? entry{left, sl.t_near} : entry{right, sr.t_near};
            } else if (hit_left) {
                stack[top++] = {left, sl.t_near};
            } else if (hit_right) {
                stack[top++] = {right, sr.t_near};
            }
        }
        return best.hit() ? best : intersection::composite_only(this);
    }

    int leaf_size_;
    mutable std::mutex build_mutex_;
    mutable std::atomic<bool> built_{false};
    mutable std::vector<node> nodes_;                  // the tree, root first (built by ensure_built)
    mutable std::vector<const rtab_component*> order_;  // the children as the leaves hold them
};

}  // namespace

std::unique_ptr<rtab_composite> make_bvh(int leaf_size) {
    if (leaf_size < 1 || leaf_size > 64)
        throw usage_error("make_bvh: leaf_size must be from 1 to 64, not " + std::to_string(leaf_size));
    return std::make_unique<bvh>(leaf_size);
}

}  // namespace vl::stage03
