// The transformed instance: see stage_03.hh for what each function must do, and README.md
// for hints. Reading, writing, checking the matrix and forwarding the surface are done;
// the TODOs are yours.
#include <cmath>
#include <limits>
#include <numbers>
#include <ostream>

#include "stage_01.hh"
#include "stage_03.hh"
#include "vl/not_implemented.hh"
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

    vector normal([[maybe_unused]] const point& p) const override {
        // TODO: the child's normal at the object-space point, taken back to world space
        // with the inverse transpose (normal_matrix_), made unit. Set its w to 0 before
        // unit(): the transpose of an affine inverse gives a normal a w that means nothing.
        // NaN_vector when there is no child.
        throw not_implemented_error();
    }
    bool contains([[maybe_unused]] const point& p) const override {
        // TODO: the child's contains() of the object-space point (false without a child).
        throw not_implemented_error();
    }
    point min_point() const override {
        // TODO: the lowest corner of the box around the eight corners of the child's box,
        // each taken to world space (NaN_point without a child or when its box is unknown).
        throw not_implemented_error();
    }
    point max_point() const override {
        // TODO: the highest corner of that box.
        throw not_implemented_error();
    }

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

    intersection find_intersection([[maybe_unused]] const ray& r) const override {
        // TODO: take the ray to object space with to_object_ and intersect the child once.
        // A vl::ray makes its direction unit, so the child's t is an object-space
        // distance: divide it by the object-space length of the world direction
        // (|to_object_ * d|, d unit) to get the world distance. A hit's object is this
        // transform (only it maps points and normals back); a child's composite_only
        // comes back as composite_only(this), a miss as a miss. No child: a miss.
        throw not_implemented_error();
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
