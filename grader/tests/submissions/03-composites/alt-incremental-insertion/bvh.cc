// BVH, built by incremental insertion (Goldsmith and Salmon 1987): at the first ray the
// children go into a tree of boxes one by one, in a shuffled order, each beside the node
// where it adds the least surface area to the tree (found by branch and bound). Then small
// subtrees become leaves where the surface area heuristic says a leaf is cheaper.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <mutex>
#include <ostream>
#include <queue>
#include <vector>

#include "sphere_group.hh"
#include "stage_03.hh"
#include "vl/bounds.hh"
#include "vl/scene_reader.hh"

namespace vl::stage03 {

namespace {

struct box3 {
    double lo[3] = {INFINITY, INFINITY, INFINITY};
    double hi[3] = {-INFINITY, -INFINITY, -INFINITY};

    static box3 of(const rtab_component& c) {
        const point a = c.min_point(), b = c.max_point();
        box3 r;
        r.lo[0] = a.x, r.lo[1] = a.y, r.lo[2] = a.z;
        r.hi[0] = b.x, r.hi[1] = b.y, r.hi[2] = b.z;
        return r;
    }
    box3 joined(const box3& o) const {
        box3 r;
        for (int k = 0; k < 3; ++k) {
            r.lo[k] = std::min(lo[k], o.lo[k]);
            r.hi[k] = std::max(hi[k], o.hi[k]);
        }
        return r;
    }
    double area() const {
        const double x = hi[0] - lo[0], y = hi[1] - lo[1], z = hi[2] - lo[2];
        return x * y + y * z + z * x;
    }
    point low() const { return point(lo[0], lo[1], lo[2]); }
    point high() const { return point(hi[0], hi[1], hi[2]); }
};

/// A node of the insertion tree: a leaf holds one child (object >= 0), an inner node two nodes.
struct tree_node {
    box3 box;
    int parent = -1;
    int kid[2] = {-1, -1};
    int object = -1;
};

/// A node of the tree that rays walk: an inner node's children are `a` and `b`; a leaf's
/// objects are order[first, first + count).
struct walk_node {
    box3 box;
    int a = -1, b = -1;
    int first = 0, count = 0;
};

class incremental_builder {
public:
    incremental_builder(const std::vector<box3>& boxes, int leaf_size) : boxes_(boxes), leaf_size_(leaf_size) {}

    void build(std::vector<walk_node>& out, std::vector<int>& order) {
        // A fixed shuffle (the same tree every time): insertion in a random order gives
        // good trees whatever order the scene lists its objects in.
        std::vector<int> sequence(boxes_.size());
        for (std::size_t i = 0; i < sequence.size(); ++i) sequence[i] = static_cast<int>(i);
        std::uint64_t state = 0x9E3779B97F4A7C15ull;
        for (std::size_t i = sequence.size(); i > 1; --i) {
            state = state * 6364136223846793005ull + 1442695040888963407ull;
            const std::size_t j = static_cast<std::size_t>((state >> 33) % i);
            std::swap(sequence[i - 1], sequence[j]);
        }
        nodes_.reserve(2 * boxes_.size());
        for (int object : sequence) add(object);
        sizes_.assign(nodes_.size(), 0);
        costs_.assign(nodes_.size(), 0);
        measure(root_);
        flatten(root_, out, order);
    }

private:
    int leaf(int object) {
        tree_node n;
        n.box = boxes_[static_cast<std::size_t>(object)];
        n.object = object;
        nodes_.push_back(n);
        return static_cast<int>(nodes_.size()) - 1;
    }

