// Reference: the bounding volume hierarchy (see assignments/03-composites/stage_03.hh).
//
// Built with the surface area heuristic over 32 bins of the children's centres (I. Wald,
// "On fast construction of SAH-based bounding volume hierarchies", IEEE Symposium on
// Interactive Ray Tracing 2007) as a binary tree, then collapsed into a tree of eight
// subtrees per node (I. Wald, C. Benthin and S. Boulos, "Getting rid of packets", IEEE
// Symposium on Interactive Ray Tracing 2008; Embree builds its BVH8 so): a ray tests the
// eight boxes of a node together, four at a time in one vector of floats, and visits a
// third as many nodes as in the binary tree. A leaf is a run of slots in blocks of four:
// each slot holds a ball around one child, in float, and the child's address, so that a
// ray tests a leaf's balls together and calls only the children whose ball its line
// meets (a sphere's ball is the sphere, rtab_component::bounding_ball(); any other
// child's is the ball around its box). The surface area heuristic counts a leaf's cost
// by its blocks, as Embree does, so that leaves fill them. Boxes are rounded outwards to
// float, balls grown, and the float arithmetic's own rounding covered, so no hit is lost
// (A. Williams, S. Barrus, R. K. Morley and P. Shirley, "An efficient and robust ray-box
// intersection algorithm", JGT 10(1), 2005; M. Pharr, W. Jakob and G. Humphreys,
// *Physically Based Rendering*, 4th ed., 6.8.2). The shell (the children, reading,
// writing, building once at the first ray) is vl::shapes::bvh_base.
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

#include "stage_03.hh"
#include "vl/composite_bases.hh"
#include "vl/stats.hh"

namespace vl::stage03 {

namespace {

// What entering an inner node costs, in units of one child's intersect(): its two box
// tests, each counted as one test, as the budgets count them.
constexpr double traversal_cost = 2;
// What testing a block of four balls costs, in the same units: about one child test.
constexpr double block_cost = 1;
constexpr int width = 8;        // subtrees per node
constexpr int block_slots = 4;  // children per block
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

/// The next float above `f`, one step of its bits (pbrt-v4's NextFloatUp, 6.8.1): what
/// std::nextafter(f, INFINITY) gives for every float but NaN, without a library call,
/// since a ray rounds its origin with it.
float next_float_up(float f) {
    if (f == INFINITY) return f;
    if (f == 0) return std::numeric_limits<float>::denorm_min();  // from +0 and -0 alike
    const auto bits = std::bit_cast<std::uint32_t>(f);
    return std::bit_cast<float>(f > 0 ? bits + 1 : bits - 1);
}
float next_float_down(float f) { return -next_float_up(-f); }

/// The float nearest `x` on the side away from the box's inside, so that a float box
/// always contains the double box it stands for (the round trip through float would
/// otherwise move a face inwards by up to half a float step).
float round_down(double x) {
    const auto f = static_cast<float>(x);
    return static_cast<double>(f) > x ? next_float_down(f) : f;
}
float round_up(double x) {
    const auto f = static_cast<float>(x);
    return static_cast<double>(f) < x ? next_float_up(f) : f;
}

/// Four floats that the compiler keeps in one SSE register (a GCC and Clang vector
/// extension): `+`, `-`, `*`, `<` and `?:` act on the four lanes at once, lane c holding
/// what belongs to a node's subtree c (or to a block's child c). A comparison gives a
/// mask4, -1 where it holds.
using float4 = float __attribute__((vector_size(16)));
using mask4 = std::int32_t __attribute__((vector_size(16)));

/// Each slab's far distance, and the best hit's distance, are stretched by this factor. It
/// covers the rounding of the float arithmetic: the inverse direction, the subtraction and
/// the product each round once, by at most 2^-24 relative (pbrt, 6.8.2: 1 + 2 gamma(3)),
/// and the stretch itself once more; 1 + 4 gamma(3) leaves a margin.
constexpr float far_stretch = 1 + 4 * (3 * 0x1p-24f / (1 - 3 * 0x1p-24f));

/// A ray prepared for many slab tests in float: per axis, the reciprocal direction, which
/// face of a box it meets first and which last (as rows of a node's bounds read as six
/// rows, low x, y, z then high x, y, z: the high face comes first when the direction is
/// negative), and the origin rounded twice. The near distance is taken from the float
/// origin rounded so that it comes out no larger than the exact one, the far distance
/// from the one rounded the other way, so the origin's rounding to float never moves a
/// face across it. A zero direction component has the reciprocal +-infinity (as does one
/// below 3e-39 in magnitude, whose reciprocal no float holds), which the slab test
/// handles. Each value is held in all four lanes, ready for four boxes. For the ball tests
/// it also keeps the origin and the direction as the nearest floats, and the origin's
/// largest coordinate, by which their rounding is bounded.
struct slab_ray {
    float4 origin_near[3], origin_far[3], inverse[3];
    float4 origin[3], direction[3];
    float origin_size;
    int near_row[3], far_row[3];
    explicit slab_ray(const ray& r) {
        const point& o = r.origin();
        const vector& d = r.direction();
        const double dir[3] = {d.x, d.y, d.z}, from[3] = {o.x, o.y, o.z};
        for (int k = 0; k < 3; ++k) {
            const bool negative = std::signbit(dir[k]);
            near_row[k] = negative ? 3 + k : k;
            far_row[k] = negative ? k : 3 + k;
            inverse[k] = float4{} + 1 / static_cast<float>(dir[k]);
            // (face - origin) * inverse is smallest with the origin rounded up when the
            // direction is positive, and with it rounded down when it is negative.
            origin_near[k] = float4{} + (negative ? round_down(from[k]) : round_up(from[k]));
            origin_far[k] = float4{} + (negative ? round_up(from[k]) : round_down(from[k]));
            origin[k] = float4{} + static_cast<float>(from[k]);
            direction[k] = float4{} + static_cast<float>(dir[k]);
        }
        origin_size = round_up(std::max({std::fabs(from[0]), std::fabs(from[1]), std::fabs(from[2])}));
    }
};

/// `t`, a distance in double, as a float bound for the slab test: rounded up and stretched.
float float_limit(double t) { return round_up(t) * far_stretch; }

/// \brief The tree over the children, built on the first ray after a change.
class bvh final : public shapes::bvh_base {
public:
    explicit bvh(int leaf_size) : bvh_base(leaf_size) {}

