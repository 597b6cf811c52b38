// The bounding volume hierarchy as a linear BVH (Karras 2012): every child gets a Morton
// code, the 3 x 21 bits of its box centre's position in the box of all centres, bit by
// bit interleaved, so that sorting the codes lays the children along a Z-order curve.
// A node's range of the sorted children is split where its first and last code first
// differ (the highest differing bit: one side of a plane through the middle of a cell),
// found by binary search; a range of equal codes is split by count. A range of at most
// leaf_size children becomes a leaf unless that split is cheaper by the surface area
// heuristic. Nodes are stored depth first, each inner node followed by its left child,
// and walked near-first with a stack.
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <ostream>
#include <vector>

#include "sphere_bound.hh"
#include "stage_03.hh"
#include "vl/bounds.hh"
#include "vl/error.hh"
#include "vl/composite_bases.hh"

namespace vl::stage03 {

namespace {

constexpr double unlimited = 1e300;
constexpr int bits_per_axis = 21;

/// An axis-aligned box as two corners' coordinates.
struct aabb {
    double lo[3] = {unlimited, unlimited, unlimited};
    double hi[3] = {-unlimited, -unlimited, -unlimited};

    void grow(const aabb& b) {
        for (int a = 0; a < 3; ++a) {
            lo[a] = std::min(lo[a], b.lo[a]);
            hi[a] = std::max(hi[a], b.hi[a]);
        }
    }
    /// Half the surface area (only ratios of areas count).
    double half_area() const {
        const double dx = hi[0] - lo[0], dy = hi[1] - lo[1], dz = hi[2] - lo[2];
        return dx * dy + dy * dz + dz * dx;
    }
    point low() const { return point(lo[0], lo[1], lo[2]); }
    point high() const { return point(hi[0], hi[1], hi[2]); }
};

/// Spreads the low 21 bits of `v` so that bit i moves to bit 3i.
std::uint64_t spread(std::uint64_t v) {
    v &= 0x1fffffULL;
    v = (v | (v << 32)) & 0x1f00000000ffffULL;
    v = (v | (v << 16)) & 0x1f0000ff0000ffULL;
    v = (v | (v << 8)) & 0x100f00f00f00f00fULL;
    v = (v | (v << 4)) & 0x10c30c30c30c30c3ULL;
    v = (v | (v << 2)) & 0x1249249249249249ULL;
    return v;
}

class linear_bvh final : public shapes::bvh_base {
public:
    explicit linear_bvh(int leaf_size) : bvh_base(leaf_size) {}

    void insert(std::unique_ptr<rtab_component> child) override {
        if (!child) throw usage_error("BVH: insert() was given a null pointer, not an object");
        if (child.get() == this) throw usage_error("BVH: a BVH cannot hold itself");
        if (!box_is_finite(*child)) {
            const std::string kind = child->type_name();
            throw usage_error("BVH cannot hold a " + kind + ": the " + kind +
                              " has no finite box (it is unbounded or empty), so no box of the tree holds it;"
                              " put the " + kind + " beside the BVH in a LIST");
        }
        adopt(std::move(child));  // marks the tree to be built again
    }

    point min_point() const override {
        ensure_built();
        return nodes_.empty() ? NaN_point : nodes_.front().box.low();
    }
    point max_point() const override {
        ensure_built();
        return nodes_.empty() ? NaN_point : nodes_.front().box.high();
    }

private:
    /// A node; its left child (an inner node's) is the next node in nodes_.
    struct node {
        aabb box;
        std::uint32_t first = 0;  // a leaf: its children are leaves_[first, first + count)
        std::uint32_t count = 0;  // 0: an inner node
        std::uint32_t right = 0;  // an inner node: the index of its right child
    };

    void build() const override {
        nodes_.clear();
        leaves_.clear();
        boxes_.clear();
        codes_.clear();
        const std::size_t n = children_.size();
        if (n == 0) return;
        boxes_.resize(n);
        aabb centres;
        std::vector<std::array<double, 3>> mid(n);
        for (std::size_t k = 0; k < n; ++k) {
            const point lo = children_[k]->min_point(), hi = children_[k]->max_point();
            boxes_[k] = aabb{{lo.x, lo.y, lo.z}, {hi.x, hi.y, hi.z}};
            for (int a = 0; a < 3; ++a) {
                mid[k][static_cast<std::size_t>(a)] = 0.5 * (boxes_[k].lo[a] + boxes_[k].hi[a]);
                centres.lo[a] = std::min(centres.lo[a], mid[k][static_cast<std::size_t>(a)]);
                centres.hi[a] = std::max(centres.hi[a], mid[k][static_cast<std::size_t>(a)]);
            }
        }
        // The Morton code of each child's centre in the box of all centres.
        const double cells = static_cast<double>((1u << bits_per_axis) - 1);
        std::vector<std::uint64_t> code(n);
        for (std::size_t k = 0; k < n; ++k) {
            std::uint64_t c = 0;
            for (int a = 0; a < 3; ++a) {
                const double extent = centres.hi[a] - centres.lo[a];
                const double unit = extent > 0 ? (mid[k][static_cast<std::size_t>(a)] - centres.lo[a]) / extent : 0;
                const auto q = static_cast<std::uint64_t>(std::clamp(unit, 0.0, 1.0) * cells);
                c |= spread(q) << (2 - a);  // x in the highest bit of each triple
            }
            code[k] = c;
        }
        std::vector<std::uint32_t> order(n);
        std::iota(order.begin(), order.end(), 0u);
        std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return code[a] < code[b]; });
        codes_.resize(n);
        leaves_.resize(n);
        std::vector<aabb> sorted_boxes(n);
        for (std::size_t k = 0; k < n; ++k) {
            codes_[k] = code[order[k]];
            leaves_[k] = children_[order[k]].get();
            sorted_boxes[k] = boxes_[order[k]];
        }
        boxes_ = std::move(sorted_boxes);
        nodes_.reserve(2 * n);
        emit(0, static_cast<std::uint32_t>(n));
        codes_.clear();
        boxes_.clear();
    }

