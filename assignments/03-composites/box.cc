// The box of six polygons: see stage_03.hh for what each function must do, and README.md
// for hints. Reading, writing and checking the corners are done; the TODOs are yours.
#include <cmath>
#include <limits>
#include <ostream>

#include "stage_02.hh"
#include "stage_03.hh"
#include "vl/bounds.hh"
#include "vl/not_implemented.hh"
#include "vl/primitive.hh"
#include "vl/scene_reader.hh"
#include "vl/shape_params.hh"

namespace vl::stage03 {

namespace {

/// \brief An axis-aligned box made of its six faces, tested as a box first.
class box final : public rtab_composite {
public:
    box(const point& lo, const point& hi) { set_geometry(lo, hi); }

    std::string type_name() const override { return "BOX"; }

    void insert(std::unique_ptr<rtab_component>) override {
        // TODO: refuse with a vl::usage_error that says why (a box is made of its six
        // faces) and what to do instead (put the BOX and the other object in a LIST).
        throw not_implemented_error();
    }
    void delete_all_children() override {
        // TODO: refuse too: the faces are the box.
        throw not_implemented_error();
    }

    point min_point() const override { return lo_; }
    point max_point() const override { return hi_; }

    bool contains([[maybe_unused]] const point& p) const override {
        // TODO: true when p is strictly inside: every coordinate strictly between lo_ and hi_.
        throw not_implemented_error();
    }

    vector normal([[maybe_unused]] const point& p) const override {
        // TODO: the outward unit normal of the face p lies on: of the face whose plane is
        // nearest to p (on an edge either will do).
        throw not_implemented_error();
    }

    void read(scene_reader& in) override {
        shapes::box_params p{lo_, hi_};
        source_location where;
        std::vector<scene_reader::property> properties = p.properties(in, where);
        add_surface_properties(properties, in, surface_, "BOX");
        in.read_block("BOX", properties);
        if (!checks::below(p.lo, p.hi))
            in.fail(where, "min of BOX must be below max in x, y and z (a box has volume)");
        set_geometry(p.lo, p.hi);
    }

    void write(std::ostream& s) const override {
        shapes::box_params{lo_, hi_}.write(s);
        write_surface(s, surface_);
        s << " }";
    }

private:
    /// Stores the corners and makes the faces: called by the constructor, and again by
    /// read() with what it read (and after the surface keys, so the faces get them).
    void set_geometry(const point& lo, const point& hi) {
        lo_ = lo.homogenized();
        hi_ = hi.homogenized();
        children_.clear();
        // TODO: the six faces, each a stage02::make_polygon() of four corners wound
        // counter-clockwise seen from OUTSIDE the box (so its normal points out), each
        // given surface_ with set_surface(), pushed onto children_.
        throw not_implemented_error();
    }

    intersection find_intersection([[maybe_unused]] const ray& r) const override {
        // TODO: one vl::hits_box() test first (a miss tests no face), then the nearest
        // face hit (nearest_child_hit()), or composite_only(this) when no face is hit.
        throw not_implemented_error();
    }

    point lo_, hi_;
    surface surface_;
};

}  // namespace

std::unique_ptr<rtab_composite> make_box(const point& lo, const point& hi) {
    if (!checks::finite(lo.homogenized()) || !checks::finite(hi.homogenized()))
        throw usage_error("make_box: both corners must be finite points");
    if (!checks::below(lo.homogenized(), hi.homogenized()))
        throw usage_error("make_box: lo must be below hi in x, y and z (a box has volume)");
    return std::make_unique<box>(lo, hi);
}

}  // namespace vl::stage03
