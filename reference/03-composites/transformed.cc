// Reference: the transformed instance (see assignments/03-composites/stage_03.hh); the
// shell (the matrices, reading, writing, the one child and its surface) is
// vl::shapes::transformed_base.
#include <cmath>

#include "stage_01.hh"
#include "stage_03.hh"
#include "vl/composite_bases.hh"

namespace vl::stage03 {

namespace {

/// \brief One child seen through a matrix: rays go to the child's space, hits come back.
class transformed final : public shapes::transformed_base {
public:
    vector normal(const point& p) const override {
        if (children_.empty()) return NaN_vector;
        // Normals go back with the inverse transpose; w is dropped, since the transpose
        // of an affine inverse gives the normal a w that means nothing.
        vector n = normal_matrix_ * children_.front()->normal(to_object_ * p);
        n.w = 0;
        return n.unit();
    }
    bool contains(const point& p) const override {
        return !children_.empty() && children_.front()->contains(to_object_ * p);
    }
    point min_point() const override { return corner(true); }
    point max_point() const override { return corner(false); }

private:
    point corner(bool lowest) const {
        if (children_.empty()) return NaN_point;
        const point a = children_.front()->min_point(), b = children_.front()->max_point();
        if (is_nan(a) || is_nan(b)) return NaN_point;
        point result;
        for (int i = 0; i < 8; ++i) {
            const point p = to_world_ * point(i & 1 ? b.x : a.x, i & 2 ? b.y : a.y, i & 4 ? b.z : a.z);
            if (i == 0)
                result = p;
            else if (lowest)
                result = point(std::fmin(result.x, p.x), std::fmin(result.y, p.y), std::fmin(result.z, p.z));
            else
                result = point(std::fmax(result.x, p.x), std::fmax(result.y, p.y), std::fmax(result.z, p.z));
        }
        return result;
    }

    intersection find_intersection(const ray& r) const override {
        if (children_.empty()) return intersection::none();
        const vector d = to_object_ * r.direction();
        const double stretch = d.length();  // |M^-1 d|: object-space length of one world unit along the ray
        const intersection i = children_.front()->intersect(ray(to_object_ * r.origin(), d));
        if (i.hit()) return intersection::at(i.t / stretch, this);
        return i.is_composite_only() ? intersection::composite_only(this) : intersection::none();
    }
};

}  // namespace

std::unique_ptr<rtab_composite> make_transformed(std::unique_ptr<rtab_component> child, const matrix& object_to_world) {
    return shapes::transformed_base::make<transformed>(std::move(child), object_to_world, stage01::inverse,
        {stage01::scale_matrix, stage01::rotate_matrix, stage01::translate_matrix});
}

}  // namespace vl::stage03
