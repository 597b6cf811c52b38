// The fractal spheres: see stage_03.hh for what each function must do, and README.md for
// hints. build() is yours. The rest is done in the base class,
// vl::shapes::frac_sphere_base (framework/include/vl/composite_bases.hh): the values
// center_, radius_, depth_, ratio_, surface_ and parent_direction_, the table
// `directions`, reading and writing FRACSPH, the refusal of insert(), and the checks of
// make_frac_sphere(). A fractal level is your bounding_sphere: build() uses its adopt().
#include "bounding_sphere.hh"
#include "stage_02.hh"
#include "vl/not_implemented.hh"

namespace vl::stage03 {

namespace {

/// \brief A sphere with a fractal sphere of `ratio` times its radius on each side but the
/// one towards its parent, all inside one tight bounding sphere. It needs no constructor:
/// make<frac_sphere>(center, radius, depth, ratio, surface, parent_direction) makes it,
/// sets the values and calls build().
class frac_sphere final : public shapes::frac_sphere_base<bounding_sphere> {
private:
    /// Makes the spheres: called by make(), and again by read() with what it read (once
    /// the spheres made before are gone).
    void build() override {
        // TODO: the big sphere (stage02::make_sphere, with surface_ set on it), then, when
        // depth_ > 0, a frac_sphere of depth_ - 1 and radius radius_ * ratio_ in each of
        // the six `directions` but parent_direction_, touching the big sphere from
        // outside (centre at distance radius_ + radius_ * ratio_), each made by
        // make<frac_sphere>(centre, radius, depth, ratio_, surface_, its parent's
        // direction). adopt() the big sphere and each fractal sphere. Then
        // set_sphere() to the tight bound of stage_03.hh: r (1 + 2Q + ... + 2Q^D) around
        // center_. (A child placed in direction k has its parent in direction k ^ 1.)
        throw not_implemented_error();
    }
};

}  // namespace

std::unique_ptr<rtab_composite> make_frac_sphere(const point& center, double radius, int depth, double ratio) {
    shapes::check_frac_sphere(center, radius, depth, ratio);
    return frac_sphere::make<frac_sphere>(center, radius, depth, ratio);
}

}  // namespace vl::stage03
