// The fractal spheres: nested bounding spheres, each with a tight sphere of its own.
#include <charconv>
#include <cmath>
#include <ostream>
#include <string>

#include "sphere_hull.hh"
#include "stage_02.hh"
#include "vl/primitive.hh"
#include "vl/scene_reader.hh"

namespace vl::stage03 {

namespace {

struct direction {
    int axis;   // 0, 1, 2
    int sign;   // +1 or -1
    vector unit() const {
        return vector(axis == 0 ? sign : 0, axis == 1 ? sign : 0, axis == 2 ? sign : 0);
    }
    bool operator==(const direction&) const = default;
};

/// Fills `hull` with the sphere at `c` of radius `r` and, below it, the `depth` levels of
/// smaller spheres, none towards `parent` (when `has_parent`). Returns how far from `c`
/// the farthest sphere reaches, and fixes the hull's sphere to that (a little more, so
/// that round-off never cuts a sphere off).
double fill(sphere_hull& hull, const point& c, double r, int depth, double q, const surface& s, bool has_parent,
            direction parent) {
    std::unique_ptr<primitive> ball = stage02::make_sphere(c, r);
    ball->set_surface(s);
    hull.add_child(std::move(ball));
    double reach = r;
    if (depth > 0) {
        const double small = q * r;
        for (int axis = 0; axis < 3; ++axis)
            for (int sign = 1; sign >= -1; sign -= 2) {
                const direction d{axis, sign};
                if (has_parent && d == parent) continue;
                auto level = std::make_unique<sphere_hull>();
                const double offset = r + small;
                const double sub = fill(*level, c + offset * d.unit(), small, depth - 1, q, s, true,
                                        direction{axis, -sign});
                reach = std::fmax(reach, offset + sub);
                hull.add_child(std::move(level));
            }
    }
    hull.fix_sphere(c, reach * (1 + 1e-12));
    return reach;
}

void put_number(std::ostream& out, double x) {
    char text[64];
    const auto result = std::to_chars(text, text + sizeof text, x);
    out.write(text, result.ptr - text);
}

class fractal final : public sphere_hull {
public:
    fractal(const point& c, double r, int depth, double q) : c_(c), r_(r), depth_(depth), q_(q) { rebuild(); }

    std::string type_name() const override { return "FRACSPH"; }

    void insert(std::unique_ptr<rtab_component>) override {
        throw usage_error("FRACSPH generates its spheres itself, so insert() cannot add an object to it; "
                          "put the FRACSPH and the other object in a LIST");
    }

    void read(scene_reader& in) override {
        point c = c_;
        double r = r_, q = q_;
        int depth = depth_;
        surface s = surface_;
        std::vector<scene_reader::property> keys{
            {"center", [&] {
                 const source_location at = in.peek().where;
                 c = in.read_point("center of FRACSPH").homogenized();
                 if (!finite_point(c)) in.fail(at, "the center of FRACSPH must be a finite point");
             }},
            {"radius", [&] { r = in.read_positive("radius of FRACSPH"); }},
            {"depth", [&] { depth = in.read_int("depth of FRACSPH", 0, 7); }},
            {"ratio", [&] {
                 const source_location at = in.peek().where;
                 q = in.read_number("ratio of FRACSPH");
                 if (!(q > 0 && q < 1)) in.fail(at, "the ratio of FRACSPH must be greater than 0 and less than 1");
             }},
        };
        add_surface_properties(keys, in, s, "FRACSPH");
        in.read_block("FRACSPH", keys);
        c_ = c;
        r_ = r;
        q_ = q;
        depth_ = depth;
        surface_ = s;
        rebuild();
    }

    void write(std::ostream& out) const override {
        out << "FRACSPH { center ";
        put_number(out, c_.x);
        out << ' ';
        put_number(out, c_.y);
        out << ' ';
        put_number(out, c_.z);
        out << " radius ";
        put_number(out, r_);
        out << " depth " << depth_ << " ratio ";
        put_number(out, q_);
        write_surface(out, surface_);
        out << " }";
    }

private:
    void rebuild() {
        sphere_hull::delete_all_children();
        fill(*this, c_, r_, depth_, q_, surface_, false, direction{0, 0});
    }

    point c_;
    double r_;
    int depth_;
    double q_;
    surface surface_;
};

}  // namespace

std::unique_ptr<rtab_composite> make_frac_sphere(const point& center, double radius, int depth, double ratio) {
    const point c = center.homogenized();
    if (!finite_point(c)) throw usage_error("make_frac_sphere: the center is not a finite point");
    if (!(std::isfinite(radius) && radius > 0))
        throw usage_error("make_frac_sphere: the radius must be a finite number greater than 0");
    if (depth < 0 || depth > 7) throw usage_error("make_frac_sphere: the depth must be a whole number from 0 to 7");
    if (!(ratio > 0 && ratio < 1)) throw usage_error("make_frac_sphere: the ratio must lie between 0 and 1");
    return std::make_unique<fractal>(c, radius, depth, ratio);
}

}  // namespace vl::stage03