    point min_point() const override {
        ensure_built();
        return children_.empty() ? NaN_point : point(root_.lo[0], root_.lo[1], root_.lo[2]);
    }
    point max_point() const override {
        ensure_built();
        return children_.empty() ? NaN_point : point(root_.hi[0], root_.hi[1], root_.hi[2]);
    }

private:
    /// Where a subtree is, as the binary tree holds it: an inner node, or a leaf's run of
    /// items.
    struct subtree {
        std::uint32_t index;  // count 0: binary[index]; otherwise items[index, index + count)
        std::uint32_t count;  // a leaf: how many children it holds
    };

    /// Where a lane of a node leads, in 8 bytes: another node, one child (a pointer to the
    /// child itself, so that the walk loads nothing between a node and the child it
    /// calls), or a leaf's run of slots in the blocks. The two low bits say which (a
    /// child's address is a multiple of 8, so they are free); a lane without a subtree
    /// holds 0.
    /// (No default value, so that the walk's stack of them is not cleared for each ray.)
    class link {
    public:
        link() = default;
        static link none() { return from_bits(0); }
        static link to_node(std::uint32_t index) { return from_bits(std::uint64_t{index} << tag_bits | node_tag); }
        static link to_child(const rtab_component* c) {
            return from_bits(reinterpret_cast<std::uintptr_t>(c) | child_tag);
        }
        /// Slots [first, first + count) of the blocks (slot s is child s % 4 of block
        /// s / 4), count at most 64 (the largest leaf_size).
        static link to_slots(std::uint64_t first, std::uint32_t count) {
            return from_bits((first << count_bits | count) << tag_bits | slots_tag);
        }

        bool is_none() const { return bits_ == 0; }
        bool is_node() const { return (bits_ & tag_mask) == node_tag; }
        bool is_child() const { return (bits_ & tag_mask) == child_tag; }
        std::uint32_t node_index() const { return static_cast<std::uint32_t>(bits_ >> tag_bits); }
        const rtab_component* child() const {
            return reinterpret_cast<const rtab_component*>(static_cast<std::uintptr_t>(bits_ & ~tag_mask));
        }
        std::uint64_t first_slot() const { return bits_ >> (tag_bits + count_bits); }
        std::uint32_t slot_count() const {
            return static_cast<std::uint32_t>(bits_ >> tag_bits & ((std::uint64_t{1} << count_bits) - 1));
        }

