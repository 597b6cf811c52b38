// TRANSFORM: a child placed by a matrix. Normals go to world space with the cofactor
// matrix of the linear part (the inverse transpose times the determinant).
#include <cmath>
#include <numbers>
#include <ostream>

#include "geom3.hh"
#include "stage_01.hh"
#include "stage_03.hh"
#include "vl/registry.hh"
#include "vl/scene_reader.hh"

namespace vl::stage03 {

namespace {

bool placeable(const matrix& m, std::string& why) {
    for (int i = 0; i < 16; ++i)
        if (!std::isfinite(m(i / 4, i % 4))) {
            why = "not every element is finite";
            return false;
        }
    if (m(3, 0) != 0 || m(3, 1) != 0 || m(3, 2) != 0 || m(3, 3) != 1) {
        why = "the bottom row is not 0 0 0 1 (not affine)";
        return false;
    }
    if (m.determinant() == 0) {
        why = "it is singular (no inverse; is a factor of scale 0?)";
        return false;
    }
    return true;
}

class placed final : public rtab_composite {
public:
    placed(std::unique_ptr<rtab_component> child, const matrix& m) {
        set(m);
        if (child) children_.push_back(std::move(child));
    }

    std::string type_name() const override { return "TRANSFORM"; }

    void insert(std::unique_ptr<rtab_component> child) override {
        if (num_children() == 1)
            throw usage_error("TRANSFORM takes exactly one object and has one; put a LIST inside for several");
        rtab_composite::insert(std::move(child));
    }

    vector normal(const point& p) const override {
        if (children_.empty()) return NaN_vector;
        const vector n = children_[0]->normal(to_object_ * p);
        return vector(cof_[0][0] * n.x + cof_[0][1] * n.y + cof_[0][2] * n.z,
                      cof_[1][0] * n.x + cof_[1][1] * n.y + cof_[1][2] * n.z,
                      cof_[2][0] * n.x + cof_[2][1] * n.y + cof_[2][2] * n.z)
            .unit();
    }
    bool contains(const point& p) const override {
        return !children_.empty() && children_[0]->contains(to_object_ * p);
    }
    point min_point() const override { return bound(false); }
    point max_point() const override { return bound(true); }

    color clr() const override { return children_.empty() ? WHITE : children_[0]->clr(); }
    double kdr() const override { return children_.empty() ? 0.0 : children_[0]->kdr(); }
    double ksr() const override { return children_.empty() ? 0.0 : children_[0]->ksr(); }
    double kdt() const override { return children_.empty() ? 0.0 : children_[0]->kdt(); }
    double kst() const override { return children_.empty() ? 0.0 : children_[0]->kst(); }
    double n() const override { return children_.empty() ? 1.0 : children_[0]->n(); }
    double ior() const override { return children_.empty() ? 1.0 : children_[0]->ior(); }
    double zero_t() const override { return children_.empty() ? default_zero_t : children_[0]->zero_t(); }

    void read(scene_reader& in) override {
        in.expect('{', "after TRANSFORM");
        matrix m = IDENTITY;
        for (;;) {
            const token& t = in.peek();
            if (t.type != token::kind::word || registry::valid_name(t.text)) break;
            const token step = in.next();
            matrix s = IDENTITY;
            auto num = [&](const char* what) { return in.read_number(std::string(what) + " of " + step.text); };
            if (step.text == "scale") {
                const double x = num("x"), y = num("y"), z = num("z");
                s = stage01::scale_matrix(x, y, z);
            } else if (step.text == "translate") {
                const double x = num("x"), y = num("y"), z = num("z");
                s = stage01::translate_matrix(vector(x, y, z));
            } else if (step.text == "rotate") {
                const double x = num("axis x"), y = num("axis y"), z = num("axis z"), degrees = num("degrees");
                if (x == 0 && y == 0 && z == 0) in.fail(step.where, "rotate: the axis must not be the zero vector");
                s = stage01::rotate_matrix(vector(x, y, z), degrees * (std::numbers::pi / 180));
            } else if (step.text == "matrix") {
                double e[16];
                for (double& x : e) x = num("element");
                s = matrix(e[0], e[1], e[2], e[3], e[4], e[5], e[6], e[7], e[8], e[9], e[10], e[11], e[12], e[13],
                           e[14], e[15]);
            } else {
                in.fail(step.where, "TRANSFORM: '" + step.text +
                                        "' is not a step (scale, rotate, translate, matrix) nor an object");
            }
            m = s * m;
            std::string why;
            if (!placeable(m, why)) in.fail(step.where, "TRANSFORM: the matrix cannot place an object: " + why);
        }
        if (in.peek().type == token::kind::punct && in.peek().text == "}")
            in.fail_expected("the object of TRANSFORM before '}'");
        set(m);
        children_.clear();
        in.read_child(*this);
        if (!in.accept('}')) in.fail_expected("'}' after the one object of TRANSFORM");
    }