    void add(int object) {
        const int fresh = leaf(object);
        if (root_ < 0) {
            root_ = fresh;
            return;
        }
        const box3& b = nodes_[static_cast<std::size_t>(fresh)].box;
        // Branch and bound over the tree: the cost of making node s the new leaf's sibling
        // is the area of s joined with it plus what every ancestor of s grows by.
        struct candidate {
            double inherited;
            int node;
            bool operator<(const candidate& o) const { return inherited > o.inherited; }  // smallest first
        };
        std::priority_queue<candidate> open;
        open.push({0, root_});
        int best = root_;
        double best_cost = INFINITY;
        const double own = b.area();
        while (!open.empty()) {
            const candidate c = open.top();
            open.pop();
            if (c.inherited + own >= best_cost) break;  // nothing left can be cheaper
            const tree_node& n = nodes_[static_cast<std::size_t>(c.node)];
            const double joined = n.box.joined(b).area();
            const double cost = c.inherited + joined;
            if (cost < best_cost) {
                best_cost = cost;
                best = c.node;
            }
            if (n.object < 0) {
                const double inherited = c.inherited + joined - n.box.area();
                if (inherited + own < best_cost) {
                    open.push({inherited, n.kid[0]});
                    open.push({inherited, n.kid[1]});
                }
            }
        }
        // A new inner node takes best's place, with best and the new leaf as its children.
        tree_node inner;
        inner.parent = nodes_[static_cast<std::size_t>(best)].parent;
        inner.kid[0] = best;
        inner.kid[1] = fresh;
        inner.box = nodes_[static_cast<std::size_t>(best)].box.joined(b);
        nodes_.push_back(inner);
        const int joint = static_cast<int>(nodes_.size()) - 1;
        if (inner.parent < 0) {
            root_ = joint;
        } else {
            tree_node& p = nodes_[static_cast<std::size_t>(inner.parent)];
            p.kid[p.kid[0] == best ? 0 : 1] = joint;
        }
        nodes_[static_cast<std::size_t>(best)].parent = joint;
        nodes_[static_cast<std::size_t>(fresh)].parent = joint;
        for (int up = inner.parent; up >= 0; up = nodes_[static_cast<std::size_t>(up)].parent) {
            tree_node& u = nodes_[static_cast<std::size_t>(up)];
            u.box = nodes_[static_cast<std::size_t>(u.kid[0])].box.joined(nodes_[static_cast<std::size_t>(u.kid[1])].box);
        }
    }

    /// Counts each subtree's objects and its expected cost per ray that enters it, in
    /// units of one object test (a node's two box tests cost 1).
    void measure(int root) {
        // Children before parents, without recursion (the tree may be deep).
        std::vector<int> post;
        std::vector<int> todo{root};
        while (!todo.empty()) {
            const int k = todo.back();
            todo.pop_back();
            post.push_back(k);
            const tree_node& n = nodes_[static_cast<std::size_t>(k)];
            if (n.object < 0) {
                todo.push_back(n.kid[0]);
                todo.push_back(n.kid[1]);
            }
        }
        for (auto it = post.rbegin(); it != post.rend(); ++it) {
            const std::size_t k = static_cast<std::size_t>(*it);
            const tree_node& n = nodes_[k];
            if (n.object >= 0) {
                sizes_[k] = 1;
                costs_[k] = 1;
                continue;
            }
            const auto a = static_cast<std::size_t>(n.kid[0]), b = static_cast<std::size_t>(n.kid[1]);
            sizes_[k] = sizes_[a] + sizes_[b];
            const double area = n.box.area();
            const double split = area > 0 ? 1 + (nodes_[a].box.area() * costs_[a] + nodes_[b].box.area() * costs_[b]) / area
                                          : 1 + costs_[a] + costs_[b];
            const auto count = static_cast<double>(sizes_[k]);
            costs_[k] = sizes_[k] <= static_cast<std::size_t>(leaf_size_) && count <= split ? count : split;
        }
    }

    bool collapsed(std::size_t k) const {
        return nodes_[k].object < 0 && sizes_[k] <= static_cast<std::size_t>(leaf_size_) &&
               costs_[k] == static_cast<double>(sizes_[k]);
    }

    void gather(int k, std::vector<int>& order) const {
        std::vector<int> todo{k};
        while (!todo.empty()) {
            const tree_node& n = nodes_[static_cast<std::size_t>(todo.back())];
            todo.pop_back();
            if (n.object >= 0) {
                order.push_back(n.object);
            } else {
                todo.push_back(n.kid[1]);
                todo.push_back(n.kid[0]);
            }
        }
    }

    void flatten(int root, std::vector<walk_node>& out, std::vector<int>& order) const {
        struct job {
            int tree;
            int slot;
        };
        out.clear();
        out.emplace_back();
        std::vector<job> todo{{root, 0}};
        while (!todo.empty()) {
            const job j = todo.back();
            todo.pop_back();
            const tree_node& n = nodes_[static_cast<std::size_t>(j.tree)];
            walk_node& w = out[static_cast<std::size_t>(j.slot)];
            w.box = n.box;
            if (n.object >= 0 || collapsed(static_cast<std::size_t>(j.tree))) {
                w.first = static_cast<int>(order.size());
                gather(j.tree, order);
                w.count = static_cast<int>(order.size()) - w.first;
                continue;
            }
            const int a = static_cast<int>(out.size());
            out.emplace_back();
            out.emplace_back();
            out[static_cast<std::size_t>(j.slot)].a = a;
            out[static_cast<std::size_t>(j.slot)].b = a + 1;
            todo.push_back({n.kid[0], a});
            todo.push_back({n.kid[1], a + 1});
        }
    }

