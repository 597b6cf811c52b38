// Reference: the bounding volume hierarchy (see assignments/03-composites/stage_03.hh).
//
// Built with the surface area heuristic over 32 bins of the children's centres (I. Wald,
// "On fast construction of SAH-based bounding volume hierarchies", IEEE Symposium on
// Interactive Ray Tracing 2007); stored flat, each inner node one 64-byte cache line that
// holds its two children's boxes, in floats rounded outwards; walked near-first with a
// slab test that takes the ray's reciprocal direction once per ray (A. Williams,
// S. Barrus, R. K. Morley and P. Shirley, "An efficient and robust ray-box intersection
// algorithm", JGT 10(1), 2005). The shell (the children, reading, writing, building once
// at the first ray) is vl::shapes::bvh_base.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "stage_03.hh"
#include "vl/bounds.hh"
#include "vl/composite_bases.hh"
#include "vl/stats.hh"

namespace vl::stage03 {

namespace {

// What entering an inner node costs, in units of one child's intersect(): its two box
// tests, each counted as one test, as the budgets count them.
constexpr double traversal_cost = 2;
constexpr int max_bins = 32;          // SAH bins per axis (Wald 2007 finds 16 to 32 enough)
constexpr int max_sah_depth = 60;     // deeper than this, split by count (always balanced)
// The deepest tree: 60 SAH levels, then halving at most 32 times (2^32 children).
constexpr int max_tree_depth = max_sah_depth + 32;

/// A box in double precision, as the children report it (and the root's exact box). Its
/// corners are never NaN (insert() refuses a child without a finite box), so std::min and
/// std::max serve, which compile to one instruction where std::fmin is a library call.
struct box3 {
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    void grow(const box3& b) {
        for (int k = 0; k < 3; ++k) {
            lo[k] = std::min(lo[k], b.lo[k]);
            hi[k] = std::max(hi[k], b.hi[k]);
        }
    }
    void grow(const double p[3]) {
        for (int k = 0; k < 3; ++k) {
            lo[k] = std::min(lo[k], p[k]);
            hi[k] = std::max(hi[k], p[k]);
        }
    }
    /// Half the surface area (the factor 2 cancels in every ratio); 0 for an empty box.
    double half_area() const {
        if (!(lo[0] <= hi[0])) return 0;
        const double x = hi[0] - lo[0], y = hi[1] - lo[1], z = hi[2] - lo[2];
        return x * y + y * z + z * x;
    }
};

/// The float nearest `x` on the side away from the box's inside, so that a float box
/// always contains the double box it stands for (the round trip through float would
/// otherwise move a face inwards by up to half a float step).
float round_down(double x) {
    const auto f = static_cast<float>(x);
    return static_cast<double>(f) > x ? std::nextafter(f, -INFINITY) : f;
}
float round_up(double x) {
    const auto f = static_cast<float>(x);
    return static_cast<double>(f) < x ? std::nextafter(f, INFINITY) : f;
}

/// A ray prepared for many slab tests: its origin, its reciprocal direction and, per axis,
/// which face of a box it meets first (1 when the direction is negative, so the high face).
/// A zero direction component has the reciprocal +-infinity, which the slab test handles.
struct slab_ray {
    double origin[3], inverse[3];
    int first_face[3];
    explicit slab_ray(const ray& r) {
        const point& o = r.origin();
        const vector& d = r.direction();
        const double dir[3] = {d.x, d.y, d.z};
        origin[0] = o.x, origin[1] = o.y, origin[2] = o.z;
        for (int k = 0; k < 3; ++k) {
            inverse[k] = 1.0 / dir[k];
            first_face[k] = std::signbit(dir[k]) ? 1 : 0;
        }
    }
};

// Each slab's far distance is stretched by this factor, covering the rounding of the two
// operations that compute it and of the near distance (M. Pharr, W. Jakob and
// G. Humphreys, *Physically Based Rendering*, 4th ed., 6.8.2: 1 + 2 gamma(3)).
constexpr double far_stretch = 1 + 2 * (3 * 0x1p-53 / (1 - 3 * 0x1p-53));

/// \brief The tree over the children, built on the first ray after a change.
class bvh final : public shapes::bvh_base {
public:
    explicit bvh(int leaf_size) : bvh_base(leaf_size) {}

    point min_point() const override {
        ensure_built();
        return order_.empty() ? NaN_point : point(root_.lo[0], root_.lo[1], root_.lo[2]);
    }
    point max_point() const override {
        ensure_built();
        return order_.empty() ? NaN_point : point(root_.hi[0], root_.hi[1], root_.hi[2]);
    }

private:
    /// Where a subtree is: an inner node, or a leaf's run of children in order_.
    struct subtree {
        std::uint32_t index = 0;  // count 0: nodes_[index]; otherwise order_[index, index + count)
        std::uint32_t count = 0;  // a leaf: how many children it holds
    };

