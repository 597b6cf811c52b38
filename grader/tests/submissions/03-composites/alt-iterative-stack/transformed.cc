// The transformed instance (stage_03.hh): the child seen through object_to_world.
#include <cmath>

#include "stage_01.hh"
#include "stage_03.hh"
#include "vl/composite_bases.hh"

namespace vl::stage03 {

namespace {

/// \brief One child seen through a matrix: rays go to the child's space, hits come back.
class transformed final : public shapes::transformed_base {
public:
    transformed(std::unique_ptr<rtab_component> child, const matrix& object_to_world)
        : transformed_base(std::move(child), object_to_world,
                           {stage01::scale_matrix, stage01::rotate_matrix, stage01::translate_matrix}, stage01::inverse) {}

    vector normal(const point& p) const override {
        if (children_.empty()) return NaN_vector;
        const vector n = children_.front()->normal(to_object_ * p);
        const vector world = normal_matrix_ * vector(n.x, n.y, n.z, 0);
        return vector(world.x, world.y, world.z, 0).unit();
    }
    bool contains(const point& p) const override {
        if (children_.empty()) return false;
        return children_.front()->contains(to_object_ * p);
    }
    /// The child's box as a centre and half-extents: the world box is centred at M c and
    /// reaches |A| h in each axis (A the linear part of M, |A| element by element).
    point min_point() const override { return world_box(-1); }
    point max_point() const override { return world_box(1); }

private:
    point world_box(double side) const {
        if (children_.empty()) return NaN_point;
        const point a = children_.front()->min_point(), b = children_.front()->max_point();
        if (is_nan(a) || is_nan(b)) return NaN_point;
        const point c = to_world_ * point((a.x + b.x) / 2, (a.y + b.y) / 2, (a.z + b.z) / 2);
        const double h[3] = {(b.x - a.x) / 2, (b.y - a.y) / 2, (b.z - a.z) / 2};
        double reach[3];
        for (int i = 0; i < 3; ++i)
            reach[i] = std::fabs(to_world_(i, 0)) * h[0] + std::fabs(to_world_(i, 1)) * h[1] +
                       std::fabs(to_world_(i, 2)) * h[2];
        return point(c.x + side * reach[0], c.y + side * reach[1], c.z + side * reach[2]);
    }

    intersection find_intersection(const ray& r) const override {
        if (children_.empty()) return intersection::none();
        const point o = to_object_ * r.origin();
        const vector d = to_object_ * r.direction();
        const intersection i = children_.front()->intersect(ray(o, d));
        if (i.is_miss()) return i;
        if (!i.hit()) return intersection::composite_only(this);
        return intersection::at(i.t / d.length(), this);
    }
};

}  // namespace

std::unique_ptr<rtab_composite> make_transformed(std::unique_ptr<rtab_component> child, const matrix& object_to_world) {
    shapes::transformed_base::check_matrix(object_to_world);
    return std::make_unique<transformed>(std::move(child), object_to_world);
}

}  // namespace vl::stage03
