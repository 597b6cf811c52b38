// BVH: a tree of heap nodes, each inner node split at the middle of the longest side of
// its children's centres (by count when that leaves one side empty), walked near-first.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <memory>
#include <mutex>
#include <ostream>
#include <vector>

#include "sphere_bound.hh"
#include "stage_03.hh"
#include "vl/bounds.hh"
#include "vl/scene_reader.hh"

namespace vl::stage03 {

namespace {

struct span3 {
    point lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
    void cover(const point& a, const point& b) {
        lo = point(std::min(lo.x, a.x), std::min(lo.y, a.y), std::min(lo.z, a.z));
        hi = point(std::max(hi.x, b.x), std::max(hi.y, b.y), std::max(hi.z, b.z));
    }
};

double pick(const point& p, int axis) { return axis == 0 ? p.x : axis == 1 ? p.y : p.z; }

struct item {
    point lo, hi, mid;
    const rtab_component* object;
};

struct tree_node {
    span3 box;
    std::unique_ptr<tree_node> near_side, far_side;  // inner node: the lower and the upper half
    std::vector<const rtab_component*> objects;      // leaf
};

std::unique_ptr<tree_node> build(std::vector<item>& items, std::size_t begin, std::size_t end, int leaf_size, int depth) {
    auto n = std::make_unique<tree_node>();
    span3 centres;
    for (std::size_t i = begin; i < end; ++i) {
        n->box.cover(items[i].lo, items[i].hi);
        centres.cover(items[i].mid, items[i].mid);
    }
    const std::size_t count = end - begin;
    if (count <= static_cast<std::size_t>(leaf_size)) {
        for (std::size_t i = begin; i < end; ++i) n->objects.push_back(items[i].object);
        return n;
    }
    const vector size = centres.hi - centres.lo;
    const int axis = size.x >= size.y && size.x >= size.z ? 0 : size.y >= size.z ? 1 : 2;
    const double middle = (pick(centres.lo, axis) + pick(centres.hi, axis)) / 2;
    auto first = items.begin() + static_cast<std::ptrdiff_t>(begin), last = items.begin() + static_cast<std::ptrdiff_t>(end);
    std::size_t cut = static_cast<std::size_t>(
        std::partition(first, last, [&](const item& it) { return pick(it.mid, axis) < middle; }) - items.begin());
    if (cut == begin || cut == end || depth > 60) {
        // All centres on one side of the middle (or alike): halve by count along the axis.
        cut = begin + count / 2;
        std::nth_element(first, items.begin() + static_cast<std::ptrdiff_t>(cut), last,
                         [&](const item& a, const item& b) { return pick(a.mid, axis) < pick(b.mid, axis); });
    }
    n->near_side = build(items, begin, cut, leaf_size, depth + 1);
    n->far_side = build(items, cut, end, leaf_size, depth + 1);
    return n;
}

class bvh final : public rtab_composite {
public:
    explicit bvh(int leaf_size) : leaf_size_(leaf_size) {}

    std::string type_name() const override { return "BVH"; }

    void insert(std::unique_ptr<rtab_component> child) override {
        if (child && child.get() != this && !box_known(*child))
            throw usage_error("BVH cannot take " + child->type_name() + ": " + child->type_name() +
                              " has no finite box for the tree to hold (unbounded or empty); place it beside the BVH "
                              "in a LIST");
        std::lock_guard lock(lock_);
        rtab_composite::insert(std::move(child));
        valid_.store(false, std::memory_order_release);
    }
    void delete_all_children() override {
        std::lock_guard lock(lock_);
        rtab_composite::delete_all_children();
        valid_.store(false, std::memory_order_release);
    }

    point min_point() const override { return root() ? root()->box.lo : NaN_point; }
    point max_point() const override { return root() ? root()->box.hi : NaN_point; }

    void read(scene_reader& in) override {
        in.expect('{', "after BVH");
        if (in.peek().type == token::kind::word && in.peek().text == "leaf_size") {
            in.next();
            leaf_size_ = in.read_int("leaf_size of BVH", 1, 64);
        }
        while (!in.accept('}')) in.read_child(*this);
    }
    void write(std::ostream& out) const override {
        out << "BVH { leaf_size " << leaf_size_;
        for (const auto& c : children_) out << "\n  " << *c;
        out << "\n}";
    }

private:
    const tree_node* root() const {
        if (!valid_.load(std::memory_order_acquire)) {
            std::lock_guard lock(lock_);
            if (!valid_.load(std::memory_order_relaxed)) {
                tree_.reset();
                if (!children_.empty()) {
                    std::vector<item> items;
                    for (const auto& c : children_) {
                        const point a = c->min_point(), b = c->max_point();
                        items.push_back({a, b, point((a.x + b.x) / 2, (a.y + b.y) / 2, (a.z + b.z) / 2), c.get()});
                    }
                    tree_ = build(items, 0, items.size(), leaf_size_, 0);
                }
                valid_.store(true, std::memory_order_release);
            }
        }
        return tree_.get();
    }

    intersection find_intersection(const ray& r) const override {
        const tree_node* top = root();
        if (!top) return intersection::none();
        ray_span s;
        if (!hits_box(r, top->box.lo, top->box.hi, 1e300, &s)) return intersection::none();
        struct waiting {
            const tree_node* node;
            double from;
        };
        std::vector<waiting> later;
        const tree_node* current = top;
        double current_from = s.t_near;
        intersection best = intersection::none();
        for (;;) {
            if (current && !(best.hit() && current_from > best.t)) {
                if (current->near_side) {
                    const double limit = best.hit() ? best.t : 1e300;
                    ray_span a, b;
                    const bool in_a = hits_box(r, current->near_side->box.lo, current->near_side->box.hi, limit, &a);
                    const bool in_b = hits_box(r, current->far_side->box.lo, current->far_side->box.hi, limit, &b);
                    if (in_a && in_b) {
                        // Go on with the nearer; the other waits.
                        const bool a_first = a.t_near <= b.t_near;
                        later.push_back(a_first ? waiting{current->far_side.get(), b.t_near}
                                                : waiting{current->near_side.get(), a.t_near});
                        current_from = a_first ? a.t_near : b.t_near;
                        current = a_first ? current->near_side.get() : current->far_side.get();
                    } else if (in_a || in_b) {
                        current_from = in_a ? a.t_near : b.t_near;
                        current = in_a ? current->near_side.get() : current->far_side.get();
                    } else {
                        current = nullptr;
                    }
                    continue;
                }
                for (const rtab_component* o : current->objects) {
                    const intersection i = o->intersect(r);
                    if (i.nearer_than(best)) best = i;
                }
            }
            if (later.empty()) break;
            current = later.back().node;
            current_from = later.back().from;
            later.pop_back();
        }
        return best.hit() ? best : intersection::composite_only(this);
    }

    int leaf_size_;
    mutable std::mutex lock_;
    mutable std::atomic<bool> valid_{false};
    mutable std::unique_ptr<tree_node> tree_;
};

}  // namespace

std::unique_ptr<rtab_composite> make_bvh(int leaf_size) {
    if (leaf_size < 1 || leaf_size > 64)
        throw usage_error("make_bvh: leaf_size " + std::to_string(leaf_size) + " is not a whole number from 1 to 64");
    return std::make_unique<bvh>(leaf_size);
}

}  // namespace vl::stage03
