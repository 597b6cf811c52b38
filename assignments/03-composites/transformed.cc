// The transformed instance: see stage_03.hh for what each function must do, and README.md
// for hints. The TODOs are yours. The rest is done in the base class,
// vl::shapes::transformed_base (framework/include/vl/composite_bases.hh): the matrices
// to_world_ (M), to_object_ (M^-1, by your stage 01's inverse()) and normal_matrix_
// ((M^-1)^T), the child (children_.front(), when children_ is not empty) and the one-child
// insert(), the surface members (the child's), reading the steps, writing, and the checks
// of make_transformed().
#include "stage_01.hh"
#include "stage_03.hh"
#include "vl/composite_bases.hh"
#include "vl/not_implemented.hh"

namespace vl::stage03 {

namespace {

/// \brief One child seen through a matrix: rays go to the child's space, hits come back.
class transformed final : public shapes::transformed_base {
public:
    vector normal([[maybe_unused]] const point& p) const override {
        // TODO: the child's normal at the object-space point, taken back to world space
        // with the inverse transpose (normal_matrix_), made unit. Set its w to 0 before
        // unit(): the transpose of an affine inverse gives a normal a w that means nothing.
        // NaN_vector when there is no child.
        throw not_implemented_error();
    }
    bool contains([[maybe_unused]] const point& p) const override {
        // TODO: the child's contains() of the object-space point (false without a child).
        throw not_implemented_error();
    }
    point min_point() const override {
        // TODO: the lowest corner of the box around the eight corners of the child's box,
        // each taken to world space (NaN_point without a child or when its box is unknown).
        throw not_implemented_error();
    }
    point max_point() const override {
        // TODO: the highest corner of that box.
        throw not_implemented_error();
    }

private:
    intersection find_intersection([[maybe_unused]] const ray& r) const override {
        // TODO: take the ray to object space with to_object_ and intersect the child once.
        // A vl::ray makes its direction unit, so the child's t is an object-space
        // distance: divide it by the object-space length of the world direction
        // (|to_object_ * d|, d unit) to get the world distance. A hit's object is this
        // transform (only it maps points and normals back); a child's composite_only
        // comes back as composite_only(this), a miss as a miss. No child: a miss.
        throw not_implemented_error();
    }
};

}  // namespace

std::unique_ptr<rtab_composite> make_transformed(std::unique_ptr<rtab_component> child, const matrix& object_to_world) {
    // Stage 01 makes the steps a scene file gives and inverts the matrix.
    return shapes::transformed_base::make<transformed>(std::move(child), object_to_world, stage01::inverse,
        {stage01::scale_matrix, stage01::rotate_matrix, stage01::translate_matrix});
}

}  // namespace vl::stage03
