// BVH: binned surface area heuristic (16 bins per axis), nodes in one flat array with
// the two children of a node side by side, walked with an explicit stack.
#include <algorithm>
#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <ostream>
#include <vector>

#include "geom3.hh"
#include "stage_03.hh"
#include "vl/bounds.hh"
#include "vl/scene_reader.hh"

namespace vl::stage03 {

namespace {

constexpr int bins = 16;
constexpr int max_depth = 64;  // below this, halve by count (the tree stays shallow)

struct aabb {
    geom3::triple lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
    void merge(const aabb& o) {
        for (int k = 0; k < 3; ++k) {
            lo[k] = std::min(lo[k], o.lo[k]);
            hi[k] = std::max(hi[k], o.hi[k]);
        }
    }
    void merge(const geom3::triple& p) {
        for (int k = 0; k < 3; ++k) {
            lo[k] = std::min(lo[k], p[k]);
            hi[k] = std::max(hi[k], p[k]);
        }
    }
    bool empty() const { return !(lo[0] <= hi[0]); }
    double area() const {
        if (empty()) return 0;
        const double a = hi[0] - lo[0], b = hi[1] - lo[1], c = hi[2] - lo[2];
        return 2 * (a * b + b * c + c * a);
    }
};

/// A node: an inner node's children are nodes[offset] and nodes[offset + 1]; a leaf's
/// objects are objects[offset, offset + count).
struct flat_node {
    aabb box;
    std::uint32_t offset = 0;
    std::uint32_t count = 0;  // 0: inner node
};

struct tree {
    std::vector<flat_node> nodes;
    std::vector<const rtab_component*> objects;
};

struct prim {
    aabb box;
    geom3::triple centre;
    const rtab_component* object;
};

class builder {
public:
    builder(std::vector<prim>& prims, int leaf_size, tree& out) : prims_(prims), leaf_size_(leaf_size), out_(out) {}

    void run() {
        out_.nodes.reserve(2 * prims_.size());
        out_.nodes.emplace_back();
        make(0, 0, prims_.size(), 0);
        for (const prim& p : prims_) out_.objects.push_back(p.object);
    }

private:
    void make(std::size_t at, std::size_t begin, std::size_t end, int depth) {
        aabb box, centres;
        for (std::size_t i = begin; i < end; ++i) {
            box.merge(prims_[i].box);
            centres.merge(prims_[i].centre);
        }
        out_.nodes[at].box = box;
        const std::size_t n = end - begin;
        auto leaf = [&] {
            out_.nodes[at].offset = static_cast<std::uint32_t>(begin);
            out_.nodes[at].count = static_cast<std::uint32_t>(n);
        };
        if (n == 1) return leaf();

        // Bin the centres along each axis; the cheapest boundary between bins wins.
        double best = INFINITY;
        int best_axis = -1, best_bin = 0;
        for (int axis = 0; axis < 3 && depth < max_depth; ++axis) {
            const double lo = centres.lo[axis], extent = centres.hi[axis] - lo;
            if (!(extent > 0)) continue;
            aabb bin_box[bins];
            std::size_t bin_count[bins] = {};
            for (std::size_t i = begin; i < end; ++i) {
                const int b = bin_of(prims_[i].centre[axis], lo, extent);
                bin_box[b].merge(prims_[i].box);
                ++bin_count[b];
            }
            double right_area[bins];
            std::size_t right_count[bins];
            aabb right;
            std::size_t count = 0;
            for (int b = bins - 1; b > 0; --b) {
                right.merge(bin_box[b]);
                count += bin_count[b];
                right_area[b] = right.area();
                right_count[b] = count;
            }
            aabb left;
            std::size_t left_count = 0;
            for (int b = 1; b < bins; ++b) {  // left: bins [0, b)
                left.merge(bin_box[b - 1]);
                left_count += bin_count[b - 1];
                if (left_count == 0 || right_count[b] == 0) continue;
                const double cost = left.area() * static_cast<double>(left_count) +
                                    right_area[b] * static_cast<double>(right_count[b]);
                if (cost < best) {
                    best = cost;
                    best_axis = axis;
                    best_bin = b;
                }
            }
        }
        const double area = box.area();
        // Leaf cost n, split cost 1 (the two box tests) + the children's expected tests.
        const bool split_pays = best_axis >= 0 && (area > 0 ? 1 + best / area : 1.0) < static_cast<double>(n);
        if (n <= static_cast<std::size_t>(leaf_size_) && !split_pays) return leaf();

        std::size_t mid;
        if (best_axis >= 0) {
            const double lo = centres.lo[best_axis], extent = centres.hi[best_axis] - lo;
            const auto first_right = std::partition(
                prims_.begin() + static_cast<std::ptrdiff_t>(begin), prims_.begin() + static_cast<std::ptrdiff_t>(end),
                [&](const prim& p) { return bin_of(p.centre[best_axis], lo, extent) < best_bin; });
            mid = static_cast<std::size_t>(first_right - prims_.begin());
        } else {
            // Every centre alike, or the tree too deep: halve by count.
            mid = begin + n / 2;
        }
        const auto children = static_cast<std::uint32_t>(out_.nodes.size());
        out_.nodes.emplace_back();
        out_.nodes.emplace_back();
        out_.nodes[at].offset = children;
        out_.nodes[at].count = 0;
        make(children, begin, mid, depth + 1);
        make(children + 1, mid, end, depth + 1);
    }

