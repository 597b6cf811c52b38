// The transformed instance (stage_03.hh): the child seen through object_to_world.
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
    if (const char* why = checks::unusable_matrix(object_to_world))
        throw usage_error(std::string("make_transformed: the matrix cannot place an object: ") + why);
    return std::make_unique<transformed>(std::move(child), object_to_world);
}

}  // namespace vl::stage03
