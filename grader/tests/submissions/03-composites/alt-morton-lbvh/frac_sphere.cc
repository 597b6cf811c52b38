// The fractal spheres: each level a bounding sphere around its big sphere and its child
// levels, with the tight sphere of the contract. The six directions come from one
// direction, +x or -x, turned about the diagonal (1, 1, 1) by a table of axis rotations.
#include <cmath>
#include <limits>
#include <ostream>
#include <string>

#include "sphere_bound.hh"
#include "stage_02.hh"
#include "vl/error.hh"
#include "vl/primitive.hh"
#include "vl/scene_reader.hh"

namespace vl::stage03 {

namespace {

bool finite(const point& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

constexpr int deepest = 7;
constexpr int top_level = -1;  // the top sphere has no parent direction

/// The rotations by 0, 120 and 240 degrees about (1, 1, 1), row by row: rotation `turn`
/// permutes the axes cyclically and takes the x axis to axis `turn` (x, then y, then z).
constexpr double turns[3][3][3] = {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}},
                                   {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},
                                   {{0, 1, 0}, {0, 0, 1}, {1, 0, 0}}};

/// Direction k of the six: (+1, 0, 0) for even k, (-1, 0, 0) for odd k, turned by
/// rotation k / 2. So direction k ^ 1 is the opposite of direction k.
vector direction(int k) {
    const double start[3] = {(k & 1) ? -1.0 : 1.0, 0, 0};
    const auto& rotation = turns[k >> 1];
    double out[3] = {0, 0, 0};
    for (int row = 0; row < 3; ++row)
        for (int col = 0; col < 3; ++col) out[row] += rotation[row][col] * start[col];
    return vector(out[0], out[1], out[2]);
}

/// r (1 + 2Q + 2Q^2 + ... + 2Q^D): from the centre to the far end of the longest chain.
double reach(double radius, int depth, double ratio) {
    double sum = 0, power = 1;
    for (int level = 1; level <= depth; ++level) {
        power *= ratio;
        sum += power;
    }
    return radius * (1 + 2 * sum);
}

class fractal final : public sphere_bound {
public:
    fractal(const point& center, double radius, int depth, double ratio, const surface& s, int back = top_level)
        : center_(center.homogenized()), radius_(radius), depth_(depth), ratio_(ratio), surface_(s), back_(back) {
        grow();
    }

    std::string type_name() const override { return "FRACSPH"; }

    void insert(std::unique_ptr<rtab_component>) override {
        throw usage_error("FRACSPH makes its own spheres: insert() cannot add to it"
                          " (put the FRACSPH and the other object in a LIST)");
    }

    void read(scene_reader& in) override {
        point center = center_;
        double radius = radius_, ratio = ratio_;
        int depth = depth_;
        std::vector<scene_reader::property> properties{
            {"center", [&] {
                 const source_location where = in.peek().where;
                 center = in.read_point("center of FRACSPH").homogenized();
                 if (!finite(center)) in.fail(where, "center of FRACSPH must be a finite point (w not 0)");
             }},
            {"radius", [&] { radius = in.read_positive("radius of FRACSPH"); }},
            {"depth", [&] { depth = in.read_int("depth of FRACSPH", 0, deepest); }},
            {"ratio", [&] {
                 const source_location where = in.peek().where;
                 ratio = in.read_number("ratio of FRACSPH");
                 if (!(ratio > 0 && ratio < 1))
                     in.fail(where, "ratio of FRACSPH must be between 0 and 1 (each level smaller), found " +
                                        std::to_string(ratio));
             }}};
        add_surface_properties(properties, in, surface_, "FRACSPH");
        in.read_block("FRACSPH", properties);
        center_ = center;
        radius_ = radius;
        depth_ = depth;
        ratio_ = ratio;
        grow();
    }

    void write(std::ostream& s) const override {
        const auto old_precision = s.precision(std::numeric_limits<double>::max_digits10);
        s << "FRACSPH { center " << center_.x << ' ' << center_.y << ' ' << center_.z << " radius " << radius_
          << " depth " << depth_ << " ratio " << ratio_;
        s.precision(old_precision);
        write_surface(s, surface_);
        s << " }";
    }

private:
    /// Makes this level's big sphere and its child levels, then the tight sphere.
    void grow() {
        sphere_bound::delete_all_children();
        auto big = stage02::make_sphere(center_, radius_);
        big->set_surface(surface_);
        take(std::move(big));
        if (depth_ > 0) {
            const double small = radius_ * ratio_;
            for (int k = 0; k < 6; ++k) {
                if (k == back_) continue;
                // The child in direction k has its parent in the opposite direction, k ^ 1.
                take(std::make_unique<fractal>(center_ + (radius_ + small) * direction(k), small, depth_ - 1, ratio_,
                                               surface_, k ^ 1));
            }
        }
        use_sphere(center_, reach(radius_, depth_, ratio_));
    }

    point center_;
    double radius_;
    int depth_;
    double ratio_;
    surface surface_;
    int back_;  // the direction towards the parent, or top_level
};

}  // namespace

std::unique_ptr<rtab_composite> make_frac_sphere(const point& center, double radius, int depth, double ratio) {
    if (!finite(center.homogenized()) || !std::isfinite(radius) || !(radius > 0))
        throw usage_error("make_frac_sphere: the center must be finite and the radius a finite number > 0");
    if (depth < 0 || depth > deepest)
        throw usage_error("make_frac_sphere: the depth must be from 0 to 7, not " + std::to_string(depth));
    if (!(ratio > 0 && ratio < 1)) throw usage_error("make_frac_sphere: the ratio must be between 0 and 1");
    return std::make_unique<fractal>(center, radius, depth, ratio, surface{});
}

}  // namespace vl::stage03
