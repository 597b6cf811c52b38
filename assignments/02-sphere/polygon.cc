// The convex planar polygon: see stage_02.hh for what each function must do, and
// README.md for hints. read(), write() and the checks of the vertices are done
// (vl/shape_params.hh, vl/convex_polygon.hh); the functions marked TODO are yours.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "stage_02.hh"
#include "vl/convex_polygon.hh"
#include "vl/not_implemented.hh"
#include "vl/shape_params.hh"

namespace vl::stage02 {

namespace {

/// \brief A convex planar polygon; its front is the side from which its vertices run
/// counter-clockwise.
class polygon final : public primitive {
public:
    explicit polygon(std::vector<point> vertices) { set_geometry(std::move(vertices)); }

    std::string type_name() const override { return "POLYGON"; }

    vector normal([[maybe_unused]] const point& p) const override {
        // TODO: the unit normal on the side from which the vertices run counter-clockwise
        // (the same everywhere). vl::newell_normal() (vl/convex_polygon.hh) points that way.
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
        shapes::polygon_params p{vertices_};
        read_with_surface(in, p.properties(in));
        set_geometry(std::move(p.vertices));
    }
    void write(std::ostream& s) const override {
        shapes::polygon_params{vertices_}.write(s);
        write_surface(s);
        s << " }";
    }

private:
    /// Stores the geometry (vertices already checked by find_polygon_problem()); the constructor
    /// calls it, and read() calls it again with what it read from the scene.
    void set_geometry(std::vector<point> vertices) {
        vertices_ = std::move(vertices);
        for (point& p : vertices_) p = p.homogenized();
        // TODO (optional): anything find_intersection() should not recompute for every ray
        // (the normal? the box?) belongs here, so that it is also right after read().
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

    std::vector<point> vertices_;
};

}  // namespace

std::unique_ptr<primitive> make_polygon(std::vector<point> vertices) {
    for (point& p : vertices) p = p.homogenized();
    if (const auto problem = find_polygon_problem(vertices)) throw usage_error("make_polygon: " + problem->message);
    return std::make_unique<polygon>(std::move(vertices));
}

}  // namespace vl::stage02
