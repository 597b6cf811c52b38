// The triangle: see stage_02.hh for what each function must do, and README.md for hints.
// Holding, reading and writing the vertices, their check and contains() are done
// (vl::shapes::triangle_base, vl/primitive_bases.hh); the functions marked TODO are yours.
#include <cmath>

#include "stage_02.hh"
#include "vl/not_implemented.hh"
#include "vl/primitive_bases.hh"

namespace vl::stage02 {

namespace {

/// \brief The triangle a_ b_ c_ (members of the base); its front is the side from which
/// a, b, c run counter-clockwise.
class triangle final : public shapes::triangle_base {
public:
    vector normal([[maybe_unused]] const point& p) const override {
        // TODO: the unit normal on the side from which a, b, c run counter-clockwise.
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
    /// Called after every change of a_, b_ and c_: once when make_triangle() makes the triangle
    /// (the base's make() sets the geometry), and again by the base's read() with what it read
    /// from the scene.
    void geometry_changed() override {
        // TODO (optional): anything find_intersection() should not recompute for every ray
        // belongs here (in members you add), so that it is also right after read().
    }

    intersection find_intersection([[maybe_unused]] const ray& r) const override {
        // TODO: the hit of r with t > |zero_t()|, from either side, or intersection::none().
        // - It must be watertight: two triangles sharing an edge or a vertex never let a
        //   ray pass between them. Comparing barycentric coordinates with 0 and 1 is not:
        //   for a ray through the shared edge, each triangle may round its way to "just
        //   outside" (see the [watertight] tests).
        // - Woop, Benthin and Wald, "Watertight Ray/Triangle Intersection" (JCGT 2(1),
        //   2013, jcgt.org) decide inside or outside in the ray's own coordinates, with
        //   one edge function per edge. What must be true of the edge function of the
        //   shared edge, computed by each neighbour, so that they always agree? What do
        //   you do when one is exactly 0?
        throw not_implemented_error();
    }
};

}  // namespace

std::unique_ptr<primitive> make_triangle(const point& a, const point& b, const point& c) {
    return shapes::triangle_base::make<triangle>(a, b, c);
}

}  // namespace vl::stage02
