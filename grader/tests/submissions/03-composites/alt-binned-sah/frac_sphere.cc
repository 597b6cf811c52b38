// FRACSPH: every level a bounding sphere with the tight radius of its own chains.
#include <cmath>
#include <ostream>
#include <string>

#include "bsphere.hh"
#include "stage_02.hh"
#include "vl/primitive.hh"
#include "vl/scene_reader.hh"

namespace vl::stage03 {

namespace {

/// How far the spheres of a fractal of radius r, ratio q and depth d reach from its centre:
/// r (1 + 2q + 2q^2 + ... + 2q^d) = r (1 + 2q (1 - q^d) / (1 - q)).
double reach(double r, double q, int d) { return r * (1 + 2 * q * (1 - std::pow(q, d)) / (1 - q)); }

class frac_level final : public bsphere {
public:
    /// `back` is the axis direction (0 .. 5: +x, +y, +z, -x, -y, -z) towards the parent, -1 at the top.
    frac_level(const point& c, double r, int d, double q, const surface& s, int back)
        : c_(c), r_(r), d_(d), q_(q), s_(s), back_(back) {
        generate();
    }

    std::string type_name() const override { return "FRACSPH"; }

    void insert(std::unique_ptr<rtab_component>) override {
        throw usage_error("FRACSPH: insert() is refused, a fractal sphere makes its own children "
                          "(put the FRACSPH and the other object in a LIST)");
    }

    void read(scene_reader& in) override {
        point c = c_;
        double r = r_, q = q_;
        int d = d_;
        std::vector<scene_reader::property> keys;
        keys.push_back({"center", [&] {
                            const source_location where = in.peek().where;
                            const point p = in.read_point("center of FRACSPH").homogenized();
                            if (!geom3::all_finite(geom3::xyz(p))) in.fail(where, "FRACSPH: center must be finite");
                            c = p;
                        }});
        keys.push_back({"radius", [&] { r = in.read_positive("radius of FRACSPH"); }});
        keys.push_back({"depth", [&] { d = in.read_int("depth of FRACSPH", 0, 7); }});
        keys.push_back({"ratio", [&] {
                            const source_location where = in.peek().where;
                            const double x = in.read_number("ratio of FRACSPH");
                            if (!(0 < x && x < 1)) in.fail(where, "FRACSPH: ratio must be in (0, 1)");
                            q = x;
                        }});
        add_surface_properties(keys, in, s_, "FRACSPH");
        in.read_block("FRACSPH", keys);
        c_ = c;
        r_ = r;
        d_ = d;
        q_ = q;
        generate();
    }

    void write(std::ostream& out) const override {
        out << "FRACSPH {\n  center ";
        geom3::number(out, c_.x);
        out << ' ';
        geom3::number(out, c_.y);
        out << ' ';
        geom3::number(out, c_.z);
        out << "\n  radius ";
        geom3::number(out, r_);
        out << "\n  depth " << d_ << "\n  ratio ";
        geom3::number(out, q_);
        out << "\n ";
        write_surface(out, s_);
        out << "\n}";
    }

private:
    void generate() {
        bsphere::delete_all_children();
        auto ball = stage02::make_sphere(c_, r_);
        ball->set_surface(s_);
        append(std::move(ball));
        if (d_ > 0) {
            const double rq = r_ * q_;
            for (int k = 0; k < 6; ++k) {
                if (k == back_) continue;
                const double sign = k < 3 ? 1 : -1;
                const vector u(k % 3 == 0 ? sign : 0, k % 3 == 1 ? sign : 0, k % 3 == 2 ? sign : 0);
                append(std::make_unique<frac_level>(c_ + (r_ + rq) * u, rq, d_ - 1, q_, s_, (k + 3) % 6));
            }
        }
        // A hair more than the exact reach, so rounding never cuts off the tip of a chain.
        set_bound(c_, reach(r_, q_, d_) * (1 + 1e-12));
    }

    point c_;
    double r_;
    int d_;
    double q_;
    surface s_;
    int back_;
};

}  // namespace

std::unique_ptr<rtab_composite> make_frac_sphere(const point& center, double radius, int depth, double ratio) {
    const point c = center.homogenized();
    if (!geom3::all_finite(geom3::xyz(c))) throw usage_error("make_frac_sphere: center must be a finite point");
    if (!std::isfinite(radius) || radius <= 0) throw usage_error("make_frac_sphere: radius must be finite and > 0");
    if (depth < 0 || depth > 7) throw usage_error("make_frac_sphere: depth must be from 0 to 7");
    if (!(ratio > 0) || !(ratio < 1)) throw usage_error("make_frac_sphere: ratio must be in (0, 1)");
    return std::make_unique<frac_level>(c, radius, depth, ratio, surface{}, -1);
}

}  // namespace vl::stage03
