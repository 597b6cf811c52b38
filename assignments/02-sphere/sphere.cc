// The sphere: see stage_02.hh for what each function must do, and README.md for hints.
// Holding, reading and writing the center and radius are done (vl::shapes::sphere_base,
// vl/primitive_bases.hh); the functions marked TODO are yours.
#include <cmath>

#include "stage_02.hh"
#include "vl/not_implemented.hh"
#include "vl/primitive_bases.hh"

namespace vl::stage02 {

namespace {

/// \brief The thesis's sphere: every point at distance `radius_` from `center_` (both
/// members of the base).
class sphere final : public shapes::sphere_base {
public:
    vector normal([[maybe_unused]] const point& p) const override {
        // TODO: the outward unit normal at p, a point on the sphere.
        throw not_implemented_error();
    }
    bool contains([[maybe_unused]] const point& p) const override {
        // TODO: true when p is strictly inside the sphere.
        throw not_implemented_error();
    }
    point min_point() const override {
        // TODO: the lower-left-back corner of the smallest axis-aligned box around the sphere.
        throw not_implemented_error();
    }
    point max_point() const override {
        // TODO: the upper-right-front corner of that box.
        throw not_implemented_error();
    }

private:
    /// Called after every change of center_ and radius_: once when make_sphere() makes the
    /// sphere (the base's make() sets the geometry), and again by the base's read() with what
    /// it read from the scene.
    void geometry_changed() override {
        // TODO (optional): anything find_intersection() should not recompute for every ray
        // belongs here (in members you add), so that it is also right after read().
    }

    intersection find_intersection([[maybe_unused]] const ray& r) const override {
        // TODO: the nearest hit of r with t > |zero_t()|, or intersection::none().
        // - Put the ray o + t d (d is unit) into |p - center|^2 = radius^2: a quadratic in t.
        // - Of its two roots, return the smaller one that counts; a ray starting inside
        //   the sphere counts only one of them.
        // - The textbook formula fails for a small sphere far away and for rays starting
        //   on the surface (see the [stability] tests). Look at each subtraction: when
        //   are its two operands large and nearly equal? Ray Tracing Gems, chapter 7,
        //   shows how to avoid both.
        throw not_implemented_error();
    }
};

}  // namespace

std::unique_ptr<primitive> make_sphere(const point& center, double radius) {
    return shapes::sphere_base::make<sphere>(center, radius);
}

}  // namespace vl::stage02
