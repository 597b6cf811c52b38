// TRANSFORM: rays into the child's space with M^-1, hits and normals back.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <ostream>

#include "stage_01.hh"
#include "stage_03.hh"
#include "vl/registry.hh"
#include "vl/scene_reader.hh"

namespace vl::stage03 {

namespace {

std::string g17(double x) {
    char text[40];
    std::snprintf(text, sizeof text, "%.17g", x);
    return text;
}

/// Throws vl::usage_error saying why `m` cannot place an object (prefixed by `who`).
void check_placement(const matrix& m, const std::string& who) {
    bool finite = true;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) finite = finite && std::isfinite(m(r, c));
    if (!finite) throw usage_error(who + "the matrix has an element that is not finite");
    if (m.row(3) != vector(0, 0, 0, 1)) throw usage_error(who + "the matrix is not affine (bottom row not 0 0 0 1)");
    if (m.determinant() == 0) throw usage_error(who + "the matrix is singular (has no inverse: a zero scale?)");
}

class transformed final : public rtab_composite {
public:
    transformed(std::unique_ptr<rtab_component> child, const matrix& m) : forward_(m), backward_(stage01::inverse(m)) {
        if (child) children_.push_back(std::move(child));
    }

    std::string type_name() const override { return "TRANSFORM"; }

    void insert(std::unique_ptr<rtab_component> child) override {
        if (!children_.empty())
            throw usage_error("TRANSFORM: it already holds its object; a TRANSFORM holds one (put a LIST inside)");
        rtab_composite::insert(std::move(child));
    }

    vector normal(const point& p) const override {
        if (children_.empty()) return NaN_vector;
        const vector n = children_.front()->normal(backward_ * p);
        // (M^-1)^T n: component i is column i of M^-1 dotted with n.
        vector w(0, 0, 0);
        w.x = backward_(0, 0) * n.x + backward_(1, 0) * n.y + backward_(2, 0) * n.z;
        w.y = backward_(0, 1) * n.x + backward_(1, 1) * n.y + backward_(2, 1) * n.z;
        w.z = backward_(0, 2) * n.x + backward_(1, 2) * n.y + backward_(2, 2) * n.z;
        return w.unit();
    }
    bool contains(const point& p) const override {
        return !children_.empty() && children_.front()->contains(backward_ * p);
    }

    /// Arvo's method: each world coordinate of the box is the translation plus, for every
    /// object axis, the smaller (or larger) of the two corners' contributions.
    point min_point() const override { return world_corner(false); }
    point max_point() const override { return world_corner(true); }

    color clr() const override { return children_.empty() ? rtab_component::clr() : children_.front()->clr(); }
    double kdr() const override { return children_.empty() ? rtab_component::kdr() : children_.front()->kdr(); }
    double ksr() const override { return children_.empty() ? rtab_component::ksr() : children_.front()->ksr(); }
    double kdt() const override { return children_.empty() ? rtab_component::kdt() : children_.front()->kdt(); }
    double kst() const override { return children_.empty() ? rtab_component::kst() : children_.front()->kst(); }
    double n() const override { return children_.empty() ? rtab_component::n() : children_.front()->n(); }
    double ior() const override { return children_.empty() ? rtab_component::ior() : children_.front()->ior(); }
    double zero_t() const override { return children_.empty() ? rtab_component::zero_t() : children_.front()->zero_t(); }

    void read(scene_reader& in) override {
        in.expect('{', "after TRANSFORM");
        matrix m = IDENTITY;
        while (in.peek().type == token::kind::word && !registry::valid_name(in.peek().text)) {
            const token step = in.next();
            auto three = [&](const char* what) {
                const double x = in.read_number(what), y = in.read_number(what), z = in.read_number(what);
                return vector(x, y, z);
            };
            matrix s;
            if (step.text == "scale") {
                const vector f = three("factor of scale");
                s = stage01::scale_matrix(f.x, f.y, f.z);
            } else if (step.text == "rotate") {
                const vector axis = three("axis of rotate");
                const double degrees = in.read_number("degrees of rotate");
                if (axis.length() == 0) in.fail(step.where, "the axis of rotate is the zero vector");
                s = stage01::rotate_matrix(axis, degrees * std::numbers::pi / 180);
            } else if (step.text == "translate") {
                s = stage01::translate_matrix(three("offset of translate"));
            } else if (step.text == "matrix") {
                for (int r = 0; r < 4; ++r)
                    for (int c = 0; c < 4; ++c) s(r, c) = in.read_number("element of matrix");
            } else {
                in.fail(step.where, "'" + step.text + "' is not a step of TRANSFORM (scale, rotate, translate, matrix)");
            }
            m = s * m;
            try {
                check_placement(m, "TRANSFORM: ");
            } catch (const usage_error& e) {
                in.fail(step.where, e.what());
            }
        }
        if (in.peek().type != token::kind::word) in.fail_expected("the one object inside TRANSFORM");
        forward_ = m;
        backward_ = stage01::inverse(m);
        children_.clear();
        in.read_child(*this);
        if (!in.accept('}')) in.fail_expected("'}' (a TRANSFORM holds exactly one object)");
    }

    void write(std::ostream& out) const override {
        out << "TRANSFORM { matrix";
        for (int r = 0; r < 4; ++r)
            for (int c = 0; c < 4; ++c) out << ' ' << g17(forward_(r, c));
        if (!children_.empty()) out << ' ' << *children_.front();
        out << " }";
    }

private:
    point world_corner(bool upper) const {
        if (children_.empty()) return NaN_point;
        const point a = children_.front()->min_point(), b = children_.front()->max_point();
        if (is_nan(a) || is_nan(b)) return NaN_point;
        const double lo[3] = {a.x, a.y, a.z}, hi[3] = {b.x, b.y, b.z};
        double out[3];
        for (int i = 0; i < 3; ++i) {
            out[i] = forward_(i, 3);
            for (int j = 0; j < 3; ++j) {
                const double p = forward_(i, j) * lo[j], q = forward_(i, j) * hi[j];
                out[i] += upper ? std::max(p, q) : std::min(p, q);
            }
        }
        return point(out[0], out[1], out[2]);
    }

    intersection find_intersection(const ray& r) const override {
        if (children_.empty()) return intersection::none();
        const vector d = backward_ * r.direction();
        const intersection i = children_.front()->intersect(ray(backward_ * r.origin(), d));
        if (i.hit()) return intersection::at(i.t / d.length(), this);
        return i.is_miss() ? intersection::none() : intersection::composite_only(this);
    }

    matrix forward_, backward_;
};

}  // namespace

std::unique_ptr<rtab_composite> make_transformed(std::unique_ptr<rtab_component> child, const matrix& object_to_world) {
    check_placement(object_to_world, "make_transformed: ");
    return std::make_unique<transformed>(std::move(child), object_to_world);
}

}  // namespace vl::stage03
