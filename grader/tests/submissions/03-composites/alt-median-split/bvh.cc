// The bounding volume hierarchy: split at the median of the longest axis, walked
// recursively, nearer child first.
#include <algorithm>
#include <atomic>
#include <mutex>
#include <numeric>
#include <ostream>
#include <vector>

#include "extent.hh"
#include "stage_03.hh"
#include "vl/bounds.hh"
#include "vl/scene_reader.hh"

namespace vl::stage03 {

namespace {

constexpr double far_away = 1e300;

class hierarchy final : public rtab_composite {
public:
    explicit hierarchy(int leaf_size) : leaf_size_(leaf_size) {}

    std::string type_name() const override { return "BVH"; }

    void insert(std::unique_ptr<rtab_component> child) override {
        if (!child) throw usage_error("BVH: insert() was given a null pointer instead of an object");
        if (child.get() == this) throw usage_error("BVH: a BVH cannot hold itself");
        if (!box_is_known(*child))
            throw usage_error("BVH refuses a " + child->type_name() +
                              ": its box is unknown, so no box of the tree can hold it; put the " +
                              child->type_name() + " next to the BVH in a LIST instead");
        std::lock_guard guard(mutex_);
        children_.push_back(std::move(child));
        ready_.store(false);
    }
    void delete_all_children() override {
        std::lock_guard guard(mutex_);
        children_.clear();
        ready_.store(false);
    }

    point min_point() const override {
        prepare();
        return nodes_.empty() ? NaN_point : nodes_[0].box.lo;
    }
    point max_point() const override {
        prepare();
        return nodes_.empty() ? NaN_point : nodes_[0].box.hi;
    }

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
        for (const auto& c : children_) out << ' ' << *c;
        out << " }";
    }

private:
    struct node {
        extent box;
        int left = -1, right = -1;  // inner node: the two subtrees; leaf: -1
        int begin = 0, end = 0;     // leaf: its children are leaves_[begin, end)
    };

    void prepare() const {
        if (ready_.load()) return;
        std::lock_guard guard(mutex_);
        if (ready_.load()) return;
        construct();
        ready_.store(true);
    }

    void construct() const {
        nodes_.clear();
        leaves_.clear();
        boxes_.clear();
        centres_.clear();
        if (children_.empty()) return;
        for (const auto& c : children_) {
            extent e;
            e.add(c->min_point(), c->max_point());
            boxes_.push_back(e);
            centres_.push_back(e.middle());
        }
        std::vector<int> index(children_.size());
        std::iota(index.begin(), index.end(), 0);
        split(index, 0, static_cast<int>(index.size()));
        for (int i : index) leaves_.push_back(children_[static_cast<std::size_t>(i)].get());
    }

    /// Makes the subtree over index[begin, end) and returns where its root is in nodes_.
    int split(std::vector<int>& index, int begin, int end) const {
        const int at = static_cast<int>(nodes_.size());
        nodes_.emplace_back();
        extent box, middles;
        for (int k = begin; k < end; ++k) {
            box.add(boxes_[static_cast<std::size_t>(index[static_cast<std::size_t>(k)])]);
            middles.add(centres_[static_cast<std::size_t>(index[static_cast<std::size_t>(k)])]);
        }
        nodes_[static_cast<std::size_t>(at)].box = box;
        if (end - begin <= leaf_size_) {
            nodes_[static_cast<std::size_t>(at)].begin = begin;
            nodes_[static_cast<std::size_t>(at)].end = end;
            return at;
        }
        // Half the children on each side of the median centre along the longest axis of the
        // centres (with all centres alike this still halves them: it splits by count).
        const int axis = middles.longest_axis();
        const int mid = begin + (end - begin) / 2;
        std::nth_element(index.begin() + begin, index.begin() + mid, index.begin() + end, [&](int a, int b) {
            return extent::along(centres_[static_cast<std::size_t>(a)], axis) <
                   extent::along(centres_[static_cast<std::size_t>(b)], axis);
        });
        const int left = split(index, begin, mid);
        const int right = split(index, mid, end);
        nodes_[static_cast<std::size_t>(at)].left = left;
        nodes_[static_cast<std::size_t>(at)].right = right;
        return at;
    }

    void visit(int k, const ray& r, intersection& best) const {
        const node& nd = nodes_[static_cast<std::size_t>(k)];
        if (nd.left < 0) {
            for (int i = nd.begin; i < nd.end; ++i) {
                const intersection hit = leaves_[static_cast<std::size_t>(i)]->intersect(r);
                if (hit.nearer_than(best)) best = hit;
            }
            return;
        }
        const double limit = best.hit() ? best.t : far_away;
        const node& a = nodes_[static_cast<std::size_t>(nd.left)];
        const node& b = nodes_[static_cast<std::size_t>(nd.right)];
        ray_span in_a, in_b;
        const bool enters_a = hits_box(r, a.box.lo, a.box.hi, limit, &in_a);
        const bool enters_b = hits_box(r, b.box.lo, b.box.hi, limit, &in_b);
        if (enters_a && enters_b) {
            const bool a_first = in_a.t_near <= in_b.t_near;
            visit(a_first ? nd.left : nd.right, r, best);
            const double later = a_first ? in_b.t_near : in_a.t_near;
            if (!best.hit() || later <= best.t) visit(a_first ? nd.right : nd.left, r, best);
        } else if (enters_a) {
            visit(nd.left, r, best);
        } else if (enters_b) {
            visit(nd.right, r, best);
        }
    }

    intersection find_intersection(const ray& r) const override {
        prepare();
        if (nodes_.empty()) return intersection::none();
        if (!hits_box(r, nodes_[0].box.lo, nodes_[0].box.hi)) return intersection::none();
        intersection best = intersection::none();
        visit(0, r, best);
        return best.hit() ? best : intersection::composite_only(this);
    }

    int leaf_size_;
    mutable std::mutex mutex_;
    mutable std::atomic<bool> ready_{false};
    mutable std::vector<node> nodes_;
    mutable std::vector<const rtab_component*> leaves_;
    mutable std::vector<extent> boxes_;
    mutable std::vector<point> centres_;
};

}  // namespace

std::unique_ptr<rtab_composite> make_bvh(int leaf_size) {
    if (!(leaf_size >= 1 && leaf_size <= 64))
        throw usage_error("make_bvh: leaf_size must be a whole number from 1 to 64, not " + std::to_string(leaf_size));
    return std::make_unique<hierarchy>(leaf_size);
}

}  // namespace vl::stage03
