// FRACSPH as one object: all its spheres are its children, and a tree of levels (each a
// centre and a tight bounding radius) says which spheres a ray must test. A ray tests
// the bound of a level only when it entered its parent's bound, so the bound tests and
// the sphere tests are those of nested bounding spheres.
#include <cmath>
#include <limits>
#include <ostream>
#include <string>
#include <vector>

#include "stage_02.hh"
#include "stage_03.hh"
#include "vl/bounds.hh"
#include "vl/primitive.hh"
#include "vl/scene_reader.hh"

namespace vl::stage03 {

namespace {

bool finite_centre(const point& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

class fractal final : public rtab_composite {
public:
    fractal(const point& centre, double radius, int depth, double ratio)
        : centre_(centre), radius_(radius), depth_(depth), ratio_(ratio) {
        generate();
    }

    std::string type_name() const override { return "FRACSPH"; }

    void insert(std::unique_ptr<rtab_component>) override {
        throw usage_error("FRACSPH makes its spheres itself: nothing can be inserted into it "
                          "(put the FRACSPH and the other object in a LIST)");
    }
    void delete_all_children() override {
        rtab_composite::delete_all_children();
        levels_.clear();
    }

    void read(scene_reader& in) override {
        point centre = centre_;
        double radius = radius_, ratio = ratio_;
        int depth = depth_;
        std::vector<scene_reader::property> keys{
            {"center", [&] {
                 const source_location where = in.peek().where;
                 centre = in.read_point("center of FRACSPH").homogenized();
                 if (!finite_centre(centre)) in.fail(where, "center of FRACSPH: not a finite point");
             }},
            {"radius", [&] { radius = in.read_positive("radius of FRACSPH"); }},
            {"depth", [&] { depth = in.read_int("depth of FRACSPH", 0, 7); }},
            {"ratio", [&] {
                 const source_location where = in.peek().where;
                 ratio = in.read_number("ratio of FRACSPH");
                 if (!(ratio > 0) || !(ratio < 1)) in.fail(where, "ratio of FRACSPH: must be above 0 and below 1");
             }}};
        add_surface_properties(keys, in, look_, "FRACSPH");
        in.read_block("FRACSPH", keys);
        centre_ = centre;
        radius_ = radius;
        depth_ = depth;
        ratio_ = ratio;
        generate();
    }

    void write(std::ostream& out) const override {
        const auto keep = out.precision(std::numeric_limits<double>::max_digits10);
        out << "FRACSPH { center " << centre_.x << ' ' << centre_.y << ' ' << centre_.z << " radius " << radius_
            << " depth " << depth_ << " ratio " << ratio_;
        out.precision(keep);
        write_surface(out, look_);
        out << " }";
    }

private:
    struct level {
        point centre;
        double bound;                // the radius of the sphere around this level's spheres
        std::size_t sphere;          // its big sphere, in children_
        std::vector<std::size_t> sub;  // the levels touching it, in levels_
    };

    void generate() {
        children_.clear();
        levels_.clear();
        add_level(centre_, radius_, depth_, -1, -1);
    }

    /// Adds the level at `c` (radius r, depth d) and its sublevels, none on axis `back_axis`
    /// on side `back_side` (the parent's side); returns its index in levels_.
    std::size_t add_level(const point& c, double r, int d, int back_axis, int back_side) {
        std::unique_ptr<primitive> ball = stage02::make_sphere(c, r);
        ball->set_surface(look_);
        children_.push_back(std::move(ball));
        const std::size_t at = levels_.size();
        levels_.push_back({c, tight(r, d), children_.size() - 1, {}});
        if (d == 0) return at;
        const double small = r * ratio_;
        for (int axis = 0; axis < 3; ++axis)
            for (int side = -1; side <= 1; side += 2) {
                if (axis == back_axis && side == back_side) continue;
                vector offset(0, 0, 0);
                (axis == 0 ? offset.x : axis == 1 ? offset.y : offset.z) = side * (r + small);
                const std::size_t s = add_level(c + offset, small, d - 1, axis, -side);
                levels_[at].sub.push_back(s);
            }
        return at;
    }

    /// r (1 + 2Q + ... + 2Q^d), summed in long double, a little enlarged against round-off.
    double tight(double r, int d) const {
        long double sum = 1, power = 1;
        for (int k = 1; k <= d; ++k) {
            power *= ratio_;
            sum += 2 * power;
        }
        return static_cast<double>(r * sum) * (1 + 1e-12);
    }

    void walk(std::size_t k, const ray& r, intersection& best) const {
        const level& l = levels_[k];
        const intersection i = children_[l.sphere]->intersect(r);
        if (i.nearer_than(best)) best = i;
        for (std::size_t s : l.sub)
            if (hits_sphere(r, levels_[s].centre, levels_[s].bound)) walk(s, r, best);
    }

    intersection find_intersection(const ray& r) const override {
        if (levels_.empty()) return intersection::none();
        if (!hits_sphere(r, levels_[0].centre, levels_[0].bound)) return intersection::none();
        intersection best = intersection::none();
        walk(0, r, best);
        return best.hit() ? best : intersection::composite_only(this);
    }

    point centre_;
    double radius_;
    int depth_;
    double ratio_;
    surface look_;
    std::vector<level> levels_;
};

}  // namespace

std::unique_ptr<rtab_composite> make_frac_sphere(const point& center, double radius, int depth, double ratio) {
    const point c = center.homogenized();
    if (!finite_centre(c)) throw usage_error("make_frac_sphere: center is not a finite point");
    if (!std::isfinite(radius) || !(radius > 0)) throw usage_error("make_frac_sphere: radius must be finite and above 0");
    if (depth < 0 || depth > 7) throw usage_error("make_frac_sphere: depth must be a whole number from 0 to 7");
    if (!(ratio > 0) || !(ratio < 1)) throw usage_error("make_frac_sphere: ratio must be above 0 and below 1");
    return std::make_unique<fractal>(c, radius, depth, ratio);
}

}  // namespace vl::stage03