    void write(std::ostream& out) const override {
        out << "TRANSFORM {\n  matrix";
        for (int i = 0; i < 4; ++i) {
            out << "\n   ";
            for (int j = 0; j < 4; ++j) {
                out << ' ';
                geom3::number(out, to_world_(i, j));
            }
        }
        for (const auto& c : children_) out << "\n  " << *c;
        out << "\n}";
    }

private:
    void set(const matrix& m) {
        to_world_ = m;
        to_object_ = stage01::inverse(m);
        // The cofactors of the 3x3 linear part A: cof(A) = det(A) (A^-1)^T. With the sign
        // of det(A) it turns a normal the same way as the inverse transpose (a mirror
        // would otherwise flip it).
        auto a = [&](int i, int j) { return m(i % 3, j % 3); };
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                cof_[i][j] = a(i + 1, j + 1) * a(i + 2, j + 2) - a(i + 1, j + 2) * a(i + 2, j + 1);
        const double det = m(0, 0) * cof_[0][0] + m(0, 1) * cof_[0][1] + m(0, 2) * cof_[0][2];
        if (det < 0)
            for (auto& row : cof_)
                for (double& x : row) x = -x;
    }

    point bound(bool upper) const {
        if (children_.empty()) return NaN_point;
        const geom3::triple a = geom3::xyz(children_[0]->min_point()), b = geom3::xyz(children_[0]->max_point());
        if (!geom3::all_finite(a) || !geom3::all_finite(b)) return NaN_point;
        geom3::triple result{};
        for (int corner = 0; corner < 8; ++corner) {
            const point p = to_world_ * point(corner & 4 ? b[0] : a[0], corner & 2 ? b[1] : a[1], corner & 1 ? b[2] : a[2]);
            const geom3::triple w = geom3::xyz(p);
            for (int k = 0; k < 3; ++k)
                if (corner == 0 || (upper ? w[k] > result[k] : w[k] < result[k])) result[k] = w[k];
        }
        return geom3::as_point(result);
    }

    intersection find_intersection(const ray& r) const override {
        if (children_.empty()) return intersection::none();
        const ray local(to_object_ * r.origin(), to_object_ * r.direction());
        const intersection i = children_[0]->intersect(local);
        if (i.is_miss()) return intersection::none();
        if (!i.hit()) return intersection::composite_only(this);
        // Back to world space: the hit point, then its distance along the world ray.
        const point world = to_world_ * local.t_point(i.t);
        const double t = (world - r.origin()) * r.direction();
        return t > 0 ? intersection::at(t, this) : intersection::composite_only(this);
    }

    matrix to_world_, to_object_;
    double cof_[3][3] = {};
};

}  // namespace

std::unique_ptr<rtab_composite> make_transformed(std::unique_ptr<rtab_component> child, const matrix& object_to_world) {
    std::string why;
    if (!placeable(object_to_world, why)) throw usage_error("make_transformed: the matrix cannot place an object: " + why);
    return std::make_unique<placed>(std::move(child), object_to_world);
}

}  // namespace vl::stage03
