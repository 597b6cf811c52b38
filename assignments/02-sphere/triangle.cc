// The triangle: see stage_02.hh for what each function must do, and README.md for hints.
// read(), write() and the check of the vertices are done (vl/shape_params.hh); the
// functions marked TODO are yours.
#include <cmath>
#include <ostream>
#include <string>

#include "stage_02.hh"
#include "vl/not_implemented.hh"
#include "vl/shape_params.hh"

namespace vl::stage02 {

namespace {

/// \brief The triangle a b c; its front is the side from which a, b, c run counter-clockwise.
class triangle final : public primitive {
public:
    triangle(const point& a, const point& b, const point& c) { set_geometry(a, b, c); }

    std::string type_name() const override { return "TRIANGLE"; }

    vector normal([[maybe_unused]] const point& p) const override {
        // TODO: the unit normal on the side from which a, b, c run counter-clockwise.
        throw not_implemented_error();
    }
    bool contains(const point&) const override { return false; }  // a flat object has no inside
    point min_point() const override {
        // TODO: the lower-left-back corner of the smallest axis-aligned box around the vertices.
        throw not_implemented_error();
    }
    point max_point() const override {
        // TODO: the upper-right-front corner of that box.
        throw not_implemented_error();
    }

    void read(scene_reader& in) override {
        const source_location where = in.peek().where;
        shapes::triangle_params p{a_, b_, c_};
        read_with_surface(in, p.properties(in));
        p.check(in, where);
        set_geometry(p.a, p.b, p.c);
    }
    void write(std::ostream& s) const override {
        shapes::triangle_params{a_, b_, c_}.write(s);
        write_surface(s);
        s << " }";
    }

private:
    /// Stores the geometry; the constructor calls it, and read() calls it again with what
    /// it read from the scene.
    void set_geometry(const point& a, const point& b, const point& c) {
        a_ = a.homogenized();
        b_ = b.homogenized();
        c_ = c.homogenized();
        // TODO (optional): anything find_intersection() should not recompute for every ray
        // belongs here, so that it is also right after read().
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

    point a_, b_, c_;
};

}  // namespace

std::unique_ptr<primitive> make_triangle(const point& a, const point& b, const point& c) {
    if (const std::string problem = checks::triangle_problem(a.homogenized(), b.homogenized(), c.homogenized()); !problem.empty())
        throw usage_error("make_triangle: " + problem);
    return std::make_unique<triangle>(a, b, c);
}

}  // namespace vl::stage02
