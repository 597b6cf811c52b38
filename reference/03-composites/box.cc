// Reference: the box of six polygons (see assignments/03-composites/stage_03.hh); the
// shell (corners, reading, writing, refusals) is vl::shapes::box_base.
#include <cmath>

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

    bool contains(const point& p) const override {
        const point q = p.homogenized();
        return lo_.x < q.x && q.x < hi_.x && lo_.y < q.y && q.y < hi_.y && lo_.z < q.z && q.z < hi_.z;
    }

    vector normal(const point& p) const override {
        // The face whose plane is nearest to p.
        const point q = p.homogenized();
        const double distance[6] = {q.x - lo_.x, hi_.x - q.x, q.y - lo_.y, hi_.y - q.y, q.z - lo_.z, hi_.z - q.z};
        static const vector outward[6] = {{-1, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, 1, 0}, {0, 0, -1}, {0, 0, 1}};
        int nearest = 0;
        for (int k = 1; k < 6; ++k)
            if (std::fabs(distance[k]) < std::fabs(distance[nearest])) nearest = k;
        return outward[nearest];
    }

private:
    void make_faces() override {
        // The eight corners; corner(i, j, k) takes x, y, z from hi when i, j, k is 1.
        auto c = [&](int i, int j, int k) { return point(i ? hi_.x : lo_.x, j ? hi_.y : lo_.y, k ? hi_.z : lo_.z); };
        // Each face counter-clockwise seen from outside, so its normal points out.
        const point faces[6][4] = {
            {c(0, 0, 0), c(0, 0, 1), c(0, 1, 1), c(0, 1, 0)},  // x = lo, normal -x
            {c(1, 0, 0), c(1, 1, 0), c(1, 1, 1), c(1, 0, 1)},  // x = hi, normal +x
            {c(0, 0, 0), c(1, 0, 0), c(1, 0, 1), c(0, 0, 1)},  // y = lo, normal -y
            {c(0, 1, 0), c(0, 1, 1), c(1, 1, 1), c(1, 1, 0)},  // y = hi, normal +y
            {c(0, 0, 0), c(0, 1, 0), c(1, 1, 0), c(1, 0, 0)},  // z = lo, normal -z
            {c(0, 0, 1), c(1, 0, 1), c(1, 1, 1), c(0, 1, 1)},  // z = hi, normal +z
        };
        for (const auto& f : faces) {
            std::unique_ptr<primitive> face = stage02::make_polygon({f[0], f[1], f[2], f[3]});
            face->set_surface(surface_);
            children_.push_back(std::move(face));
        }
    }

    intersection find_intersection(const ray& r) const override {
        if (!hits_box(r, lo_, hi_)) return intersection::none();
        const intersection nearest = nearest_child_hit(r);
        return nearest.hit() ? nearest : intersection::composite_only(this);
    }
};

}  // namespace

std::unique_ptr<rtab_composite> make_box(const point& lo, const point& hi) {
    shapes::box_base::check_corners(lo, hi);
    return std::make_unique<box>(lo, hi);
}

}  // namespace vl::stage03