    private:
        static constexpr int tag_bits = 2, count_bits = 7;  // a leaf's count: 2 to 64 fits in 7 bits
        static constexpr std::uint64_t tag_mask = 3, node_tag = 1, child_tag = 2, slots_tag = 3;
        static link from_bits(std::uint64_t bits) {
            link l;
            l.bits_ = bits;
            return l;
        }
        std::uint64_t bits_;
    };
    static_assert(alignof(rtab_component) >= 4, "a link keeps its tag in a child's two low address bits");

    /// The binary tree as the surface area heuristic builds it, in double; build() then
    /// collapses it into nodes_ and drops it.
    struct binary_node {
        box3 bounds[2];     // [0] left, [1] right
        subtree child[2];
    };

    /// An inner node: the boxes of up to eight subtrees, four lanes to a float4, and where
    /// they are. Leaves are not nodes: a leaf is a run of slots (or one child) that its
    /// parent points to. A lane without a subtree has the empty box (low corner
    /// +infinity, high -infinity), which every ray misses, and link::none(). Four 64-byte
    /// cache lines: the boxes, then the links.
    struct alignas(64) node {
        float4 bounds[2][3][width / 4];  // [0 low corner, 1 high corner][axis][lanes 0-3, 4-7], rounded outwards
        link child[width];
        /// How many lanes hold a subtree, so how many boxes a visit tests: 2 to 8 (the
        /// lanes in use come first).
        int lanes() const {
            int n = 2;
            while (n < width && !child[n].is_none()) ++n;
            return n;
        }
    };
    static_assert(sizeof(node) == 256);

    /// Four slots of leaves: around each child a ball, its centre's x, y and z and its
    /// radius lane by lane, in float, grown to hold the child's ball (see set_slot()), and
    /// the child. A slot that holds no child has the radius -infinity and no child. One
    /// leaf's slots are consecutive; a leaf of up to four sits in one block, which it may
    /// share with other small leaves.
    struct alignas(32) block {
        float4 ball[4] = {{}, {}, {}, {-INFINITY, -INFINITY, -INFINITY, -INFINITY}};  // centre x, y, z, radius
        const rtab_component* child[block_slots] = {};
    };
    static_assert(sizeof(block) == 96);

    struct item {
        box3 bounds;
        double centre[3];
        const rtab_component* object;
    };

    void build() const override {
        nodes_.clear();
        blocks_.clear();
        ball_size_ = 0;
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
        for (int c = 0; c < width; ++c) set_lane(root_box_, c, c == 0 ? &root_ : nullptr);
        std::vector<binary_node> binary;
        binary.reserve(items.size());
        const subtree binary_root = build_subtree(binary, items, 0, items.size(), 0, root_);
        std::array<std::vector<std::uint32_t>, block_slots> open;  // blocks with free slots, by how many
        root_link_ = to_link(binary, items, open, binary_root);
        nodes_.shrink_to_fit();
        blocks_.shrink_to_fit();
    }

    /// Lane c of a node's boxes: `box` rounded outwards, or the empty box (low corner
    /// +infinity, high -infinity), which every ray misses, where `box` is null.
    static void set_lane(float4 (&bounds)[2][3][width / 4], int c, const box3* box) {
        for (int k = 0; k < 3; ++k) {
            bounds[0][k][c / 4][c % 4] = box ? round_down(box->lo[k]) : INFINITY;
            bounds[1][k][c / 4][c % 4] = box ? round_up(box->hi[k]) : -INFINITY;
        }
    }

