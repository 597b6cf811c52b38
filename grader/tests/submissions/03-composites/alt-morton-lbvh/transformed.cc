// The transformed instance. Rays go to object space through the inverse matrix; normals
// come back through the cofactor matrix of the linear part A of object_to_world: the
// inverse transpose of A is cof(A) / det(A), and the columns of cof(A) are the cross
// products of A's columns, a2 x a3, a3 x a1, a1 x a2.
#include <cmath>
#include <ostream>

#include "stage_01.hh"
#include "stage_03.hh"
#include "vl/error.hh"
#include "vl/scene_reader.hh"
#include "vl/shape_params.hh"

namespace vl::stage03 {

namespace {

/// TRANSFORM's steps, made by stage 01.
const shapes::transform_step_makers steps{stage01::scale_matrix, stage01::rotate_matrix, stage01::translate_matrix};

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
    if (const char* why = checks::unusable_matrix(object_to_world))
        throw usage_error(std::string("make_transformed: the matrix cannot place an object: ") + why);
    return std::make_unique<transformed>(std::move(child), object_to_world);
}

}  // namespace vl::stage03
