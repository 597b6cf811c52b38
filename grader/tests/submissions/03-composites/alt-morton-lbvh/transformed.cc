// The transformed instance. Rays go to object space through the inverse matrix; normals
// come back through the cofactor matrix of the linear part A of object_to_world: the
// inverse transpose of A is cof(A) / det(A), and the columns of cof(A) are the cross
// products of A's columns, a2 x a3, a3 x a1, a1 x a2.
#include <cmath>

#include "stage_01.hh"
#include "stage_03.hh"
#include "vl/composite_bases.hh"

namespace vl::stage03 {

namespace {

bool finite(const point& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

class transformed final : public shapes::transformed_base {
public:
    transformed(std::unique_ptr<rtab_component> child, const matrix& object_to_world)
        : transformed_base(std::move(child), object_to_world,
                           {stage01::scale_matrix, stage01::rotate_matrix, stage01::translate_matrix}, stage01::inverse) {}

    vector normal(const point& p) const override {
        if (children_.empty()) return NaN_vector;
        const vector n = children_.front()->normal(to_object_ * p);
        const matrix& m = to_world_;
        const vector a1(m(0, 0), m(1, 0), m(2, 0)), a2(m(0, 1), m(1, 1), m(2, 1)), a3(m(0, 2), m(1, 2), m(2, 2));
        const vector cofactor[3] = {a2 % a3, a3 % a1, a1 % a2};  // the columns of cof(A)
        const double det = a1 * cofactor[0];
        // (A^-1)^T n = (n.x (a2 x a3) + n.y (a3 x a1) + n.z (a1 x a2)) / det A; w stays 0.
        vector world = (n.x * cofactor[0] + n.y * cofactor[1] + n.z * cofactor[2]) / det;
        world.w = 0;
        return world.unit();
    }
    bool contains(const point& p) const override {
        return !children_.empty() && children_.front()->contains(to_object_ * p);
    }
    point min_point() const override { return world_corner(false); }
    point max_point() const override { return world_corner(true); }

private:
    /// The low (`high` false) or high corner of the world box around the child's box.
    point world_corner(bool high) const {
        if (children_.empty()) return NaN_point;
        const point lo = children_.front()->min_point(), hi = children_.front()->max_point();
        if (!finite(lo) || !finite(hi)) return NaN_point;
        double out[3] = {0, 0, 0};
        for (unsigned bits = 0; bits < 8; ++bits) {
            const point c = to_world_ * point((bits & 1u) ? hi.x : lo.x, (bits & 2u) ? hi.y : lo.y,
                                              (bits & 4u) ? hi.z : lo.z);
            const double xyz[3] = {c.x, c.y, c.z};
            for (int a = 0; a < 3; ++a)
                if (bits == 0 || (high ? xyz[a] > out[a] : xyz[a] < out[a])) out[a] = xyz[a];
        }
        return point(out[0], out[1], out[2]);
    }

    intersection find_intersection(const ray& r) const override {
        if (children_.empty()) return intersection::none();
        const vector d = to_object_ * r.direction();
        const double stretch = d.length();  // |M^-1 d| for the unit world direction d
        const intersection i = children_.front()->intersect(ray(to_object_ * r.origin(), d));
        if (i.hit()) return intersection::at(i.t / stretch, this);
        if (i.is_composite_only()) return intersection::composite_only(this);
        return intersection::none();
    }
};

}  // namespace

std::unique_ptr<rtab_composite> make_transformed(std::unique_ptr<rtab_component> child, const matrix& object_to_world) {
    shapes::transformed_base::check_matrix(object_to_world);
    return std::make_unique<transformed>(std::move(child), object_to_world);
}

}  // namespace vl::stage03
