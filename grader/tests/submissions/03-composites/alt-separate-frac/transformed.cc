// TRANSFORM: the child in object space; its normals come back through the inverse of the
// transposed matrix (the same as the transposed inverse).
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <ostream>

#include "stage_01.hh"
#include "stage_03.hh"
#include "vl/registry.hh"
#include "vl/scene_reader.hh"

namespace vl::stage03 {

namespace {

/// An empty string when `m` can place an object, else the reason it cannot.
std::string fault(const matrix& m) {
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            if (!std::isfinite(m(i, j))) return "an element is infinite or not a number";
    if (m(3, 0) != 0 || m(3, 1) != 0 || m(3, 2) != 0 || m(3, 3) != 1) return "it is not affine (bottom row 0 0 0 1)";
    if (m.determinant() == 0) return "it is singular, it has no inverse (a scale by 0?)";
    return "";
}

class xform final : public rtab_composite {
public:
    xform(std::unique_ptr<rtab_component> child, const matrix& m) {
        use(m);
        if (child) children_.push_back(std::move(child));
    }

    std::string type_name() const override { return "TRANSFORM"; }

    void insert(std::unique_ptr<rtab_component> child) override {
        if (!children_.empty())
            throw usage_error("TRANSFORM: it has its one object already (for several, put a LIST inside it)");
        rtab_composite::insert(std::move(child));
    }

    vector normal(const point& p) const override {
        if (children_.empty()) return NaN_vector;
        const vector n = children_[0]->normal(inverse_ * p);
        vector w(0, 0, 0);
        w.x = normals_(0, 0) * n.x + normals_(0, 1) * n.y + normals_(0, 2) * n.z;
        w.y = normals_(1, 0) * n.x + normals_(1, 1) * n.y + normals_(1, 2) * n.z;
        w.z = normals_(2, 0) * n.x + normals_(2, 1) * n.y + normals_(2, 2) * n.z;
        return w.unit();
    }
    bool contains(const point& p) const override { return !children_.empty() && children_[0]->contains(inverse_ * p); }
    point min_point() const override { return extreme(true); }
    point max_point() const override { return extreme(false); }

    color clr() const override { return children_.empty() ? WHITE : children_[0]->clr(); }
    double kdr() const override { return children_.empty() ? 0 : children_[0]->kdr(); }
    double ksr() const override { return children_.empty() ? 0 : children_[0]->ksr(); }
    double kdt() const override { return children_.empty() ? 0 : children_[0]->kdt(); }
    double kst() const override { return children_.empty() ? 0 : children_[0]->kst(); }
    double n() const override { return children_.empty() ? 1 : children_[0]->n(); }
    double ior() const override { return children_.empty() ? 1 : children_[0]->ior(); }
    double zero_t() const override { return children_.empty() ? default_zero_t : children_[0]->zero_t(); }

    void read(scene_reader& in) override {
        in.expect('{', "after TRANSFORM");
        matrix m = IDENTITY;
        while (in.peek().type == token::kind::word && !registry::valid_name(in.peek().text)) {
            const token step = in.next();
            const std::string of = " of " + step.text;
            matrix s = IDENTITY;
            if (step.text == "scale" || step.text == "translate") {
                const double x = in.read_number("x" + of), y = in.read_number("y" + of), z = in.read_number("z" + of);
                s = step.text == "scale" ? stage01::scale_matrix(x, y, z) : stage01::translate_matrix(vector(x, y, z));
            } else if (step.text == "rotate") {
                const double x = in.read_number("axis x" + of), y = in.read_number("axis y" + of),
                             z = in.read_number("axis z" + of), angle = in.read_number("degrees" + of);
                if (x == 0 && y == 0 && z == 0) in.fail(step.where, "rotate: the axis is zero");
                s = stage01::rotate_matrix(vector(x, y, z), angle * std::numbers::pi / 180);
            } else if (step.text == "matrix") {
                for (int k = 0; k < 16; ++k) s(k / 4, k % 4) = in.read_number("element" + of);
            } else {
                in.fail(step.where, "unknown step '" + step.text + "' in TRANSFORM (scale, rotate, translate or matrix)");
            }
            m = s * m;
            if (const std::string why = fault(m); !why.empty())
                in.fail(step.where, "TRANSFORM: this step gives a matrix that cannot place an object: " + why);
        }
        if (in.peek().type == token::kind::punct && in.peek().text == "}")
            in.fail_expected("an object inside TRANSFORM (exactly one)");
        use(m);
        children_.clear();
        in.read_child(*this);
        if (!in.accept('}')) in.fail_expected("'}': a TRANSFORM holds exactly one object");
    }

    void write(std::ostream& out) const override {
        const auto keep = out.precision(std::numeric_limits<double>::max_digits10);
        out << "TRANSFORM { matrix";
        for (int k = 0; k < 16; ++k) out << ' ' << forward_(k / 4, k % 4);
        out.precision(keep);
        if (!children_.empty()) out << ' ' << *children_[0];
        out << " }";
    }

private:
    void use(const matrix& m) {
        forward_ = m;
        inverse_ = stage01::inverse(m);
        normals_ = stage01::inverse(m.transpose());
    }

    point extreme(bool lowest) const {
        if (children_.empty()) return NaN_point;
        const point a = children_[0]->min_point(), b = children_[0]->max_point();
        if (is_nan(a) || is_nan(b)) return NaN_point;
        double xs[8], ys[8], zs[8];
        for (int k = 0; k < 8; ++k) {
            const point w = forward_ * point(k % 2 ? b.x : a.x, (k / 2) % 2 ? b.y : a.y, k / 4 ? b.z : a.z);
            xs[k] = w.x;
            ys[k] = w.y;
            zs[k] = w.z;
        }
        if (lowest) return point(*std::min_element(xs, xs + 8), *std::min_element(ys, ys + 8), *std::min_element(zs, zs + 8));
        return point(*std::max_element(xs, xs + 8), *std::max_element(ys, ys + 8), *std::max_element(zs, zs + 8));
    }

    intersection find_intersection(const ray& r) const override {
        if (children_.empty()) return intersection::none();
        const vector local = inverse_ * r.direction();
        const intersection i = children_[0]->intersect(ray(inverse_ * r.origin(), local));
        if (i.hit()) return intersection::at(i.t / local.length(), this);
        if (i.is_composite_only()) return intersection::composite_only(this);
        return intersection::none();
    }

    matrix forward_, inverse_, normals_;
};

}  // namespace

std::unique_ptr<rtab_composite> make_transformed(std::unique_ptr<rtab_component> child, const matrix& object_to_world) {
    if (const std::string why = fault(object_to_world); !why.empty())
        throw usage_error("make_transformed: the matrix cannot place an object: " + why);
    return std::make_unique<xform>(std::move(child), object_to_world);
}

}  // namespace vl::stage03