    /// An inner node in one cache line: the boxes of its two subtrees and where they are,
    /// so that the two box tests of a node read one line. Leaves are not nodes: a leaf is
    /// a run of children that its parent points to.
    struct node {
        float bounds[2][2][3];  // [subtree][0 low corner, 1 high corner][axis], rounded outwards
        subtree child[2];       // [0] left, [1] right
    };
    static_assert(sizeof(node) == 64);

    struct item {
        box3 bounds;
        double centre[3];
        const rtab_component* object;
    };

    void build() const override {
        nodes_.clear();
        order_.clear();
        root_ = {};
        if (children_.empty()) return;
        std::vector<item> items;
        items.reserve(children_.size());
        for (const auto& c : children_) {
            const point lo = c->min_point(), hi = c->max_point();
            item it{{{lo.x, lo.y, lo.z}, {hi.x, hi.y, hi.z}}, {}, c.get()};
            for (int k = 0; k < 3; ++k) it.centre[k] = (it.bounds.lo[k] + it.bounds.hi[k]) / 2;
            items.push_back(it);
        }
        for (const item& it : items) root_.grow(it.bounds);
        nodes_.reserve(items.size());
        root_subtree_ = build_subtree(items, 0, items.size(), 0, root_);
        nodes_.shrink_to_fit();  // N - 1 nodes at most, usually far fewer
        order_.reserve(items.size());
        for (const item& it : items) order_.push_back(it.object);
    }

    /// Builds the subtree of items[begin, end), whose box is `bounds`; returns where it is.
    subtree build_subtree(std::vector<item>& items, std::size_t begin, std::size_t end, int depth,
                          const box3& bounds) const {
        const std::size_t n = end - begin;
        const subtree leaf{static_cast<std::uint32_t>(begin), static_cast<std::uint32_t>(n)};
        if (n == 1) return leaf;
        box3 centres;
        for (std::size_t i = begin; i < end; ++i) centres.grow(items[i].centre);

        const split best = depth < max_sah_depth ? cheapest_split(items, begin, end, bounds, centres) : split{};
        if (n <= static_cast<std::size_t>(leaf_size_) && !(best.cost < static_cast<double>(n))) return leaf;
        std::size_t middle;
        if (best.axis < 0) {  // every centre alike, or too deep: split by count
            middle = begin + n / 2;
        } else {
            const int axis = best.axis;
            const int bins = bins_for(n);
            const double lo = centres.lo[axis], scale = bins / (centres.hi[axis] - centres.lo[axis]);
            const auto right_of_split = std::partition(
                items.begin() + static_cast<std::ptrdiff_t>(begin), items.begin() + static_cast<std::ptrdiff_t>(end),
                [&](const item& it) { return bin_of(it.centre[axis], lo, scale, bins) < best.bin; });
            middle = static_cast<std::size_t>(right_of_split - items.begin());
        }
        const auto index = static_cast<std::uint32_t>(nodes_.size());
        nodes_.emplace_back();
        const std::size_t from[2] = {begin, middle}, to[2] = {middle, end};
        for (int side = 0; side < 2; ++side) {
            box3 box;
            for (std::size_t i = from[side]; i < to[side]; ++i) box.grow(items[i].bounds);
            for (int k = 0; k < 3; ++k) {
                nodes_[index].bounds[side][0][k] = round_down(box.lo[k]);
                nodes_[index].bounds[side][1][k] = round_up(box.hi[k]);
            }
            const subtree child = build_subtree(items, from[side], to[side], depth + 1, box);
            nodes_[index].child[side] = child;  // after the call, which may move nodes_
        }
        return {index, 0};
    }

    struct split {
        double cost = INFINITY;
        int axis = -1;  // -1: no split found
        int bin = 0;    // the left side takes the bins below this one
    };

    /// As many bins as children, up to max_bins: a few children need no more.
    static int bins_for(std::size_t n) { return static_cast<int>(std::min<std::size_t>(n, max_bins)); }
    static int bin_of(double centre, double lo, double scale, int bins) {
        return std::min(bins - 1, static_cast<int>((centre - lo) * scale));
    }