    /// Where to split the sorted range [first, last) of at least two children: the first
    /// index whose code differs from codes_[first] in the highest bit where codes_[first]
    /// and codes_[last - 1] differ; the middle when all codes are equal.
    std::uint32_t morton_split(std::uint32_t first, std::uint32_t last) const {
        const std::uint64_t a = codes_[first], b = codes_[last - 1];
        if (a == b) return first + (last - first) / 2;
        const int common = std::countl_zero(a ^ b);
        // Binary search for the last index that shares more than `common` leading bits
        // with codes_[first]; the codes are sorted, so those come first.
        std::uint32_t lo = first, hi = last - 1;  // lo shares, hi does not
        while (hi - lo > 1) {
            const std::uint32_t m = lo + (hi - lo) / 2;
            if (std::countl_zero(a ^ codes_[m]) > common)
                lo = m;
            else
                hi = m;
        }
        return hi;
    }

    aabb range_box(std::uint32_t first, std::uint32_t last) const {
        aabb b;
        for (std::uint32_t k = first; k < last; ++k) b.grow(boxes_[k]);
        return b;
    }

    /// Appends the subtree over the sorted children [first, last) and returns its index.
    std::uint32_t emit(std::uint32_t first, std::uint32_t last) const {
        const auto index = static_cast<std::uint32_t>(nodes_.size());
        nodes_.emplace_back();
        const std::uint32_t count = last - first;
        std::uint32_t split = 0;
        bool leaf = count == 1;
        if (!leaf) {
            split = morton_split(first, last);
            if (count <= static_cast<std::uint32_t>(leaf_size_)) {
                // Testing all `count` children, or two boxes and then the expected share of
                // each half (the chance of entering a box is its area over the node's).
                const double whole = range_box(first, last).half_area();
                const double sah = whole > 0 ? 1 + (range_box(first, split).half_area() * (split - first) +
                                                    range_box(split, last).half_area() * (last - split)) /
                                                       whole
                                             : 1 + count;
                leaf = !(sah < count);
            }
        }
        if (leaf) {
            nodes_[index].box = range_box(first, last);
            nodes_[index].first = first;
            nodes_[index].count = count;
            return index;
        }
        const std::uint32_t left = emit(first, split);
        const std::uint32_t right = emit(split, last);
        aabb b = nodes_[left].box;
        b.grow(nodes_[right].box);
        nodes_[index].box = b;
        nodes_[index].right = right;
        return index;
    }

    intersection find_intersection(const ray& r) const override {
        ensure_built();
        if (nodes_.empty()) return intersection::none();
        ray_span span;
        if (!hits_box(r, nodes_[0].box.low(), nodes_[0].box.high(), unlimited, &span)) return intersection::none();
        struct pending {
            std::uint32_t node;
            double t_near;
        };
        std::array<pending, 256> stack;
        std::size_t top = 0;
        stack[top++] = {0, span.t_near};
        intersection best = intersection::none();
        while (top > 0) {
            const pending p = stack[--top];
            if (best.hit() && p.t_near >= best.t) continue;  // its box starts beyond the best hit
            const node& nd = nodes_[p.node];
            if (nd.count > 0) {
                for (std::uint32_t k = nd.first; k < nd.first + nd.count; ++k) {
                    const intersection i = leaves_[k]->intersect(r);
                    if (i.nearer_than(best)) best = i;
                }
                continue;
            }
            const double t_max = best.hit() ? best.t : unlimited;
            const std::uint32_t kids[2] = {p.node + 1, nd.right};
            ray_span spans[2];
            bool entered[2];
            for (int s = 0; s < 2; ++s)
                entered[s] = hits_box(r, nodes_[kids[s]].box.low(), nodes_[kids[s]].box.high(), t_max, &spans[s]);
            if (entered[0] && entered[1]) {
                const int nearer = spans[1].t_near < spans[0].t_near ? 1 : 0;
                stack[top++] = {kids[1 - nearer], spans[1 - nearer].t_near};  // visited later
                stack[top++] = {kids[nearer], spans[nearer].t_near};
            } else {
                for (int s = 0; s < 2; ++s)
                    if (entered[s]) stack[top++] = {kids[s], spans[s].t_near};
            }
        }
        return best.hit() ? best : intersection::composite_only(this);
    }

    mutable std::vector<node> nodes_;                    // the tree, root first, depth first
    mutable std::vector<const rtab_component*> leaves_;  // the children in Morton order
    mutable std::vector<aabb> boxes_;                    // while building: their boxes
    mutable std::vector<std::uint64_t> codes_;           // while building: their codes
};

}  // namespace

std::unique_ptr<rtab_composite> make_bvh(int leaf_size) {
    shapes::bvh_base::check_leaf_size(leaf_size);
    return std::make_unique<linear_bvh>(leaf_size);
}

}  // namespace vl::stage03
