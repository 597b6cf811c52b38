#pragma once
/// \file
/// \brief Helpers for stage 02's public tests, which the later stages' tests use too. You
/// need not read this file: the tests themselves say what they check.

#include <cmath>
#include <memory>
#include <numbers>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "../../01-tuples/tests/test_support.hh"
#include "all_pieces.hh"
#include "stage_02.hh"
#include "vl/error.hh"
#include "vl/scene_reader.hh"

namespace vl::stage02::testing {

// Numbers, points, vectors and rays in messages, at full precision (stage 01's helpers).
using test01::num;
using test01::show;

/// What an intersection says: "a hit at t = 4 on a SPHERE", "composite_only of a BVH", "a miss".
inline std::string show(const intersection& i) {
    if (i.is_miss()) return "a miss (intersection::none())";
    if (i.is_composite_only()) return "composite_only of a " + i.object->type_name() + " (t == 0)";
    return "a hit at t = " + num(i.t) + " on a " + i.object->type_name();
}

/// The ray from `from` through `to`.
inline ray ray_through(const point& from, const point& to) { return ray(from, to - from); }

/// The distance between two points.
inline double distance(const point& p, const point& q) { return (p - q).length(); }

/// The six faces of the box with the corner `o` and the edges `x`, `y` and `z` (x % y
/// towards z), each a make_polygon() of its four corners; each face's front is outside
/// the box when `fronts_outside`, inside otherwise.
inline std::vector<std::unique_ptr<primitive>> box_of_polygons(const point& o, const vector& x, const vector& y,
                                                               const vector& z, bool fronts_outside) {
    const auto corner = [&](int i, int j, int k) { return o + i * x + j * y + k * z; };
    // Each face from one corner along two edges: fronts outside take them the other way round.
    const auto face = [&](const point& a, const point& b, const point& c, const point& d) {
        return fronts_outside ? make_polygon({a, b, c, d}) : make_polygon({a, d, c, b});
    };
    std::vector<std::unique_ptr<primitive>> faces;
    faces.push_back(face(corner(0, 0, 0), corner(0, 1, 0), corner(1, 1, 0), corner(1, 0, 0)));
    faces.push_back(face(corner(0, 0, 1), corner(1, 0, 1), corner(1, 1, 1), corner(0, 1, 1)));
    faces.push_back(face(corner(0, 0, 0), corner(1, 0, 0), corner(1, 0, 1), corner(0, 0, 1)));
    faces.push_back(face(corner(0, 1, 0), corner(0, 1, 1), corner(1, 1, 1), corner(1, 1, 0)));
    faces.push_back(face(corner(0, 0, 0), corner(0, 0, 1), corner(0, 1, 1), corner(0, 1, 0)));
    faces.push_back(face(corner(1, 0, 0), corner(1, 1, 0), corner(1, 1, 1), corner(1, 0, 1)));
    return faces;
}

/// Where the line of a ray meets a sphere, in long double: the roots t1 <= t2 of
/// |origin + t direction - center| = radius, when `meets`.
struct sphere_roots {
    bool meets = false;
    long double t1 = 0, t2 = 0;
};

/// \brief Where the line of `r` meets the sphere of `center` and `radius`, computed in
/// long double. The tests' own spheres (the later stages' test_sphere) hit with it, so
/// what a test expects never depends on your sphere.
inline sphere_roots roots_in_long_double(const point& center, double radius, const ray& r) {
    using ld = long double;
    const point o = r.origin().homogenized();
    const vector d = r.direction();
    const ld ox = ld(o.x) - center.x, oy = ld(o.y) - center.y, oz = ld(o.z) - center.z;
    const ld dd = ld(d.x) * d.x + ld(d.y) * d.y + ld(d.z) * d.z;
    const ld b = ox * d.x + oy * d.y + oz * d.z;
    const ld c = ox * ox + oy * oy + oz * oz - ld(radius) * radius;
    const ld disc = b * b - dd * c;
    if (disc < 0) return {};
    const ld root = std::sqrt(disc);
    // The near root without cancellation, the far one from the product of the roots.
    const ld q = b > 0 ? -(b + root) : -(b - root);
    ld t1 = q / dd, t2 = q != 0 ? c / q : t1;
    if (t1 > t2) std::swap(t1, t2);
    return {true, t1, t2};
}

/// \brief What the later stages' test spheres share: the ball of `center_` and `radius_`,
/// its outward normal, its box and its inside (strictly). `Base` is the interface the
/// sphere implements (vl::rtab_component, or vl::primitive for one with a surface); a
/// test sphere adds its hits, computed with roots_in_long_double().
template <class Base>
class test_ball : public Base {
public:
    vector normal(const point& p) const override { return (p.homogenized() - center_).unit(); }
    point min_point() const override { return center_ - vector(radius_, radius_, radius_); }
    point max_point() const override { return center_ + vector(radius_, radius_, radius_); }
    bool contains(const point& p) const override { return (p.homogenized() - center_).length() < radius_; }

protected:
    test_ball(const point& center, double radius) : center_(center), radius_(radius) {}

