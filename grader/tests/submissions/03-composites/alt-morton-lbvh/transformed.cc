// The transformed instance. Rays go to object space through the inverse matrix; normals
// come back through the cofactor matrix of the linear part A of object_to_world: the
// inverse transpose of A is cof(A) / det(A), and the columns of cof(A) are the cross
// products of A's columns, a2 x a3, a3 x a1, a1 x a2.
#include <cmath>
#include <limits>
#include <numbers>
#include <ostream>

#include "stage_01.hh"
#include "stage_03.hh"
#include "vl/error.hh"
#include "vl/scene_reader.hh"

namespace vl::stage03 {

namespace {

/// Why `m` cannot place an object, or nullptr when it can.
const char* unusable(const matrix& m) {
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c)
            if (!std::isfinite(m(r, c))) return "it has an element that is not finite";
    if (m(3, 0) != 0 || m(3, 1) != 0 || m(3, 2) != 0 || m(3, 3) != 1)
        return "it is not affine (its bottom row must be 0 0 0 1)";
    if (m.determinant() == 0) return "it is singular (it has no inverse: is a scale 0?)";
    return nullptr;
}

bool finite(const point& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

class transformed final : public rtab_composite {
public:
    transformed(std::unique_ptr<rtab_component> child, const matrix& object_to_world) {
        set_matrix(object_to_world);
        if (child) children_.push_back(std::move(child));
    }

    std::string type_name() const override { return "TRANSFORM"; }

    void insert(std::unique_ptr<rtab_component> child) override {
        if (!children_.empty())
            throw usage_error("TRANSFORM holds one object and has it already (put a LIST inside for several)");
        rtab_composite::insert(std::move(child));
    }

    vector normal(const point& p) const override {
        if (children_.empty()) return NaN_vector;
        const vector n = children_.front()->normal(to_object_ * p);
        // (A^-1)^T n = (n.x (a2 x a3) + n.y (a3 x a1) + n.z (a1 x a2)) / det A; w stays 0.
        vector world = (n.x * cofactor_[0] + n.y * cofactor_[1] + n.z * cofactor_[2]) / det_;
        world.w = 0;
        return world.unit();
    }
    bool contains(const point& p) const override {
        return !children_.empty() && children_.front()->contains(to_object_ * p);
    }
    point min_point() const override { return world_corner(false); }
    point max_point() const override { return world_corner(true); }

    color clr() const override { return children_.empty() ? WHITE : children_.front()->clr(); }
    double kdr() const override { return children_.empty() ? 0 : children_.front()->kdr(); }
    double ksr() const override { return children_.empty() ? 0 : children_.front()->ksr(); }
    double kdt() const override { return children_.empty() ? 0 : children_.front()->kdt(); }
    double kst() const override { return children_.empty() ? 0 : children_.front()->kst(); }
    double n() const override { return children_.empty() ? 1 : children_.front()->n(); }
    double ior() const override { return children_.empty() ? 1 : children_.front()->ior(); }
    double zero_t() const override { return children_.empty() ? default_zero_t : children_.front()->zero_t(); }

    void read(scene_reader& in) override {
        in.expect('{', "after TRANSFORM");
        matrix m = IDENTITY;
        for (;;) {
            const token t = in.peek();
            if (t.type != token::kind::word || registry::valid_name(t.text)) break;
            in.next();
            matrix step;
            if (t.text == "scale") {
                const double x = in.read_number("x of scale");
                const double y = in.read_number("y of scale");
                const double z = in.read_number("z of scale");
                step = stage01::scale_matrix(x, y, z);
            } else if (t.text == "rotate") {
                const double x = in.read_number("x of the axis of rotate");
                const double y = in.read_number("y of the axis of rotate");
                const double z = in.read_number("z of the axis of rotate");
                const vector axis(x, y, z);
                if (axis.x == 0 && axis.y == 0 && axis.z == 0) in.fail(t.where, "the axis of rotate must not be zero");
                step = stage01::rotate_matrix(axis, in.read_number("degrees of rotate") * std::numbers::pi / 180);
            } else if (t.text == "translate") {
                const double x = in.read_number("x of translate");
                const double y = in.read_number("y of translate");
                const double z = in.read_number("z of translate");
                step = stage01::translate_matrix(vector(x, y, z));
            } else if (t.text == "matrix") {
                double e[16];
                for (double& x : e) x = in.read_number("element of matrix");
                step = matrix(e[0], e[1], e[2], e[3], e[4], e[5], e[6], e[7], e[8], e[9], e[10], e[11], e[12], e[13],
                              e[14], e[15]);
            } else {
                in.fail(t.where, "expected scale, rotate, translate, matrix or an object in TRANSFORM, found '" +
                                     t.text + "'");
            }
            m = step * m;  // each step acts after the ones before it
            if (const char* why = unusable(m)) in.fail(t.where, std::string("TRANSFORM cannot use this matrix: ") + why);
        }
        if (in.peek().type == token::kind::punct && in.peek().text == "}")
            in.fail_expected("the object of TRANSFORM (such as SPHERE { }) before '}'");
        set_matrix(m);
        children_.clear();
        in.read_child(*this);
        if (!in.accept('}')) in.fail_expected("'}' to close TRANSFORM (it holds exactly one object)");
    }

    void write(std::ostream& s) const override {
        const auto old_precision = s.precision(std::numeric_limits<double>::max_digits10);
        s << "TRANSFORM { matrix";
        for (int r = 0; r < 4; ++r)
            for (int c = 0; c < 4; ++c) s << ' ' << to_world_(r, c);
        s.precision(old_precision);
        for (const auto& c : children_) s << ' ' << *c;
        s << " }";
    }

private:
    void set_matrix(const matrix& m) {
        to_world_ = m;
        to_object_ = stage01::inverse(m);
        const vector a1(m(0, 0), m(1, 0), m(2, 0)), a2(m(0, 1), m(1, 1), m(2, 1)), a3(m(0, 2), m(1, 2), m(2, 2));
        cofactor_[0] = a2 % a3;
        cofactor_[1] = a3 % a1;
        cofactor_[2] = a1 % a2;
        det_ = a1 * cofactor_[0];
    }

    /// The low (`high` false) or high corner of the world box around the child's box.
    point world_corner(bool high) const {
        if (children_.empty()) return NaN_point;
        const point lo = children_.front()->min_point(), hi = children_.front()->max_point();
        if (!finite(lo) || !finite(hi)) return NaN_point;
        double out[3] = {0, 0, 0};
        for (unsigned bits = 0; bits < 8; ++bits) {
            const point c = to_world_ * point((bits & 1u) ? hi.x : lo.x, (bits & 2u) ? hi.y : lo.y,
                                              (bits & 4u) ? hi.z : lo.z);
            const double xyz[3] = {c.x, c.y, c.z};
            for (int a = 0; a < 3; ++a)
                if (bits == 0 || (high ? xyz[a] > out[a] : xyz[a] < out[a])) out[a] = xyz[a];
        }
        return point(out[0], out[1], out[2]);
    }

    intersection find_intersection(const ray& r) const override {
        if (children_.empty()) return intersection::none();
        const vector d = to_object_ * r.direction();
        const double stretch = d.length();  // |M^-1 d| for the unit world direction d
        const intersection i = children_.front()->intersect(ray(to_object_ * r.origin(), d));
        if (i.hit()) return intersection::at(i.t / stretch, this);
        if (i.is_composite_only()) return intersection::composite_only(this);
        return intersection::none();
    }

    matrix to_world_, to_object_;
    vector cofactor_[3];  // the columns of cof(A), A the linear part of to_world_
    double det_ = 1;      // det A
};

}  // namespace

std::unique_ptr<rtab_composite> make_transformed(std::unique_ptr<rtab_component> child, const matrix& object_to_world) {
    if (const char* why = unusable(object_to_world))
        throw usage_error(std::string("make_transformed: the matrix cannot place an object: ") + why);
    return std::make_unique<transformed>(std::move(child), object_to_world);
}

}  // namespace vl::stage03
