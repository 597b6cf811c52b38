// The transformed instance (stage_03.hh): the child seen through object_to_world.
#include <cmath>
#include <limits>
#include <numbers>
#include <ostream>

#include "stage_01.hh"
#include "stage_03.hh"
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

/// \brief One child seen through a matrix: rays go to the child's space, hits come back.
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
        const vector world = normal_matrix_ * vector(n.x, n.y, n.z, 0);
        return vector(world.x, world.y, world.z, 0).unit();
    }
    bool contains(const point& p) const override {
        if (children_.empty()) return false;
        return children_.front()->contains(to_object_ * p);
    }
    /// The child's box as a centre and half-extents: the world box is centred at M c and
    /// reaches |A| h in each axis (A the linear part of M, |A| element by element).
    point min_point() const override { return world_box(-1); }
    point max_point() const override { return world_box(1); }

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
        normal_matrix_ = to_object_.transpose();
    }

    point world_box(double side) const {
        if (children_.empty()) return NaN_point;
        const point a = children_.front()->min_point(), b = children_.front()->max_point();
        if (is_nan(a) || is_nan(b)) return NaN_point;
        const point c = to_world_ * point((a.x + b.x) / 2, (a.y + b.y) / 2, (a.z + b.z) / 2);
        const double h[3] = {(b.x - a.x) / 2, (b.y - a.y) / 2, (b.z - a.z) / 2};
        double reach[3];
        for (int i = 0; i < 3; ++i)
            reach[i] = std::fabs(to_world_(i, 0)) * h[0] + std::fabs(to_world_(i, 1)) * h[1] +
                       std::fabs(to_world_(i, 2)) * h[2];
        return point(c.x + side * reach[0], c.y + side * reach[1], c.z + side * reach[2]);
    }

    intersection find_intersection(const ray& r) const override {
        if (children_.empty()) return intersection::none();
        const point o = to_object_ * r.origin();
        const vector d = to_object_ * r.direction();
        const intersection i = children_.front()->intersect(ray(o, d));
        if (i.is_miss()) return i;
        if (!i.hit()) return intersection::composite_only(this);
        return intersection::at(i.t / d.length(), this);
    }

    matrix to_world_, to_object_, normal_matrix_;
};

}  // namespace

std::unique_ptr<rtab_composite> make_transformed(std::unique_ptr<rtab_component> child, const matrix& object_to_world) {
    if (const char* why = unusable(object_to_world))
        throw usage_error(std::string("make_transformed: the matrix cannot place an object: ") + why);
    return std::make_unique<transformed>(std::move(child), object_to_world);
}

}  // namespace vl::stage03