    /// The split between two bins of centres that the surface area heuristic finds
    /// cheapest, over the three axes: traversal_cost + (A_left N_left + A_right N_right) / A.
    static split cheapest_split(const std::vector<item>& items, std::size_t begin, std::size_t end,
                                const box3& bounds, const box3& centres) {
        const double area = bounds.half_area();
        const auto n = static_cast<double>(end - begin);
        const int bins = bins_for(end - begin);
        split best;
        for (int axis = 0; axis < 3; ++axis) {
            const double extent = centres.hi[axis] - centres.lo[axis];
            if (!(extent > 0)) continue;  // all centres alike along this axis
            const double lo = centres.lo[axis], scale = bins / extent;
            std::array<box3, max_bins> bin_bounds;
            std::array<std::size_t, max_bins> bin_items{};
            for (std::size_t i = begin; i < end; ++i) {
                const int b = bin_of(items[i].centre[axis], lo, scale, bins);
                bin_bounds[static_cast<std::size_t>(b)].grow(items[i].bounds);
                ++bin_items[static_cast<std::size_t>(b)];
            }
            // right_cost[b]: A N of bins b and above.
            std::array<double, max_bins> right_cost{};
            box3 right;
            std::size_t right_items = 0;
            for (int b = bins - 1; b > 0; --b) {
                right.grow(bin_bounds[static_cast<std::size_t>(b)]);
                right_items += bin_items[static_cast<std::size_t>(b)];
                right_cost[static_cast<std::size_t>(b)] = right.half_area() * static_cast<double>(right_items);
            }
            box3 left;
            std::size_t left_items = 0;
            for (int b = 1; b < bins; ++b) {  // the left side: bins below b
                left.grow(bin_bounds[static_cast<std::size_t>(b - 1)]);
                left_items += bin_items[static_cast<std::size_t>(b - 1)];
                if (left_items == 0 || left_items == end - begin) continue;  // one side empty: no split
                const double weighted = left.half_area() * static_cast<double>(left_items) + right_cost[static_cast<std::size_t>(b)];
                const double cost = traversal_cost + (area > 0 ? weighted / area : n);
                if (cost < best.cost) best = {cost, axis, b};
            }
        }
        return best;
    }

    /// The slab test of `box` against `sr` for t in [0, t_max]: true, with where
    /// the ray enters the box in `t_near`, when the ray passes through it. Branch-free: the
    /// face met first comes from the direction's sign, and the IEEE rules do the rest. A
    /// zero direction component gives distances of +-infinity (inside the slab or never);
    /// the NaN of 0 * infinity, for an origin on a face of such a slab, is dropped by
    /// std::max and std::min as their second argument, so that slab limits nothing.
    static bool slabs(const float (&box)[2][3], const slab_ray& sr, double t_max, double& t_near) {
        double t0 = 0, t1 = t_max;
        for (int k = 0; k < 3; ++k) {
            const double near = (box[sr.first_face[k]][k] - sr.origin[k]) * sr.inverse[k];
            const double far = (box[1 - sr.first_face[k]][k] - sr.origin[k]) * sr.inverse[k] * far_stretch;
            t0 = std::max(t0, near);
            t1 = std::min(t1, far);
        }
        t_near = t0;
        return t0 <= t1;
    }

    intersection find_intersection(const ray& r) const override {
        ensure_built();
        if (order_.empty()) return intersection::none();
        const point lo(root_.lo[0], root_.lo[1], root_.lo[2]), hi(root_.hi[0], root_.hi[1], root_.hi[2]);
        ray_span span;
        if (!hits_box(r, lo, hi, INFINITY, &span)) return intersection::none();  // counts its test
        const slab_ray sr(r);
        struct entry {
            subtree where;
            double t_near;
        };
        std::array<entry, max_tree_depth + 2> stack;  // near-first keeps at most one entry per level
        std::size_t top = 0;
        stack[top++] = {root_subtree_, span.t_near};
        std::uint64_t box_tests = 0;
        intersection best = intersection::none();
        while (top > 0) {
            const entry e = stack[--top];
            if (best.hit() && e.t_near > best.t) continue;  // its box starts beyond the best hit
            if (e.where.count > 0) {  // a leaf
                for (std::uint32_t k = e.where.index; k < e.where.index + e.where.count; ++k) {
                    const intersection i = order_[k]->intersect(r);
                    if (i.nearer_than(best)) best = i;
                }
                continue;
            }
            const node& nd = nodes_[e.where.index];
            const double t_max = best.hit() ? best.t : INFINITY;
            double near_left, near_right;
            const bool hit_left = slabs(nd.bounds[0], sr, t_max, near_left);
            const bool hit_right = slabs(nd.bounds[1], sr, t_max, near_right);
            box_tests += 2;
            const entry left{nd.child[0], near_left}, right{nd.child[1], near_right};
            if (hit_left && hit_right) {
                const bool left_first = near_left <= near_right;
                stack[top++] = left_first ? right : left;  // the far one waits
                stack[top++] = left_first ? left : right;
            } else if (hit_left) {
                stack[top++] = left;
            } else if (hit_right) {
                stack[top++] = right;
            }
        }
        count_bounding_volume_tests(box_tests);
        return best.hit() ? best : intersection::composite_only(this);
    }

    mutable box3 root_;                                 // the children's box, exactly
    mutable subtree root_subtree_;                     // the root: nodes_[0], or one leaf
    mutable std::vector<node> nodes_;                  // the inner nodes, root first (built by ensure_built)
    mutable std::vector<const rtab_component*> order_;  // the children as the leaves hold them
};

}  // namespace

std::unique_ptr<rtab_composite> make_bvh(int leaf_size) {
    return shapes::bvh_base::make<bvh>(leaf_size);
}

}  // namespace vl::stage03
