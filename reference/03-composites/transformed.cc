// Reference: the transformed instance (see assignments/03-composites/stage_03.hh).
#include <cmath>
#include <ostream>

#include "stage_01.hh"
#include "stage_03.hh"
#include "vl/scene_reader.hh"
#include "vl/shape_params.hh"

namespace vl::stage03 {

namespace {

/// TRANSFORM's steps, made by stage 01.
const shapes::transform_step_makers steps{stage01::scale_matrix, stage01::rotate_matrix, stage01::translate_matrix};

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
            const matrix step = shapes::read_transform_step(in, t, steps);
            m = step * m;  // each step acts after the ones before it
            if (const char* why = checks::unusable_matrix(m))
                in.fail(t.where, std::string("TRANSFORM cannot use this matrix: ") + why);
        }
        if (in.peek().type == token::kind::punct && in.peek().text == "}")
            in.fail_expected("the object of TRANSFORM (such as SPHERE { }) before '}'");
        set_matrix(m);
        children_.clear();
        in.read_child(*this);
        if (!in.accept('}')) in.fail_expected("'}' to close TRANSFORM (it holds exactly one object)");
    }

    void write(std::ostream& s) const override {
        shapes::write_transform_matrix(s, to_world_);
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
    if (const char* why = checks::unusable_matrix(object_to_world))
        throw usage_error(std::string("make_transformed: the matrix cannot place an object: ") + why);
    return std::make_unique<transformed>(std::move(child), object_to_world);
}

}  // namespace vl::stage03
