// Reference: the fractal spheres (see assignments/03-composites/stage_03.hh).
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
    void build() {
        bounding_sphere::delete_all_children();
        std::unique_ptr<primitive> big = stage02::make_sphere(center_, radius_);
        big->set_surface(surface_);
        adopt(std::move(big));
        double extent = radius_, step = radius_;
        if (depth_ > 0) {
            const double small = radius_ * ratio_;
            for (int k = 0; k < 6; ++k) {
                if (k == parent_direction_) continue;
                adopt(std::make_unique<frac_sphere>(center_ + (radius_ + small) * directions[k], small, depth_ - 1,
                                                    ratio_, surface_, k ^ 1));
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