    static int bin_of(double c, double lo, double extent) {
        const int b = static_cast<int>((c - lo) / extent * bins);
        return std::clamp(b, 0, bins - 1);
    }

    std::vector<prim>& prims_;
    int leaf_size_;
    tree& out_;
};

class bvh final : public rtab_composite {
public:
    explicit bvh(int leaf_size) : leaf_size_(leaf_size) {}

    std::string type_name() const override { return "BVH"; }

    void insert(std::unique_ptr<rtab_component> child) override {
        if (child && child.get() != this && !geom3::bounded(*child))
            throw usage_error("BVH cannot hold a " + child->type_name() +
                              ": its box is not known; put the " + child->type_name() + " beside the BVH in a LIST");
        std::lock_guard lock(building_);
        rtab_composite::insert(std::move(child));
        current_.store(nullptr);
    }
    void delete_all_children() override {
        std::lock_guard lock(building_);
        rtab_composite::delete_all_children();
        current_.store(nullptr);
    }

    point min_point() const override {
        const auto t = get();
        return t->nodes.empty() ? NaN_point : geom3::as_point(t->nodes[0].box.lo);
    }
    point max_point() const override {
        const auto t = get();
        return t->nodes.empty() ? NaN_point : geom3::as_point(t->nodes[0].box.hi);
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
        out << "BVH {\n  leaf_size " << leaf_size_ << "\n";
        for (const auto& c : children_) out << "  " << *c << "\n";
        out << "}";
    }

private:
    std::shared_ptr<const tree> get() const {
        if (auto t = current_.load()) return t;
        std::lock_guard lock(building_);
        if (auto t = current_.load()) return t;
        auto made = std::make_shared<tree>();
        std::vector<prim> prims;
        prims.reserve(children_.size());
        for (const auto& c : children_) {
            prim p{{geom3::xyz(c->min_point()), geom3::xyz(c->max_point())}, {}, c.get()};
            for (int k = 0; k < 3; ++k) p.centre[k] = (p.box.lo[k] + p.box.hi[k]) / 2;
            prims.push_back(p);
        }
        if (!prims.empty()) builder(prims, leaf_size_, *made).run();
        std::shared_ptr<const tree> done = std::move(made);
        current_.store(done);
        return done;
    }

    intersection find_intersection(const ray& r) const override {
        const auto t = get();
        const std::vector<flat_node>& nodes = t->nodes;
        if (nodes.empty()) return intersection::none();
        ray_span root;
        if (!hits_box(r, geom3::as_point(nodes[0].box.lo), geom3::as_point(nodes[0].box.hi), 1e300, &root))
            return intersection::none();
        struct pending {
            std::uint32_t node;
            double enter;
        };
        std::vector<pending> stack;
        stack.reserve(64);
        stack.push_back({0, root.t_near});
        intersection best = intersection::none();
        while (!stack.empty()) {
            const pending p = stack.back();
            stack.pop_back();
            if (best.hit() && p.enter > best.t) continue;
            const flat_node& nd = nodes[p.node];
            if (nd.count > 0) {
                for (std::uint32_t i = nd.offset; i < nd.offset + nd.count; ++i) {
                    const intersection h = t->objects[i]->intersect(r);
                    if (h.nearer_than(best)) best = h;
                }
                continue;
            }
            const double limit = best.hit() ? best.t : 1e300;
            const flat_node& a = nodes[nd.offset];
            const flat_node& b = nodes[nd.offset + 1];
            ray_span sa, sb;
            const bool ha = hits_box(r, geom3::as_point(a.box.lo), geom3::as_point(a.box.hi), limit, &sa);
            const bool hb = hits_box(r, geom3::as_point(b.box.lo), geom3::as_point(b.box.hi), limit, &sb);
            // The nearer child goes on top of the stack, so it is walked first.
            if (ha && hb) {
                if (sa.t_near <= sb.t_near) {
                    stack.push_back({nd.offset + 1, sb.t_near});
                    stack.push_back({nd.offset, sa.t_near});
                } else {
                    stack.push_back({nd.offset, sa.t_near});
                    stack.push_back({nd.offset + 1, sb.t_near});
                }
            } else if (ha) {
                stack.push_back({nd.offset, sa.t_near});
            } else if (hb) {
                stack.push_back({nd.offset + 1, sb.t_near});
            }
        }
        return best.hit() ? best : intersection::composite_only(this);
    }

    int leaf_size_;
    mutable std::mutex building_;
    mutable std::atomic<std::shared_ptr<const tree>> current_;
};

}  // namespace

std::unique_ptr<rtab_composite> make_bvh(int leaf_size) {
    if (leaf_size < 1 || leaf_size > 64)
        throw usage_error("make_bvh: leaf_size must be a whole number from 1 to 64, not " + std::to_string(leaf_size));
    return std::make_unique<bvh>(leaf_size);
}

}  // namespace vl::stage03
