// FRACSPH: a sphere, six (then five) smaller fractal spheres touching it, every level in
// its own tight bounding sphere.
#include <cmath>
#include <cstdio>
#include <ostream>
#include <string>

#include "sphere_group.hh"
#include "stage_02.hh"
#include "vl/primitive.hh"
#include "vl/scene_reader.hh"

namespace vl::stage03 {

namespace {

std::string g17(double x) {
    char text[40];
    std::snprintf(text, sizeof text, "%.17g", x);
    return text;
}

const vector axes[6] = {{0, 0, 1}, {0, 0, -1}, {1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}};

class fractal_sphere final : public sphere_group {
public:
    /// `towards_parent` is the direction from this sphere to its parent (zero at the top).
    fractal_sphere(const point& c, double r, int depth, double q, const surface& look, const vector& towards_parent)
        : centre_(c), radius_(r), depth_(depth), ratio_(q), look_(look), towards_parent_(towards_parent) {
        grow();
    }

    std::string type_name() const override { return "FRACSPH"; }

    void insert(std::unique_ptr<rtab_component>) override {
        throw usage_error("FRACSPH: a fractal sphere makes its own spheres, insert() cannot add to it "
                          "(put the FRACSPH and the other object in a LIST)");
    }

    void read(scene_reader& in) override {
        point c = centre_;
        double r = radius_, q = ratio_;
        int depth = depth_;
        std::vector<scene_reader::property> keys{
            {"center",
             [&] {
                 const source_location here = in.peek().where;
                 c = in.read_point("center of FRACSPH").homogenized();
                 if (!(std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z)))
                     in.fail(here, "center of FRACSPH is not a finite point");
             }},
            {"radius", [&] { r = in.read_positive("radius of FRACSPH"); }},
            {"depth", [&] { depth = in.read_int("depth of FRACSPH", 0, 7); }},
            {"ratio",
             [&] {
                 const source_location here = in.peek().where;
                 q = in.read_number("ratio of FRACSPH");
                 if (q <= 0 || q >= 1) in.fail(here, "ratio of FRACSPH must be more than 0 and less than 1");
             }},
        };
        add_surface_properties(keys, in, look_, "FRACSPH");
        in.read_block("FRACSPH", keys);
        centre_ = c;
        radius_ = r;
        ratio_ = q;
        depth_ = depth;
        grow();
    }

    void write(std::ostream& out) const override {
        out << "FRACSPH { center " << g17(centre_.x) << ' ' << g17(centre_.y) << ' ' << g17(centre_.z) << " radius "
            << g17(radius_) << " depth " << depth_ << " ratio " << g17(ratio_);
        write_surface(out, look_);
        out << " }";
    }

private:
    void grow() {
        sphere_group::delete_all_children();
        auto big = stage02::make_sphere(centre_, radius_);
        big->set_surface(look_);
        take(std::move(big));
        const double small = ratio_ * radius_;
        if (depth_ > 0)
            for (const vector& u : axes) {
                if (u * towards_parent_ > 0.5) continue;  // that side is the parent's
                take(std::make_unique<fractal_sphere>(centre_ + (radius_ + small) * u, small, depth_ - 1, ratio_, look_,
                                                      -u));
            }
        // The longest chain: r + 2 r q + 2 r q^2 + ... + 2 r q^depth.
        double far = radius_, size = radius_;
        for (int level = 0; level < depth_; ++level) {
            size *= ratio_;
            far += size + size;
        }
        tighten(centre_, far + far * 1e-12);
    }

    point centre_;
    double radius_;
    int depth_;
    double ratio_;
    surface look_;
    vector towards_parent_;
};

}  // namespace

std::unique_ptr<rtab_composite> make_frac_sphere(const point& center, double radius, int depth, double ratio) {
    const point c = center.homogenized();
    if (!(std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z)))
        throw usage_error("make_frac_sphere: the center is not a finite point");
    if (!(std::isfinite(radius) && radius > 0)) throw usage_error("make_frac_sphere: the radius must be finite and > 0");
    if (depth < 0 || depth > 7) throw usage_error("make_frac_sphere: the depth must be from 0 to 7");
    if (!(ratio > 0 && ratio < 1)) throw usage_error("make_frac_sphere: the ratio must be between 0 and 1");
    return std::make_unique<fractal_sphere>(c, radius, depth, ratio, surface{}, vector(0, 0, 0));
}

}  // namespace vl::stage03