    /// The node that stands for binary[index] and the binary nodes below it, up to eight
    /// subtrees: starting from its two, the largest subtree that is an inner node is
    /// replaced by its two until there are eight or only leaves (Wald, Benthin and Boulos
    /// 2008). Nodes are stored parent first, so a node is usually near its first subtree.
    std::uint32_t collapse(const std::vector<binary_node>& binary, const std::vector<item>& items,
                           std::array<std::vector<std::uint32_t>, block_slots>& open, std::uint32_t index) const {
        struct lane {
            subtree where;
            box3 bounds;
        };
        std::array<lane, width> lanes{};
        int used = 2;
        for (int side = 0; side < 2; ++side) lanes[side] = {binary[index].child[side], binary[index].bounds[side]};
        while (used < width) {
            int widest = -1;  // the inner lane with the largest surface
            for (int c = 0; c < used; ++c) {
                if (lanes[c].where.count == 0 && (widest < 0 || lanes[c].bounds.half_area() > lanes[widest].bounds.half_area()))
                    widest = c;
            }
            if (widest < 0) break;  // only leaves
            const binary_node& opened = binary[lanes[widest].where.index];
            lanes[widest] = {opened.child[0], opened.bounds[0]};
            lanes[used++] = {opened.child[1], opened.bounds[1]};
        }
        const auto at = static_cast<std::uint32_t>(nodes_.size());
        nodes_.emplace_back();
        for (int c = 0; c < width; ++c) set_lane(nodes_[at].bounds, c, c < used ? &lanes[c].bounds : nullptr);
        for (int c = 0; c < used; ++c) {
            const link child = to_link(binary, items, open, lanes[c].where);
            nodes_[at].child[c] = child;  // after the call, which may move nodes_
        }
        return at;
    }

    /// The link to `where`: an inner node is collapse()d into nodes_; a leaf of one child
    /// points at the child (its lane's box is its only test); a bigger one gets slots.
    link to_link(const std::vector<binary_node>& binary, const std::vector<item>& items,
                 std::array<std::vector<std::uint32_t>, block_slots>& open, subtree where) const {
        if (where.count == 0) return link::to_node(collapse(binary, items, open, where.index));
        if (where.count == 1) return link::to_child(items[where.index].object);
        const std::uint64_t first = place_leaf(open, where.count);
        for (std::uint32_t k = 0; k < where.count; ++k) set_slot(first + k, &items[where.index + k]);
        return link::to_slots(first, where.count);
    }

    /// The first of `count` consecutive free slots for a leaf. A leaf of up to four takes
    /// the free slots of the block with the fewest that hold it (the newest such, near
    /// its neighbours in the tree), or a new block; a bigger one takes new blocks. `open`
    /// lists the blocks with free slots by how many, so that small leaves fill blocks up.
    std::uint64_t place_leaf(std::array<std::vector<std::uint32_t>, block_slots>& open, std::uint32_t count) const {
        for (std::uint32_t free = count; free < block_slots; ++free) {
            if (open[free].empty()) continue;
            const std::uint32_t b = open[free].back();
            open[free].pop_back();
            if (free > count) open[free - count].push_back(b);
            return std::uint64_t{b} * block_slots + (block_slots - free);
        }
        const auto first_block = static_cast<std::uint32_t>(blocks_.size());
        const std::uint32_t new_blocks = (count + block_slots - 1) / block_slots;
        blocks_.resize(blocks_.size() + new_blocks);  // every slot empty
        const std::uint32_t left = new_blocks * block_slots - count;  // free in the last block
        if (left > 0) open[left].push_back(first_block + new_blocks - 1);
        return std::uint64_t{first_block} * block_slots;
    }

    /// Slot s holds `it`: the child, and a ball in float that holds every point where a
    /// ray can hit it. That is the child's bounding_ball() where it gives one, else the
    /// ball around its box (its centre, and half its diagonal). The centre is rounded to
    /// the nearest float; the radius grows by how far that moved it, and is rounded up. A
    /// ball that float cannot hold (a coordinate beyond 3.4e38) becomes the ball of
    /// radius +infinity around the origin, which every ray's line meets: that child is
    /// always called.
    void set_slot(std::uint64_t s, const item* it) const {
        block& b = blocks_[s / block_slots];
        const int c = static_cast<int>(s % block_slots);
        b.child[c] = it->object;
        const rtab_component::ball own = it->object->bounding_ball();
        double centre[3], radius;
        if (own.radius >= 0 && std::isfinite(own.center.x) && std::isfinite(own.center.y) && std::isfinite(own.center.z)) {
            centre[0] = own.center.x, centre[1] = own.center.y, centre[2] = own.center.z;
            radius = own.radius;
        } else {
            double squared = 0;
            for (int k = 0; k < 3; ++k) {
                centre[k] = (it->bounds.lo[k] + it->bounds.hi[k]) / 2;
                const double half = std::max(it->bounds.hi[k] - centre[k], centre[k] - it->bounds.lo[k]);
                squared += half * half;
            }
            radius = std::sqrt(squared) * (1 + 0x1p-50);  // covers the rounding of the sum and root
        }
        float f[3];
        double moved = 0;
        for (int k = 0; k < 3; ++k) {
            f[k] = static_cast<float>(centre[k]);
            moved += (f[k] - centre[k]) * (f[k] - centre[k]);
        }
        const float r = round_up((radius + std::sqrt(moved)) * (1 + 0x1p-50));
        if (!(std::isfinite(f[0]) && std::isfinite(f[1]) && std::isfinite(f[2]) && std::isfinite(r))) {
            for (int k = 0; k < 3; ++k) b.ball[k][c] = 0;
            b.ball[3][c] = INFINITY;
            return;
        }
        for (int k = 0; k < 3; ++k) {
            b.ball[k][c] = f[k];
            ball_size_ = std::max(ball_size_, std::fabs(f[k]));
        }
        b.ball[3][c] = r;
    }

