// The sphere: see stage_02.hh for what each function must do, and README.md for hints.
// read() and write() are done (vl/shape_params.hh); the functions marked TODO are yours.
#include <cmath>
#include <ostream>

#include "stage_02.hh"
#include "vl/not_implemented.hh"
#include "vl/shape_params.hh"

namespace vl::stage02 {

namespace {

/// \brief The thesis's sphere: every point at distance `radius` from `center`.
class sphere final : public primitive {
public:
    sphere(const point& center, double radius) { set_geometry(center, radius); }

    std::string type_name() const override { return "SPHERE"; }

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

    void read(scene_reader& in) override {
        shapes::sphere_params p{center_, radius_};
        read_with_surface(in, p.properties(in));
        set_geometry(p.center, p.radius);
    }
    void write(std::ostream& s) const override {
        shapes::sphere_params{center_, radius_}.write(s);
        write_surface(s);
        s << " }";
    }

private:
    /// Stores the geometry; the constructor calls it, and read() calls it again with what
    /// it read from the scene.
    void set_geometry(const point& center, double radius) {
        center_ = center.homogenized();
        radius_ = radius;
        // TODO (optional): anything find_intersection() should not recompute for every ray
        // belongs here, so that it is also right after read().
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

    point center_;
    double radius_ = 1;
};

}  // namespace

std::unique_ptr<primitive> make_sphere(const point& center, double radius) {
    if (!checks::finite(center.homogenized()) || !std::isfinite(radius) || !(radius > 0))
        throw usage_error("make_sphere: the center must be finite and the radius a finite number > 0");
    return std::make_unique<sphere>(center, radius);
}

}  // namespace vl::stage02
