// The fractal spheres (stage_03.hh): nested bounding spheres with tight spheres.
#include "bounding_sphere.hh"
#include "stage_02.hh"

namespace vl::stage03 {

namespace {

/// \brief A sphere with a fractal sphere of `ratio` times its radius on each side but the
/// one towards its parent, all inside one tight bounding sphere.
class frac_sphere final : public shapes::frac_sphere_base<bounding_sphere> {
public:
    using frac_sphere_base::frac_sphere_base;

private:
    /// Makes the spheres: called by make(), and again by read() with what it read.
    void build() override {
        std::unique_ptr<primitive> ball = stage02::make_sphere(center_, radius_);
        ball->set_surface(surface_);
        adopt(std::move(ball));
        const double child_radius = radius_ * ratio_;
        for (int k = 0; depth_ > 0 && k < 6; ++k)
            if (k != parent_direction_)
                adopt(make<frac_sphere>(center_ + (radius_ + child_radius) * directions[k], child_radius, depth_ - 1,
                                        ratio_, surface_, k ^ 1));
        // Horner's rule for r (1 + 2Q (1 + Q (1 + ... (1 + Q)))), depth_ factors of Q.
        double chain = 0;
        for (int level = 0; level < depth_; ++level) chain = ratio_ * (1 + chain);
        set_sphere(center_, radius_ * (1 + 2 * chain) * (1 + 1e-12));
    }
};

}  // namespace

std::unique_ptr<rtab_composite> make_frac_sphere(const point& center, double radius, int depth, double ratio) {
    shapes::check_frac_sphere(center, radius, depth, ratio);
    return frac_sphere::make<frac_sphere>(center, radius, depth, ratio);
}

}  // namespace vl::stage03
