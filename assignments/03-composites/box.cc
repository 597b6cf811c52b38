// The box of six polygons: see stage_03.hh for what each function must do, and README.md
// for hints. The TODOs are yours. The rest is done in the base class,
// vl::shapes::box_base (framework/include/vl/composite_bases.hh): the corners lo_ and hi_
// and the surface surface_, reading and writing BOX, the refusals of insert() and
// delete_all_children() (a box is stage 03's leaf: its faces are its only children), and
// the checks of make_box().
#include "stage_02.hh"
#include "stage_03.hh"
#include "vl/bounds.hh"
#include "vl/composite_bases.hh"
#include "vl/not_implemented.hh"

namespace vl::stage03 {

namespace {

/// \brief An axis-aligned box made of its six faces, tested as a box first.
class box final : public shapes::box_base {
public:
    /// set_geometry() stores the corners and calls make_faces().
    box(const point& lo, const point& hi) { set_geometry(lo, hi); }

    bool contains([[maybe_unused]] const point& p) const override {
        // TODO: true when p is strictly inside: every coordinate strictly between lo_ and hi_.
        throw not_implemented_error();
    }

    vector normal([[maybe_unused]] const point& p) const override {
        // TODO: the outward unit normal of the face p lies on: of the face whose plane is
        // nearest to p (on an edge either will do).
        throw not_implemented_error();
    }

private:
    /// Makes the faces: called by set_geometry() (from the constructor, and again by
    /// read() with what it read, after the surface keys, so the faces get them).
    void make_faces() override {
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
};

}  // namespace

std::unique_ptr<rtab_composite> make_box(const point& lo, const point& hi) {
    shapes::box_base::check_corners(lo, hi);
    return std::make_unique<box>(lo, hi);
}

}  // namespace vl::stage03
