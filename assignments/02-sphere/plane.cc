// The infinite plane: see stage_02.hh for what each function must do, and README.md for
// hints. Holding, reading and writing the point and normal are done, and so are
// contains() and the bounds (vl::shapes::plane_base, vl/primitive_bases.hh); the
// functions marked TODO are yours.
#include <cmath>

#include "stage_02.hh"
#include "vl/not_implemented.hh"
#include "vl/primitive_bases.hh"

namespace vl::stage02 {

namespace {

/// \brief The points p with (p - point_) . normal_ == 0 (both members of the base; normal_
/// as given, not unit).
class plane final : public shapes::plane_base {
public:
    vector normal([[maybe_unused]] const point& p) const override {
        // TODO: the plane's unit normal (the same everywhere).
        throw not_implemented_error();
    }
    // contains() is false (a flat object has no inside), and a plane is unbounded, so the
    // default min_point() and max_point() (NaN_point, "no box") are already right.

private:
    /// Called after every change of point_ and normal_: once when make_plane() makes the plane
    /// (the base's make() sets the geometry), and again by the base's read() with what it read
    /// from the scene.
    void geometry_changed() override {
        // TODO (optional): anything find_intersection() should not recompute for every ray
        // (the unit normal?) belongs here (in members you add), so that it is also right
        // after read().
    }

    intersection find_intersection([[maybe_unused]] const ray& r) const override {
        // TODO: the hit of r with t > |zero_t()|, or intersection::none().
        // - Put the ray o + t d into (p - point_) . n = 0 and solve for t.
        // - What if the ray runs parallel to the plane? Lies in it? Is nearly parallel?
        //   None of them may return a NaN or an infinite t.
        // - A ray starting on the plane (a reflection leaving it) must not hit it again.
        throw not_implemented_error();
    }
};

}  // namespace

std::unique_ptr<primitive> make_plane(const point& point_on_plane, const vector& normal) {
    return shapes::plane_base::make<plane>(point_on_plane, normal);
}

}  // namespace vl::stage02
