// The bounding volume hierarchy (stage_03.hh): built with the surface area heuristic,
// walked with a stack, the child on the side the ray comes from first.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "stage_03.hh"
#include "vl/bounds.hh"
#include "vl/composite_bases.hh"

namespace vl::stage03 {

namespace {

/// \brief A binary tree of boxes over the children, built with the surface area
/// heuristic on the first ray after a change, walked near-first.
class bvh final : public shapes::bvh_base {
public:
    explicit bvh(int leaf_size) : bvh_base(leaf_size) {}

    point min_point() const override {
        ensure_built();
        return nodes_.empty() ? NaN_point : nodes_[0].lo;
    }
    point max_point() const override {
        ensure_built();
        return nodes_.empty() ? NaN_point : nodes_[0].hi;
    }

private:
    /// One node of the tree, all nodes in one vector (a suggestion).
    struct node {
        point lo, hi;             // the node's box: the union of its children's boxes
        std::uint32_t first = 0;  // a leaf: its children are order_[first, first + count)
        std::uint32_t count = 0;  // 0 for an inner node
        std::uint32_t left = 0;   // an inner node: its two children in nodes_
        std::uint32_t right = 0;
        int axis = 0;             // an inner node: the left child has the smaller centres along it
    };

    static constexpr int deepest = 64;  // below this depth, split by count

    static double coordinate(const point& p, int axis) { return axis == 0 ? p.x : axis == 1 ? p.y : p.z; }
    static void grow(point& lo, point& hi, const point& a, const point& b) {
        lo = point(std::fmin(lo.x, a.x), std::fmin(lo.y, a.y), std::fmin(lo.z, a.z));
        hi = point(std::fmax(hi.x, b.x), std::fmax(hi.y, b.y), std::fmax(hi.z, b.z));
    }
    static double area(const point& lo, const point& hi) {
        const vector e = hi - lo;
        return e.x * e.y + e.y * e.z + e.z * e.x;
    }

    struct entry {
        point lo, hi, centre;
        const rtab_component* object;
    };

    /// Makes the node for items[begin, end) at nodes_[at].
    void split(std::vector<entry>& items, std::size_t at, std::size_t begin, std::size_t end, int depth) const {
        point lo(INFINITY, INFINITY, INFINITY), hi(-INFINITY, -INFINITY, -INFINITY);
        point clo = lo, chi = hi;
        for (std::size_t i = begin; i < end; ++i) {
            grow(lo, hi, items[i].lo, items[i].hi);
            grow(clo, chi, items[i].centre, items[i].centre);
        }
        nodes_[at].lo = lo;
        nodes_[at].hi = hi;
        const std::size_t n = end - begin;
        auto leaf = [&] {
            nodes_[at].first = static_cast<std::uint32_t>(begin);
            nodes_[at].count = static_cast<std::uint32_t>(n);
        };
        if (n == 1) return leaf();

        int axis = -1;
        std::size_t cut = 0;
        double best = INFINITY;
        std::vector<double> after(n);
        for (int a = 0; a < 3 && depth < deepest; ++a) {
            if (!(coordinate(clo, a) < coordinate(chi, a))) continue;
            by_centre(items, begin, end, a);
            point rlo(INFINITY, INFINITY, INFINITY), rhi(-INFINITY, -INFINITY, -INFINITY);
            for (std::size_t k = n; k-- > 1;) {  // after[k]: the area of items k .. n-1
                grow(rlo, rhi, items[begin + k].lo, items[begin + k].hi);
                after[k] = area(rlo, rhi);
            }
            point llo(INFINITY, INFINITY, INFINITY), lhi(-INFINITY, -INFINITY, -INFINITY);
            for (std::size_t k = 1; k < n; ++k) {
                grow(llo, lhi, items[begin + k - 1].lo, items[begin + k - 1].hi);
                const double cost = area(llo, lhi) * static_cast<double>(k) + after[k] * static_cast<double>(n - k);
                if (cost < best) {
                    best = cost;
                    axis = a;
                    cut = k;
                }
            }
        }
        const double whole = area(lo, hi);
        const double split_cost = axis < 0 ? INFINITY : 1 + (whole > 0 ? best / whole : static_cast<double>(n));
        if (n <= static_cast<std::size_t>(leaf_size_) && split_cost >= static_cast<double>(n)) return leaf();
        if (axis < 0) {
            axis = 0;  // all centres alike (or too deep): half and half by count
            cut = n / 2;
        } else {
            by_centre(items, begin, end, axis);
        }
        const auto left = static_cast<std::uint32_t>(nodes_.size());
        nodes_.emplace_back();
        nodes_.emplace_back();
        nodes_[at].left = left;
        nodes_[at].right = left + 1;
        nodes_[at].axis = axis;
        nodes_[at].count = 0;
        split(items, left, begin, begin + cut, depth + 1);
        split(items, left + 1, begin + cut, end, depth + 1);
    }

