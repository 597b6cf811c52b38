// Reference: the fractal spheres (see assignments/03-composites/stage_03.hh); the shell
// (values, reading, writing, the refusal of insert) is vl::shapes::frac_sphere_base.
#include "bounding_sphere.hh"
#include "stage_02.hh"

namespace vl::stage03 {

namespace {

/// \brief A sphere with a fractal sphere of `ratio` times its radius on each side but the
/// one towards its parent, all inside one tight bounding sphere.
class frac_sphere final : public shapes::frac_sphere_base<bounding_sphere> {
private:
    void build() override {
        std::unique_ptr<primitive> big = stage02::make_sphere(center_, radius_);
        big->set_surface(surface_);
        adopt(std::move(big));
        double extent = radius_, step = radius_;
        if (depth_ > 0) {
            const double small = radius_ * ratio_;
            for (int k = 0; k < 6; ++k) {
                if (k == parent_direction_) continue;
                adopt(make<frac_sphere>(center_ + (radius_ + small) * directions[k], small, depth_ - 1, ratio_,
                                        surface_, k ^ 1));
            }
        }
        // The farthest point of the straight chain of spheres: r (1 + 2Q + ... + 2Q^D).
        for (int level = 1; level <= depth_; ++level) {
            step *= ratio_;
            extent += 2 * step;
        }
        // A few units in the last place more, so round-off never cuts a sphere off.
        set_sphere(center_, extent * (1 + 1e-12));
    }
};

}  // namespace

std::unique_ptr<rtab_composite> make_frac_sphere(const point& center, double radius, int depth, double ratio) {
    shapes::check_frac_sphere(center, radius, depth, ratio);
    return frac_sphere::make<frac_sphere>(center, radius, depth, ratio);
}

}  // namespace vl::stage03