    /// Builds the subtree of items[begin, end), whose box is `bounds`; returns where it is.
    subtree build_subtree(std::vector<binary_node>& binary, std::vector<item>& items, std::size_t begin,
                          std::size_t end, int depth, const box3& bounds) const {
        const std::size_t n = end - begin;
        const subtree leaf{static_cast<std::uint32_t>(begin), static_cast<std::uint32_t>(n)};
        if (n == 1) return leaf;
        box3 centres;
        for (std::size_t i = begin; i < end; ++i) centres.grow(items[i].centre);

        const split best = depth < max_sah_depth ? cheapest_split(items, begin, end, bounds, centres) : split{};
        if (n <= static_cast<std::size_t>(leaf_size_) && !(best.cost < leaf_cost(n))) return leaf;
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
        const auto index = static_cast<std::uint32_t>(binary.size());
        binary.emplace_back();
        const std::size_t from[2] = {begin, middle}, to[2] = {middle, end};
        for (int side = 0; side < 2; ++side) {
            box3 box;
            for (std::size_t i = from[side]; i < to[side]; ++i) box.grow(items[i].bounds);
            binary[index].bounds[side] = box;
            const subtree child = build_subtree(binary, items, from[side], to[side], depth + 1, box);
            binary[index].child[side] = child;  // after the call, which may move binary
        }
        return {index, 0};
    }

    /// What a leaf of n children costs a ray that enters its box: a test of each of its
    /// blocks (Embree's builders count a leaf by its blocks, too).
    static double leaf_cost(std::size_t n) {
        return block_cost * static_cast<double>((n + block_slots - 1) / block_slots);
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
    /// cheapest, over the three axes: traversal_cost + (A_left C_left + A_right C_right) / A,
    /// where C is what a side's children cost as a leaf (leaf_cost()).
    static split cheapest_split(const std::vector<item>& items, std::size_t begin, std::size_t end,
                                const box3& bounds, const box3& centres) {
        const double area = bounds.half_area();
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
            // right_cost[b]: A C of bins b and above.
            std::array<double, max_bins> right_cost{};
            box3 right;
            std::size_t right_items = 0;
            for (int b = bins - 1; b > 0; --b) {
                right.grow(bin_bounds[static_cast<std::size_t>(b)]);
                right_items += bin_items[static_cast<std::size_t>(b)];
                right_cost[static_cast<std::size_t>(b)] = right.half_area() * leaf_cost(right_items);
            }
            box3 left;
            std::size_t left_items = 0;
            for (int b = 1; b < bins; ++b) {  // the left side: bins below b
                left.grow(bin_bounds[static_cast<std::size_t>(b - 1)]);
                left_items += bin_items[static_cast<std::size_t>(b - 1)];
                if (left_items == 0 || left_items == end - begin) continue;  // one side empty: no split
                const double weighted = left.half_area() * leaf_cost(left_items) + right_cost[static_cast<std::size_t>(b)];
                const double cost = traversal_cost + (area > 0 ? weighted / area : leaf_cost(end - begin));
                if (cost < best.cost) best = {cost, axis, b};
            }
        }
        return best;
    }

