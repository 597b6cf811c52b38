// The infinite plane: see stage_02.hh for what each function must do, and README.md for
// hints. read() and write() are done (vl/shape_params.hh); the functions marked TODO
// are yours.
#include <cmath>
#include <ostream>

#include "stage_02.hh"
#include "vl/not_implemented.hh"
#include "vl/shape_params.hh"

namespace vl::stage02 {

namespace {

/// \brief The points p with (p - point_on_plane) . normal == 0.
class plane final : public primitive {
public:
    plane(const point& point_on_plane, const vector& normal) { set_geometry(point_on_plane, normal); }

    std::string type_name() const override { return "PLANE"; }

    vector normal([[maybe_unused]] const point& p) const override {
        // TODO: the plane's unit normal (the same everywhere).
        throw not_implemented_error();
    }
    bool contains(const point&) const override { return false; }  // a flat object has no inside
    // min_point() and max_point(): a plane is unbounded, so the defaults (NaN_point, "no
    // box") are already right.

    void read(scene_reader& in) override {
        shapes::plane_params p{point_, normal_};
        read_with_surface(in, p.properties(in));
        set_geometry(p.point_on_plane, p.normal);
    }
    void write(std::ostream& s) const override {
        shapes::plane_params{point_, normal_}.write(s);
        write_surface(s);
        s << " }";
    }

private:
    /// Stores the geometry; the constructor calls it, and read() calls it again with what
    /// it read from the scene.
    void set_geometry(const point& point_on_plane, const vector& normal) {
        point_ = point_on_plane.homogenized();
        normal_ = vector(normal.x, normal.y, normal.z);
        // TODO (optional): anything find_intersection() should not recompute for every ray
        // (the unit normal?) belongs here, so that it is also right after read().
    }

    intersection find_intersection([[maybe_unused]] const ray& r) const override {
        // TODO: the hit of r with t > |zero_t()|, or intersection::none().
        // - Put the ray o + t d into (p - point_) . n = 0 and solve for t.
        // - What if the ray runs parallel to the plane? Lies in it? Is nearly parallel?
        //   None of them may return a NaN or an infinite t.
        // - A ray starting on the plane (a reflection leaving it) must not hit it again.
        throw not_implemented_error();
    }

    point point_;    ///< as given, so write() writes what was read
    vector normal_;  ///< as given (not unit), for the same reason
};

}  // namespace

std::unique_ptr<primitive> make_plane(const point& point_on_plane, const vector& normal) {
    if (!checks::finite(point_on_plane.homogenized()) || !checks::usable_normal(normal))
        throw usage_error("make_plane: the point must be finite and the normal a finite, non-zero vector");
    return std::make_unique<plane>(point_on_plane, normal);
}

}  // namespace vl::stage02
