// The fractal spheres (stage_03.hh): nested bounding spheres with tight spheres.
#include <cmath>
#include <ostream>
#include <string>

#include "bounding_sphere.hh"
#include "stage_02.hh"
#include "vl/primitive.hh"
#include "vl/scene_reader.hh"
#include "vl/shape_params.hh"

namespace vl::stage03 {

namespace {

constexpr int max_depth = shapes::frac_sphere_params::max_depth;
constexpr int no_parent = -1;

/// The six axis directions; direction k ^ 1 is the opposite of direction k.
const vector directions[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};

/// \brief A sphere with a fractal sphere of `ratio` times its radius on each side but the
/// one towards its parent, all inside one tight bounding sphere.
class frac_sphere final : public bounding_sphere {
public:
    frac_sphere(const point& center, double radius, int depth, double ratio, const surface& s,
                int parent_direction = no_parent)
        : center_(center.homogenized()), radius_(radius), depth_(depth), ratio_(ratio), surface_(s),
          parent_direction_(parent_direction) {
        build();
    }

    std::string type_name() const override { return "FRACSPH"; }

    void insert(std::unique_ptr<rtab_component>) override {
        throw usage_error("FRACSPH makes its own spheres: insert() cannot add to it"
                          " (put the FRACSPH and the other object in a LIST)");
    }

    void read(scene_reader& in) override {
        shapes::frac_sphere_params p{center_, radius_, depth_, ratio_};
        std::vector<scene_reader::property> properties = p.properties(in);
        add_surface_properties(properties, in, surface_, "FRACSPH");
        in.read_block("FRACSPH", properties);
        center_ = p.center;
        radius_ = p.radius;
        depth_ = p.depth;
        ratio_ = p.ratio;
        build();
    }

    void write(std::ostream& s) const override {
        shapes::frac_sphere_params{center_, radius_, depth_, ratio_}.write(s);
        write_surface(s, surface_);
        s << " }";
    }

private:
    /// Makes the spheres: called by the constructor, and again by read() with what it read.
    void build() {
        bounding_sphere::delete_all_children();
        std::unique_ptr<primitive> ball = stage02::make_sphere(center_, radius_);
        ball->set_surface(surface_);
        adopt(std::move(ball));
        const double child_radius = radius_ * ratio_;
        for (int k = 0; depth_ > 0 && k < 6; ++k)
            if (k != parent_direction_)
                adopt(std::make_unique<frac_sphere>(center_ + (radius_ + child_radius) * directions[k], child_radius,
                                                    depth_ - 1, ratio_, surface_, k ^ 1));
        // Horner's rule for r (1 + 2Q (1 + Q (1 + ... (1 + Q)))), depth_ factors of Q.
        double chain = 0;
        for (int level = 0; level < depth_; ++level) chain = ratio_ * (1 + chain);
        set_sphere(center_, radius_ * (1 + 2 * chain) * (1 + 1e-12));
    }

    point center_;
    double radius_;
    int depth_;
    double ratio_;
    surface surface_;
    int parent_direction_;  // the direction towards the parent, or no_parent
};

}  // namespace

std::unique_ptr<rtab_composite> make_frac_sphere(const point& center, double radius, int depth, double ratio) {
    if (!checks::finite(center.homogenized()) || !std::isfinite(radius) || !(radius > 0))
        throw usage_error("make_frac_sphere: the center must be finite and the radius a finite number > 0");
    if (depth < 0 || depth > max_depth)
        throw usage_error("make_frac_sphere: the depth must be from 0 to 7, not " + std::to_string(depth));
    if (!(ratio > 0 && ratio < 1)) throw usage_error("make_frac_sphere: the ratio must be between 0 and 1");
    return std::make_unique<frac_sphere>(center, radius, depth, ratio, surface{});
}

}  // namespace vl::stage03