    /// The slab test of a node's eight boxes against `sr` for t in [0, t_max], four lanes
    /// at a time: bit c set for each box the ray passes through, and `t_near[c]` where it
    /// enters it. Branch-free: the face met first comes from the direction's sign, and
    /// the IEEE rules do the rest. A zero direction component gives distances of
    /// +-infinity (inside the slab or never); the NaN of 0 * infinity, for an origin on a
    /// face of such a slab, compares false and so never replaces t0 or t1: that slab
    /// limits nothing. `t_max` is float_limit() of the best hit, so stretched already.
    static int slabs(const float4 (&bounds)[2][3][width / 4], const slab_ray& sr, float4 t_max, float (&t_near)[width]) {
        const float4(*const rows)[width / 4] = &bounds[0][0];  // low x, y, z, high x, y, z
        int enters = 0;
        for (int q = 0; q < width / 4; ++q) {
            float4 t0 = {0, 0, 0, 0}, t1 = {INFINITY, INFINITY, INFINITY, INFINITY};
            for (int k = 0; k < 3; ++k) {
                const float4 near = (rows[sr.near_row[k]][q] - sr.origin_near[k]) * sr.inverse[k];
                const float4 far = (rows[sr.far_row[k]][q] - sr.origin_far[k]) * sr.inverse[k];
                t0 = near > t0 ? near : t0;
                t1 = far < t1 ? far : t1;
            }
            t1 *= far_stretch;
            std::memcpy(&t_near[4 * q], &t0, sizeof t0);
            enters |= lane_bits((t0 <= t1) & (t0 <= t_max)) << 4 * q;
        }
        return enters;
    }

    /// The children of block `b` whose ball the ray's line meets no farther than t_max,
    /// as bits: the distance from each centre to the line, squared, against the radius
    /// grown by `slack`, and the distance along the ray to the point nearest the centre,
    /// less that radius, against t_max (a hit lies no nearer). In float, from the
    /// nearest floats to the origin and the direction; `slack` covers what that and the
    /// arithmetic may be off by (see find_intersection()). A NaN (a ray without a
    /// direction) compares false: no child is called, as none could be hit.
    static int balls(const block& b, const slab_ray& sr, float4 slack, float4 t_max) {
        const float4 fx = b.ball[0] - sr.origin[0], fy = b.ball[1] - sr.origin[1], fz = b.ball[2] - sr.origin[2];
        const float4 along = fx * sr.direction[0] + fy * sr.direction[1] + fz * sr.direction[2];
        const float4 lx = fx - along * sr.direction[0], ly = fy - along * sr.direction[1], lz = fz - along * sr.direction[2];
        const float4 reach = b.ball[3] * far_stretch + slack;  // -infinity for an empty slot
        return lane_bits((lx * lx + ly * ly + lz * lz <= reach * reach) & (along - reach <= t_max) & (reach >= 0));
    }

    /// Starts loading the first 64 bytes of `child` (two cache lines where they straddle
    /// one's end), where a child keeps its vtable pointer and usually its shape, so that
    /// they are on their way while the walk goes on.
    /// The same serves a leaf's first block (96 bytes, at most two lines).
    static void prefetch(const void* at, std::size_t size = 64) {
        const char* const bytes = static_cast<const char*>(at);
        __builtin_prefetch(bytes);
        __builtin_prefetch(bytes + size - 1);
    }

    /// Bit c set where lane c of `enters` is true (-1): on x86 one instruction, movmskps,
    /// which gathers the four sign bits.
    static int lane_bits(const mask4& enters) {
#if defined(__SSE__)
        return __builtin_ia32_movmskps(reinterpret_cast<float4>(enters));
#else
        return (enters[0] & 1) | (enters[1] & 2) | (enters[2] & 4) | (enters[3] & 8);
#endif
    }

