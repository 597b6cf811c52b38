// The convex planar polygon: see stage_02.hh for what each function must do, and
// README.md for hints. Holding, reading and writing the vertices, their checks and
// contains() are done (vl::shapes::polygon_base, vl/primitive_bases.hh); the functions
// marked TODO are yours. vl/convex_polygon.hh has helpers for the geometry.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

#include "stage_02.hh"
#include "vl/convex_polygon.hh"
#include "vl/not_implemented.hh"
#include "vl/primitive_bases.hh"

namespace vl::stage02 {

namespace {

/// \brief A convex planar polygon with the vertices vertices_ (a member of the base); its
/// front is the side from which its vertices run counter-clockwise.
class polygon final : public shapes::polygon_base {
public:
    vector normal([[maybe_unused]] const point& p) const override {
        // TODO: the unit normal on the side from which the vertices run counter-clockwise
        // (the same everywhere). vl::newell_normal() (vl/convex_polygon.hh) points that way.
        throw not_implemented_error();
    }
    // contains() is false: a flat object has no inside.
    point min_point() const override {
        // TODO: the lower-left-back corner of the smallest axis-aligned box around the vertices.
        throw not_implemented_error();
    }
    point max_point() const override {
        // TODO: the upper-right-front corner of that box.
        throw not_implemented_error();
    }

private:
    /// Called after every change of vertices_ (already checked by find_polygon_problem()):
    /// once when make_polygon() makes the polygon (the base's make() sets the geometry),
    /// and again by the base's read() with what it read from the scene.
    void geometry_changed() override {
        // TODO (optional): anything find_intersection() should not recompute for every ray
        // (the normal? the box?) belongs here (in members you add), so that it is also
        // right after read().
    }

    intersection find_intersection([[maybe_unused]] const ray& r) const override {
        // TODO: the hit of r with t > |zero_t()|, from either side, or intersection::none().
        // - A polygon is a piece of a plane: where does the ray meet that plane, and is
        //   that point inside the polygon?
        // - The six faces of a box share edges: a ray through an edge must hit at least
        //   one of them (see the [watertight] test). Does your inside test give the two
        //   neighbours the same answer about their shared edge? Your triangle's test may
        //   carry over: a convex polygon is "inside every edge".
        throw not_implemented_error();
    }
};

}  // namespace

std::unique_ptr<primitive> make_polygon(std::vector<point> vertices) {
    return shapes::polygon_base::make<polygon>(std::move(vertices));
}

}  // namespace vl::stage02