    point center_;
    double radius_;
};

/// True when `r` passes within `radius` of `center` ahead of its origin (or starts within
/// it): what the tests' own bounded composites answer composite_only for.
inline bool passes_within(const ray& r, const point& center, double radius) {
    const vector oc = center - r.origin().homogenized();
    const double along = oc * r.direction();
    const double miss_distance = (oc - along * r.direction()).length();
    return miss_distance < radius && (along > 0 || oc.length() < radius);
}

// ---------------------------------------------------------------------------------------
// Scene files
// ---------------------------------------------------------------------------------------

/// Every piece this build links.
inline const registry& pieces() {
    static const registry types = [] {
        registry r;
        register_all_pieces(r);
        return r;
    }();
    return types;
}

/// Reads one object (`SPHERE { ... }`) from `text` as if it were the file `file_name`,
/// with the types of `types` (every piece this build links, unless a test says otherwise).
inline std::unique_ptr<rtab_component> read_object(const std::string& text,
                                                   const std::string& file_name = "test.ray_trace",
                                                   const registry& types = pieces()) {
    scene_reader in(types);
    in.open_text(text, file_name);
    return in.read_object();
}

/// The message of the vl::file_error that reading `text` (as read_object() does) throws,
/// or "(no error)". Any other exception (a stub's "not yet implemented") goes on to fail
/// the test.
inline std::string read_error(const std::string& text) {
    try {
        read_object(text);
    } catch (const file_error& e) {
        return e.what();
    }
    return "(no error)";
}

/// What write() writes for `o`.
inline std::string written(const rtab_component& o) {
    std::ostringstream s;
    o.write(s);
    return s.str();
}

/// A surface that differs from the default only in zero_t.
inline surface with_zero_t(double zero_t) {
    surface s;
    s.zero_t = zero_t;
    return s;
}

// ---------------------------------------------------------------------------------------
// Random numbers
// ---------------------------------------------------------------------------------------

/// Random numbers for the sweeps, with a fixed seed so that every run tests the same rays.
class random_numbers {
public:
    explicit random_numbers(unsigned seed = 2) : engine_(seed) {}
    /// Uniform in [lo, hi).
    double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(engine_); }
    /// A point uniform in the cube [-s, s]^3.
    point in_cube(double s) { return {uniform(-s, s), uniform(-s, s), uniform(-s, s)}; }
    /// A point uniform in the box [lo, hi]^3.
    point in_box(double lo, double hi) { return {uniform(lo, hi), uniform(lo, hi), uniform(lo, hi)}; }
    /// A vector uniform in the cube [-s, s]^3.
    vector offset(double s) { return {uniform(-s, s), uniform(-s, s), uniform(-s, s)}; }
    /// A unit vector, uniform over the sphere of directions.
    vector direction() {
        const double z = uniform(-1, 1), phi = uniform(0, 2 * std::numbers::pi);
        const double s = std::sqrt(1 - z * z);
        return {s * std::cos(phi), s * std::sin(phi), z};
    }
    /// The generator itself, for a distribution of a test's own.
    std::mt19937_64& engine() { return engine_; }

private:
    std::mt19937_64 engine_;
};

}  // namespace vl::stage02::testing