    intersection find_intersection(const ray& r) const override {
        ensure_built();
        if (children_.empty()) return intersection::none();
        const slab_ray sr(r);
        float root_near[width];
        const int enters_root = slabs(root_box_, sr, float4{} + INFINITY, root_near);
        count_bounding_volume_tests(1);
        if (!(enters_root & 1)) return intersection::none();
        // What a ball test's float arithmetic may be off by, as a distance: rounding the
        // origin and the direction to float, and each step after, is off by at most a few
        // float steps (2^-24) of the largest coordinate involved, the origin's or a
        // centre's; 64 of them leave a wide margin, and the smallest normal float one
        // where every coordinate is 0.
        const float4 slack = float4{} + (64 * 0x1p-24f * (sr.origin_size + ball_size_) + 0x1p-126f);
        struct entry {
            link to;
            float t_near;
        };
        // Near-first leaves at most seven entries per level waiting.
        std::array<entry, (width - 1) * max_tree_depth> stack;
        std::size_t top = 0;
        std::uint64_t tests = 0;  // box and ball tests
        intersection best = intersection::none();
        float4 t_max = float4{} + INFINITY;  // float_limit(best.t) once there is a best hit
        link at = root_link_;                // the subtree walked now
        while (true) {
            if (at.is_child()) {  // a leaf of one child
                const intersection i = at.child()->intersect(r);
                if (i.nearer_than(best)) best = i;
                if (best.hit()) t_max = float4{} + float_limit(best.t);
            } else if (!at.is_node()) {  // a leaf's slots: test their balls, block by block
                const std::uint64_t end = at.first_slot() + at.slot_count();
                for (std::uint64_t s = at.first_slot(); s < end; s = (s / block_slots + 1) * block_slots) {
                    const block& b = blocks_[s / block_slots];
                    const auto from = static_cast<unsigned>(s % block_slots);
                    const auto to = static_cast<unsigned>(std::min<std::uint64_t>(block_slots, from + (end - s)));
                    const int mine = static_cast<int>((1u << to) - (1u << from));  // this leaf's slots
                    tests += static_cast<std::uint64_t>(std::popcount(static_cast<unsigned>(mine)));
                    for (int meets = balls(b, sr, slack, t_max) & mine; meets != 0; meets &= meets - 1) {
                        const intersection i = b.child[std::countr_zero(static_cast<unsigned>(meets))]->intersect(r);
                        if (i.nearer_than(best)) best = i;
                    }
                    if (best.hit()) t_max = float4{} + float_limit(best.t);
                }
            } else {
                const node& nd = nodes_[at.node_index()];
                float t_near[width];
                const int enters = slabs(nd.bounds, sr, t_max, t_near);
                tests += static_cast<std::uint64_t>(nd.lanes());
                if (enters != 0) {
                    // Walk the nearest entered subtree next. The others wait on the stack,
                    // farthest at the bottom (an insertion sort of at most seven), so that
                    // the nearest of them comes off first. A child or a leaf's block
                    // entered is fetched from memory now, while the others are sorted and
                    // walked.
                    const std::size_t first = top;
                    entry nearest{link::none(), INFINITY};  // none yet: the first lane entered replaces it
                    for (int bits = enters; bits != 0; bits &= bits - 1) {
                        const int c = std::countr_zero(static_cast<unsigned>(bits));
                        entry other{nd.child[c], t_near[c]};
                        if (other.to.is_child()) prefetch(other.to.child());
                        else if (!other.to.is_node()) prefetch(&blocks_[other.to.first_slot() / block_slots], sizeof(block));
                        if (other.t_near <= nearest.t_near) std::swap(other, nearest);
                        if (other.to.is_none()) continue;  // that was the first lane entered
                        std::size_t slot = top++;
                        for (; slot > first && stack[slot - 1].t_near < other.t_near; --slot) stack[slot] = stack[slot - 1];
                        stack[slot] = other;
                    }
                    at = nearest.to;
                    continue;
                }
            }
            // Nothing below to walk: take the nearest waiting subtree whose box starts
            // before the best hit; those beyond it are dropped.
            while (top > 0 && stack[top - 1].t_near > t_max[0]) --top;
            if (top == 0) break;
            at = stack[--top].to;
        }
        count_bounding_volume_tests(tests);
        return best.hit() ? best : intersection::composite_only(this);
    }

    mutable box3 root_;                                   // the children's box, exactly
    mutable float4 root_box_[2][3][width / 4];            // root_ rounded outwards in lane 0, as a node's boxes
    mutable link root_link_ = link::none();              // the root: nodes_[0], or one leaf
    mutable std::vector<node> nodes_;                    // the inner nodes, parent first (built by ensure_built)
    mutable std::vector<block> blocks_;                  // the leaves' slots, four to a block
    mutable float ball_size_ = 0;                        // the largest |coordinate| of a ball's centre
};

}  // namespace

std::unique_ptr<rtab_composite> make_bvh(int leaf_size) {
    return shapes::bvh_base::make<bvh>(leaf_size);
}

}  // namespace vl::stage03
