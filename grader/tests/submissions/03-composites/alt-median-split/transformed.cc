// The transformed instance: a child seen through an affine matrix.
#include <charconv>
#include <cmath>
#include <numbers>
#include <ostream>

#include "extent.hh"
#include "stage_01.hh"
#include "stage_03.hh"
#include "vl/registry.hh"
#include "vl/scene_reader.hh"

namespace vl::stage03 {

namespace {

/// Empty when `m` can place an object; otherwise why not.
std::string what_is_wrong(const matrix& m) {
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            if (!std::isfinite(m(i, j))) return "an element is not a finite number";
    if (!(m(3, 0) == 0 && m(3, 1) == 0 && m(3, 2) == 0 && m(3, 3) == 1))
        return "it is not affine: its last row must be 0 0 0 1";
    if (m.determinant() == 0) return "it is singular (a scale of 0?), so it has no inverse";
    return {};
}

/// The linear part (upper-left 3x3) of `m` applied to `v`.
vector linear(const matrix& m, const vector& v) {
    return vector(m(0, 0) * v.x + m(0, 1) * v.y + m(0, 2) * v.z, m(1, 0) * v.x + m(1, 1) * v.y + m(1, 2) * v.z,
                  m(2, 0) * v.x + m(2, 1) * v.y + m(2, 2) * v.z);
}

class instance final : public rtab_composite {
public:
    instance(std::unique_ptr<rtab_component> child, const matrix& m) {
        place(m);
        if (child) children_.push_back(std::move(child));
    }

    std::string type_name() const override { return "TRANSFORM"; }

    void insert(std::unique_ptr<rtab_component> child) override {
        if (!children_.empty())
            throw usage_error("TRANSFORM already holds its one object; to transform several, put a LIST inside");
        rtab_composite::insert(std::move(child));
    }

    const rtab_component* child() const { return children_.empty() ? nullptr : children_.front().get(); }

    vector normal(const point& p) const override {
        if (!child()) return NaN_vector;
        const vector n = child()->normal(to_object_ * p);
        return linear(normals_, n).unit();
    }
    bool contains(const point& p) const override { return child() && child()->contains(to_object_ * p); }

    point min_point() const override { return world_box().lo; }
    point max_point() const override { return world_box().hi; }

    color clr() const override { return child() ? child()->clr() : rtab_composite::clr(); }
    double kdr() const override { return child() ? child()->kdr() : rtab_composite::kdr(); }
    double ksr() const override { return child() ? child()->ksr() : rtab_composite::ksr(); }
    double kdt() const override { return child() ? child()->kdt() : rtab_composite::kdt(); }
    double kst() const override { return child() ? child()->kst() : rtab_composite::kst(); }
    double n() const override { return child() ? child()->n() : rtab_composite::n(); }
    double ior() const override { return child() ? child()->ior() : rtab_composite::ior(); }
    double zero_t() const override { return child() ? child()->zero_t() : rtab_composite::zero_t(); }

    void read(scene_reader& in) override {
        in.expect('{', "after TRANSFORM");
        matrix m;  // the identity
        while (in.peek().type == token::kind::word && !registry::valid_name(in.peek().text)) {
            const token step = in.next();
            matrix s;
            if (step.text == "scale") {
                double f[3];
                for (double& x : f) x = in.read_number("factor of scale");
                s = stage01::scale_matrix(f[0], f[1], f[2]);
            } else if (step.text == "translate") {
                double f[3];
                for (double& x : f) x = in.read_number("offset of translate");
                s = stage01::translate_matrix(vector(f[0], f[1], f[2]));
            } else if (step.text == "rotate") {
                double f[4];
                for (double& x : f) x = in.read_number("axis or angle of rotate");
                if (f[0] == 0 && f[1] == 0 && f[2] == 0) in.fail(step.where, "rotate needs an axis that is not zero");
                s = stage01::rotate_matrix(vector(f[0], f[1], f[2]), f[3] / 180 * std::numbers::pi);
            } else if (step.text == "matrix") {
                for (int i = 0; i < 4; ++i)
                    for (int j = 0; j < 4; ++j) s(i, j) = in.read_number("element of matrix");
            } else {
                in.fail(step.where, "TRANSFORM knows the steps scale, rotate, translate and matrix, not '" +
                                        step.text + "'");
            }
            m = s * m;
            const std::string wrong = what_is_wrong(m);
            if (!wrong.empty()) in.fail(step.where, "after this step TRANSFORM cannot use its matrix: " + wrong);
        }
        if (in.peek().type != token::kind::word)
            in.fail_expected("the one object of TRANSFORM (for example SPHERE { })");
        place(m);
        children_.clear();
        in.read_child(*this);
        if (!in.accept('}')) in.fail_expected("'}': a TRANSFORM holds exactly one object");
    }

    void write(std::ostream& out) const override {
        out << "TRANSFORM { matrix";
        char text[64];
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j) {
                const auto result = std::to_chars(text, text + sizeof text, to_world_(i, j));
                out << ' ';
                out.write(text, result.ptr - text);
            }
        if (child()) out << ' ' << *child();
        out << " }";
    }

private:
    void place(const matrix& m) {
        to_world_ = m;
        to_object_ = stage01::inverse(m);
        normals_ = to_object_.transpose();
    }

    extent world_box() const {
        extent e;
        if (!child()) return {NaN_point, NaN_point};
        const point a = child()->min_point(), b = child()->max_point();
        if (!finite_point(a) || !finite_point(b)) return {NaN_point, NaN_point};
        for (double x : {a.x, b.x})
            for (double y : {a.y, b.y})
                for (double z : {a.z, b.z}) e.add((to_world_ * point(x, y, z)).homogenized());
        return e;
    }

    intersection find_intersection(const ray& r) const override {
        if (!child()) return intersection::none();
        const vector d = to_object_ * r.direction();
        const double length = d.length();
        const intersection i = child()->intersect(ray(to_object_ * r.origin(), d));
        if (i.hit()) return intersection::at(i.t / length, this);
        if (i.is_composite_only()) return intersection::composite_only(this);
        return intersection::none();
    }

    matrix to_world_, to_object_, normals_;
};

}  // namespace

std::unique_ptr<rtab_composite> make_transformed(std::unique_ptr<rtab_component> child, const matrix& object_to_world) {
    const std::string wrong = what_is_wrong(object_to_world);
    if (!wrong.empty()) throw usage_error("make_transformed: this matrix cannot place an object: " + wrong);
    return std::make_unique<instance>(std::move(child), object_to_world);
}

}  // namespace vl::stage03
