// The bounding sphere: see stage_03.hh for what each function must do, and README.md for
// hints. The functions marked TODO are yours; the rest of the class is done in its base,
// vl::shapes::bounding_sphere_base (see bounding_sphere.hh).
#include "bounding_sphere.hh"

#include "vl/bounds.hh"
#include "vl/not_implemented.hh"

namespace vl::stage03 {

void bounding_sphere::insert([[maybe_unused]] std::unique_ptr<rtab_component> child) {
    // TODO: first the refusals every composite shares: check_insertable(child.get())
    // (rtab_composite's) throws for a null pointer and for the sphere itself. Then refuse
    // a child whose box is unknown (vl::shapes::finite_box() says whether it is known)
    // with a vl::usage_error that names both types and says what to do (put it beside the
    // BOUNDSPH in a LIST). Then adopt() the child, which adds it and grows the sphere.
    // (Not rtab_composite::insert(): that adds the child to children_ itself.)
    throw not_implemented_error();
}

void bounding_sphere::adopt([[maybe_unused]] std::unique_ptr<rtab_component> child) {
    // TODO: add child to children_, grow lo_ and hi_ around its box, and make the sphere
    // (bound_center_, bound_radius_) the smallest one around that box: its centre, half
    // its diagonal. (Around the children's *centres* it would cut big children off.)
    throw not_implemented_error();
}

intersection bounding_sphere::find_intersection([[maybe_unused]] const ray& r) const {
    // TODO: the thesis's three rules (stage_03.hh). One vl::hits_sphere() test first: a
    // ray that misses the sphere tests no child. Then the nearest hit among the children
    // (rtab_composite::nearest_child_hit() does that), or composite_only(this) when the
    // ray entered the sphere and hit nothing. An empty bounding sphere is missed for free.
    throw not_implemented_error();
}

std::unique_ptr<rtab_composite> make_bounding_sphere() { return std::make_unique<bounding_sphere>(); }

}  // namespace vl::stage03