    static void by_centre(std::vector<entry>& items, std::size_t begin, std::size_t end, int axis) {
        std::stable_sort(items.begin() + static_cast<std::ptrdiff_t>(begin), items.begin() + static_cast<std::ptrdiff_t>(end),
                         [axis](const entry& a, const entry& b) {
                             return coordinate(a.centre, axis) < coordinate(b.centre, axis);
                         });
    }

    void build() const override {
        nodes_.clear();
        order_.clear();
        if (children_.empty()) return;
        std::vector<entry> items;
        items.reserve(children_.size());
        for (const auto& c : children_) {
            const point a = c->min_point(), b = c->max_point();
            items.push_back({a, b, point((a.x + b.x) / 2, (a.y + b.y) / 2, (a.z + b.z) / 2), c.get()});
        }
        nodes_.reserve(2 * items.size());
        nodes_.emplace_back();
        split(items, 0, 0, items.size(), 0);
        for (const entry& e : items) order_.push_back(e.object);
    }

    intersection find_intersection(const ray& r) const override {
        ensure_built();
        if (nodes_.empty()) return intersection::none();
        ray_span root;
        if (!hits_box(r, nodes_[0].lo, nodes_[0].hi, 1e300, &root)) return intersection::none();
        const double dir[3] = {r.direction().x, r.direction().y, r.direction().z};
        struct todo {
            std::uint32_t node;
            double from;  // where the ray enters the node's box
        };
        std::array<todo, 2 * deepest + 64> stack;  // depth + 1 at most
        std::size_t size = 0;
        stack[size++] = {0, root.t_near};
        intersection best = intersection::none();
        while (size > 0) {
            const todo t = stack[--size];
            if (best.hit() && t.from > best.t) continue;
            const node& nd = nodes_[t.node];
            if (nd.count > 0) {
                for (std::uint32_t k = 0; k < nd.count; ++k) {
                    const intersection i = order_[nd.first + k]->intersect(r);
                    if (i.nearer_than(best)) best = i;
                }
                continue;
            }
            const double limit = best.hit() ? best.t : 1e300;
            ray_span sl, sr;
            const bool l = hits_box(r, nodes_[nd.left].lo, nodes_[nd.left].hi, limit, &sl);
            const bool rr = hits_box(r, nodes_[nd.right].lo, nodes_[nd.right].hi, limit, &sr);
            // A ray going up the split axis meets the left (lower) child first; pushed last,
            // it is popped first.
            const bool left_first = dir[nd.axis] >= 0;
            const todo near_one = left_first ? todo{nd.left, sl.t_near} : todo{nd.right, sr.t_near};
            const todo far_one = left_first ? todo{nd.right, sr.t_near} : todo{nd.left, sl.t_near};
            const bool near_hit = left_first ? l : rr, far_hit = left_first ? rr : l;
            if (far_hit) stack[size++] = far_one;
            if (near_hit) stack[size++] = near_one;
        }
        return best.hit() ? best : intersection::composite_only(this);
    }

    mutable std::vector<node> nodes_;                  // the tree, root first (made by build())
    mutable std::vector<const rtab_component*> order_;  // the children as the leaves hold them
};

}  // namespace

std::unique_ptr<rtab_composite> make_bvh(int leaf_size) {
    shapes::bvh_base::check_leaf_size(leaf_size);
    return std::make_unique<bvh>(leaf_size);
}

}  // namespace vl::stage03
