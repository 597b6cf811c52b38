// The transformed instance: see stage_03.hh for what each function must do, and README.md
// for hints. Reading, writing, checking the matrix and forwarding the surface are done;
// the TODOs are yours.
#include <cmath>
#include <ostream>

#include "stage_01.hh"
#include "stage_03.hh"
#include "vl/not_implemented.hh"
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
    if (const char* why = checks::unusable_matrix(object_to_world))
        throw usage_error(std::string("make_transformed: the matrix cannot place an object: ") + why);
    return std::make_unique<transformed>(std::move(child), object_to_world);
}

}  // namespace vl::stage03
