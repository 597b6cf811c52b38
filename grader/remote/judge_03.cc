// The judge's stage 03: the contract's factories (stage_03.hh) as calls to the subject,
// and stand-ins for the composites they make. A stand-in is the framework's shell of its
// composite (vl::shapes::bvh_base, ...), so reading a scene file is the framework's own
// code, here; what the student wrote (the ray test, the bound, the tree, insert()) is the
// subject's object's. What a test puts into a composite is lent to it: its tests are
// counted here, by the judge (judge_components.hh). The shapes of stage 02 that the
// student's code makes in the subject are made here too, with the reference's factories.
#include <cmath>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "calls_03.hh"
#include "judge_components.hh"
#include "stage_01.hh"
#include "stage_02.hh"
#include "stage_03.hh"
#include "vl/composite_bases.hh"

namespace vl::stage03 {

namespace {

using namespace vl::remote;
namespace c = calls_03;
namespace cc = calls_components;


/// Reads `text` (one object in the scene format) with the student's types: the object
/// a scene file gave the judge's stand-in, made again in the subject.
handle read_in_subject(const std::string& text) {
    return made_in_subject(c::read_object, message_writer().put_string(text), "the object read from a scene file");
}

/// `child`, which a refused call took, goes as it would have gone with the call.
void lost(std::unique_ptr<rtab_component>& child) {
    if (!child) return;
    if (auto* r = dynamic_cast<remote_identity*>(child.get()))
        r->given_away();  // the subject's factory took its object, and it went
    else
        unlend(child.get());
    child.reset();
}

// --- the shells: the framework's part of each composite, with no algorithm --------------

class bounding_sphere_shell : public shapes::bounding_sphere_base {
protected:
    void adopt(std::unique_ptr<rtab_component>) override {}  // insert() is the subject's
};

class frac_level_shell : public shapes::bounding_sphere_base {
protected:
    void adopt(std::unique_ptr<rtab_component>) override {}
};

/// \brief A FRACSPH: a scene file's values are made again in the subject, from the text
/// the shell writes of them (the student's read() gives its spheres the surface).
class remote_frac_sphere final : public remote_composite<shapes::frac_sphere_base<frac_level_shell>> {
public:
    void set_values(const point& center, double radius, int depth, double ratio) {
        center_ = center.homogenized();
        radius_ = radius;
        depth_ = depth;
        ratio_ = ratio;
    }

private:
    void build() override {
        std::ostringstream text;
        frac_sphere_base::write(text);
        remake(read_in_subject(text.str()));
    }
};

/// \brief A BOX: corners and surface from a scene file are made again in the subject.
class remote_box final : public remote_composite<shapes::box_base> {
public:
    void set_corners(const point& lo, const point& hi) {
        lo_ = lo.homogenized();
        hi_ = hi.homogenized();
    }
    void read(scene_reader& in) override {
        retire_children();  // the shell clears children_; the subject's old BOX still holds its faces
        box_base::read(in);
    }

private:
    void make_faces() override {
        std::ostringstream text;
        box_base::write(text);
        remake(read_in_subject(text.str()));
    }
};

class transformed_shell : public shapes::transformed_base {
public:
    using transformed_base::set_up;
};

/// \brief A TRANSFORM: a scene file's steps give a new matrix, and the subject's object is
/// made again with it before the child crosses.
class remote_transformed final : public remote_composite<transformed_shell> {
public:
    /// The matrix as the subject's object has it.
    void made_with(const matrix& m) { sent_ = m; }
    void read(scene_reader& in) override {
        retire_children();
        again_ = true;
        transformed_base::read(in);
    }

private:
    void update() const override {
        if (!again_ && same(sent_, to_world_)) return;
        auto* self = const_cast<remote_transformed*>(this);
        self->again_ = false;
        self->sent_ = to_world_;
        message_writer w;
        put_child(w, nullptr);
        w.put(to_world_);
        self->remake(made_in_subject(c::make_transformed, w, "make_transformed"));
    }
    static bool same(const matrix& a, const matrix& b) {
        for (int r = 0; r < 4; ++r)
            for (int k = 0; k < 4; ++k)
                if (!(a(r, k) == b(r, k)) && !(std::isnan(a(r, k)) && std::isnan(b(r, k)))) return false;
        return true;
    }
    matrix sent_;
    bool again_ = false;
};

class bvh_shell : public shapes::bvh_base {
public:
    bvh_shell() : bvh_base(4) {}
    void set_leaf_size(int k) { leaf_size_ = k; }

private:
    void build() const override {}  // the tree is the subject's
};

/// \brief A BVH: a scene file's leaf size makes the subject's object again before the
/// first child crosses.
class remote_bvh final : public remote_composite<bvh_shell> {
public:
    void made_with(int leaf_size) {
        set_leaf_size(leaf_size);
        sent_ = leaf_size;
    }

private:
    bool defers_bounded_children() const override { return true; }
    void update() const override {
        if (leaf_size_ == sent_) return;
        auto* self = const_cast<remote_bvh*>(this);
        self->sent_ = leaf_size_;
        self->remake(made_in_subject(c::make_bvh, message_writer().put(leaf_size_), "make_bvh"));
    }
    int sent_ = 4;
};

/// \brief A BOUNDSPH: any child with a known box goes in.
class remote_bounding_sphere final : public remote_composite<bounding_sphere_shell> {
    bool defers_bounded_children() const override { return true; }
};

// --- the shapes of stage 02 the student's code makes in the subject ----------------------

/// Answers a make_lent_* call: keeps `shape` and describes it.
void serve_made(std::unique_ptr<primitive> shape, message_writer& out) {
    const primitive& s = *shape;
    std::string type = s.type_name();
    const description d = describe(s);
    const handle h = keep_made(std::move(shape));
    out.put(h).put_string(type).put(d);
}

const bool shapes_served = [] {
    std::vector<handler>& h = judge_handlers();
    h[cc::make_lent_sphere] = [](message_reader& in, message_writer& out) {
        const auto center = in.get<point>();
        const auto radius = in.get<double>();
        in.finish();
        serve_made(stage02::make_sphere(center, radius), out);
    };
    h[cc::posted_sphere] = [](message_reader& in, message_writer&) {
        const auto made_as = in.get<handle>();
        const auto center = in.get<point>();
        const auto radius = in.get<double>();
        in.finish();
        keep_made_as(made_as, stage02::make_sphere(center, radius));
    };
    h[cc::make_lent_plane] = [](message_reader& in, message_writer& out) {
        const auto p = in.get<point>();
        const auto n = in.get<vector>();
        in.finish();
        serve_made(stage02::make_plane(p, n), out);
    };
    h[cc::make_lent_triangle] = [](message_reader& in, message_writer& out) {
        const auto a = in.get<point>(), b = in.get<point>(), k = in.get<point>();
        in.finish();
        serve_made(stage02::make_triangle(a, b, k), out);
    };
    h[cc::make_lent_polygon] = [](message_reader& in, message_writer& out) {
        std::vector<point> vertices = in.get_vector<point>(1 << 16);
        in.finish();
        serve_made(stage02::make_polygon(std::move(vertices)), out);
    };
    return true;
}();

}  // namespace

std::unique_ptr<rtab_composite> make_bounding_sphere() {
    const handle h = made_in_subject(c::make_bounding_sphere, {}, "make_bounding_sphere");
    auto s = std::make_unique<remote_bounding_sphere>();
    s->attach(h);
    return s;
}

std::unique_ptr<rtab_composite> make_frac_sphere(const point& center, double radius, int depth, double ratio) {
    const handle h = made_in_subject(c::make_frac_sphere, message_writer().put(center).put(radius).put(depth).put(ratio),
                          "make_frac_sphere");
    auto s = std::make_unique<remote_frac_sphere>();
    s->set_values(center, radius, depth, ratio);
    s->attach(h);
    s->refresh();
    return s;
}

std::unique_ptr<rtab_composite> make_box(const point& lo, const point& hi) {
    const handle h = made_in_subject(c::make_box, message_writer().put(lo).put(hi), "make_box");
    auto s = std::make_unique<remote_box>();
    s->set_corners(lo, hi);
    s->attach(h);
    s->refresh();
    return s;
}

std::unique_ptr<rtab_composite> make_transformed(std::unique_ptr<rtab_component> child, const matrix& object_to_world) {
    message_writer w;
    put_child(w, child.get());
    w.put(object_to_world);
    handle h = 0;
    try {
        h = made_in_subject(c::make_transformed, w, "make_transformed");
    } catch (...) {
        lost(child);
        throw;
    }
    auto s = std::make_unique<remote_transformed>();
    try {
        // The shell's matrices, for the steps a scene file reads (the student's code
        // decides what the matrix is; a matrix its code accepts and the shell cannot
        // invert is left as it is).
        s->set_up(nullptr, object_to_world,
                  {stage01::scale_matrix, stage01::rotate_matrix, stage01::translate_matrix}, stage01::inverse);
    } catch (const std::exception&) {
    }
    s->made_with(object_to_world);
    s->attach(h);
    if (auto* r = dynamic_cast<remote_identity*>(child.get())) r->given_away();
    s->refresh(std::move(child));
    return s;
}

std::unique_ptr<rtab_composite> make_bvh(int leaf_size) {
    const handle h = made_in_subject(c::make_bvh, message_writer().put(leaf_size), "make_bvh");
    auto s = std::make_unique<remote_bvh>();
    s->made_with(leaf_size);
    s->attach(h);
    return s;
}

}  // namespace vl::stage03
