// The box of six polygons (stage_03.hh). A ray tests the faces that face it first; the
// faces it would leave through only when none of those is hit (a ray from inside).
#include <cmath>
#include <vector>

#include "stage_02.hh"
#include "stage_03.hh"
#include "vl/bounds.hh"
#include "vl/composite_bases.hh"

namespace vl::stage03 {

namespace {

/// \brief An axis-aligned box made of its six faces, tested as a box first.
class box final : public shapes::box_base {
public:
    box(const point& lo, const point& hi) { set_geometry(lo, hi); }

    void insert(std::unique_ptr<rtab_component>) override {
        throw usage_error("BOX: insert() refused, a box consists of exactly its six faces; "
                          "put the BOX and the other object in a LIST");
    }
    void delete_all_children() override {
        throw usage_error("BOX: delete_all_children() refused, the six faces are the box");
    }

    bool contains(const point& p) const override {
        const point q = p.homogenized();
        const vector below_hi = hi_ - q, above_lo = q - lo_;
        return below_hi.x > 0 && below_hi.y > 0 && below_hi.z > 0 && above_lo.x > 0 && above_lo.y > 0 &&
               above_lo.z > 0;
    }

    vector normal(const point& p) const override {
        const point q = p.homogenized();
        // Measured from the centre in half-extents, the face p lies on is the axis where
        // |q - centre| comes nearest to the half-extent, on the side of q's sign.
        const vector half = (hi_ - lo_) / 2;
        const point centre = lo_ + half;
        const double off[3] = {q.x - centre.x, q.y - centre.y, q.z - centre.z};
        const double size[3] = {half.x, half.y, half.z};
        int axis = 0;
        double gap = INFINITY;
        for (int k = 0; k < 3; ++k) {
            const double g = std::fabs(size[k] - std::fabs(off[k]));
            if (g < gap) {
                gap = g;
                axis = k;
            }
        }
        const double sign = off[axis] < 0 ? -1 : 1;
        return vector(axis == 0 ? sign : 0, axis == 1 ? sign : 0, axis == 2 ? sign : 0);
    }

private:
    /// Makes the faces: called by set_geometry(), from the constructor and from read().
    void make_faces() override {
        outward_.clear();
        const double x[2] = {lo_.x, hi_.x}, y[2] = {lo_.y, hi_.y}, z[2] = {lo_.z, hi_.z};
        for (int side = 0; side < 2; ++side) {
            // side 1: the faces at hi, wound so the right-hand rule points out; side 0 reversed.
            const int a = side, b = 1 - side;
            std::vector<std::vector<point>> quads{
                {{x[a], y[0], z[0]}, {x[a], y[a], z[b]}, {x[a], y[1], z[1]}, {x[a], y[b], z[a]}},
                {{x[0], y[a], z[0]}, {x[b], y[a], z[a]}, {x[1], y[a], z[1]}, {x[a], y[a], z[b]}},
                {{x[0], y[0], z[a]}, {x[a], y[b], z[a]}, {x[1], y[1], z[a]}, {x[b], y[a], z[a]}},
            };
            for (auto& quad : quads) {
                std::unique_ptr<primitive> face = stage02::make_polygon(quad);
                face->set_surface(surface_);
                outward_.push_back(side == 1 ? 1 : -1);
                children_.push_back(std::move(face));
            }
        }
    }

    intersection find_intersection(const ray& r) const override {
        if (!hits_box(r, lo_, hi_)) return intersection::none();
        const double d[3] = {r.direction().x, r.direction().y, r.direction().z};
        // Face k is on axis k % 3; it faces the ray when its outward normal opposes d.
        auto facing = [&](std::size_t k) { return outward_[k] * d[k % 3] < 0; };
        intersection best = intersection::none();
        for (std::size_t k = 0; k < children_.size(); ++k)
            if (facing(k))
                if (const intersection i = children_[k]->intersect(r); i.nearer_than(best)) best = i;
        if (best.hit()) return best;  // entering through a front face: nothing is nearer
        for (std::size_t k = 0; k < children_.size(); ++k)
            if (!facing(k))
                if (const intersection i = children_[k]->intersect(r); i.nearer_than(best)) best = i;
        return best.hit() ? best : intersection::composite_only(this);
    }

    std::vector<int> outward_;  // +1 for the faces at hi, -1 at lo, in the order of children_
};

}  // namespace

std::unique_ptr<rtab_composite> make_box(const point& lo, const point& hi) {
    shapes::box_base::check_corners(lo, hi);
    return std::make_unique<box>(lo, hi);
}

}  // namespace vl::stage03
