// Reference: the transformed instance (see assignments/03-composites/stage_03.hh).
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
        // Normals go back with the inverse transpose; w is dropped, since the transpose
        // of an affine inverse gives the normal a w that means nothing.
        vector n = normal_matrix_ * children_.front()->normal(to_object_ * p);
        n.w = 0;
        return n.unit();
    }
    bool contains(const point& p) const override {
        return !children_.empty() && children_.front()->contains(to_object_ * p);
    }
    point min_point() const override { return corner(true); }
    point max_point() const override { return corner(false); }

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

    point corner(bool lowest) const {
        if (children_.empty()) return NaN_point;
        const point a = children_.front()->min_point(), b = children_.front()->max_point();
        if (is_nan(a) || is_nan(b)) return NaN_point;
        point result;
        for (int i = 0; i < 8; ++i) {
            const point p = to_world_ * point(i & 1 ? b.x : a.x, i & 2 ? b.y : a.y, i & 4 ? b.z : a.z);
            if (i == 0)
                result = p;
            else if (lowest)
                result = point(std::fmin(result.x, p.x), std::fmin(result.y, p.y), std::fmin(result.z, p.z));
            else
                result = point(std::fmax(result.x, p.x), std::fmax(result.y, p.y), std::fmax(result.z, p.z));
        }
        return result;
    }

    intersection find_intersection(const ray& r) const override {
        if (children_.empty()) return intersection::none();
        const vector d = to_object_ * r.direction();
        const double stretch = d.length();  // |M^-1 d|: object-space length of one world unit along the ray
        const intersection i = children_.front()->intersect(ray(to_object_ * r.origin(), d));
        if (i.hit()) return intersection::at(i.t / stretch, this);
        return i.is_composite_only() ? intersection::composite_only(this) : intersection::none();
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