    const std::vector<box3>& boxes_;
    int leaf_size_;
    std::vector<tree_node> nodes_;
    std::vector<std::size_t> sizes_;
    std::vector<double> costs_;
    int root_ = -1;
};

class bvh final : public rtab_composite {
public:
    explicit bvh(int leaf_size) : leaf_size_(leaf_size) {}

    std::string type_name() const override { return "BVH"; }

    void insert(std::unique_ptr<rtab_component> child) override {
        if (child && child.get() != this && !has_finite_box(*child))
            throw usage_error("BVH cannot hold " + child->type_name() + ", whose box is unknown (" + child->type_name() +
                              " is unbounded or empty): put it beside the BVH in a LIST");
        std::lock_guard lock(mutex_);
        rtab_composite::insert(std::move(child));
        stale_.store(true);
    }
    void delete_all_children() override {
        std::lock_guard lock(mutex_);
        rtab_composite::delete_all_children();
        stale_.store(true);
    }

    point min_point() const override {
        refresh();
        return walk_.empty() ? NaN_point : walk_[0].box.low();
    }
    point max_point() const override {
        refresh();
        return walk_.empty() ? NaN_point : walk_[0].box.high();
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
        out << "BVH { leaf_size " << leaf_size_ << '\n';
        for (const auto& c : children_) out << "  " << *c << '\n';
        out << '}';
    }

private:
    void refresh() const {
        if (!stale_.load(std::memory_order_acquire)) return;
        std::lock_guard lock(mutex_);
        if (!stale_.load(std::memory_order_relaxed)) return;
        walk_.clear();
        order_.clear();
        if (!children_.empty()) {
            std::vector<box3> boxes;
            boxes.reserve(children_.size());
            for (const auto& c : children_) boxes.push_back(box3::of(*c));
            std::vector<int> order;
            incremental_builder(boxes, leaf_size_).build(walk_, order);
            for (int k : order) order_.push_back(children_[static_cast<std::size_t>(k)].get());
        }
        stale_.store(false, std::memory_order_release);
    }

    intersection find_intersection(const ray& r) const override {
        refresh();
        if (walk_.empty()) return intersection::none();
        ray_span whole;
        if (!hits_box(r, walk_[0].box.low(), walk_[0].box.high(), 1e300, &whole)) return intersection::none();
        std::vector<std::pair<int, double>> stack{{0, whole.t_near}};
        intersection best = intersection::none();
        while (!stack.empty()) {
            const auto [k, enter] = stack.back();
            stack.pop_back();
            if (best.hit() && enter > best.t) continue;
            const walk_node& n = walk_[static_cast<std::size_t>(k)];
            if (n.a < 0) {
                for (int i = n.first; i < n.first + n.count; ++i)
                    if (const intersection h = order_[static_cast<std::size_t>(i)]->intersect(r); h.nearer_than(best))
                        best = h;
                continue;
            }
            const double limit = best.hit() ? best.t : 1e300;
            const walk_node& a = walk_[static_cast<std::size_t>(n.a)];
            const walk_node& b = walk_[static_cast<std::size_t>(n.b)];
            ray_span sa, sb;
            const bool in_a = hits_box(r, a.box.low(), a.box.high(), limit, &sa);
            const bool in_b = hits_box(r, b.box.low(), b.box.high(), limit, &sb);
            if (in_a && in_b) {
                const bool a_nearer = sa.t_near < sb.t_near;
                stack.emplace_back(a_nearer ? n.b : n.a, a_nearer ? sb.t_near : sa.t_near);
                stack.emplace_back(a_nearer ? n.a : n.b, a_nearer ? sa.t_near : sb.t_near);
            } else if (in_a) {
                stack.emplace_back(n.a, sa.t_near);
            } else if (in_b) {
                stack.emplace_back(n.b, sb.t_near);
            }
        }
        return best.hit() ? best : intersection::composite_only(this);
    }

    int leaf_size_;
    mutable std::mutex mutex_;
    mutable std::atomic<bool> stale_{true};
    mutable std::vector<walk_node> walk_;
    mutable std::vector<const rtab_component*> order_;
};

}  // namespace

std::unique_ptr<rtab_composite> make_bvh(int leaf_size) {
    if (leaf_size < 1 || leaf_size > 64)
        throw usage_error("make_bvh: leaf_size must be from 1 to 64, not " + std::to_string(leaf_size));
    return std::make_unique<bvh>(leaf_size);
}

}  // namespace vl::stage03
