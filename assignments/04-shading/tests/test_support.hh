#pragma once
/// \file
/// \brief Helpers for stage 04's public tests. You need not read this file to use the
/// tests, but it helps when one fails: most objects the tests give your tracer are the
/// tests' own (test_sphere, test_plane, test_glass_below, bounded_root below). Their hits
/// are computed in long double and their surface values are whatever the test sets, so a
/// test's answer depends only on your whitted.cc, never on your stage 02 or 03 code.
///
/// Three tricks make most answer keys one line of arithmetic:
/// - **Emitters.** With no lights and ambient (1, 1, 1), an object with `kdr 1` (and no
///   ksr or kst) sends back exactly its colour: ambient * clr * kdr = clr. The tests put
///   such objects where a reflected or transmitted ray should land, each in its own
///   colour, so the colour your tracer returns says where the ray went.
/// - **Your own colours as the baseline.** A test of reflection or refraction looks only
///   at what the bounce adds: it traces the same ray twice, with the mirror or glass and
///   with the same object made dull (ksr = kst = 0), and takes the difference. And it
///   asks your tracer what colour each emitter is (a ray aimed straight at it). So those
///   tests depend on your bounces alone, not on your ambient or diffuse term.
/// - **Neutral terms.** Everything a test does not look at is switched off: no ambient,
///   black background, depth 0, no lights, as the test says in its comments.

#include "vl/catch.hh"

#include <cmath>
#include <cstring>
#include <memory>
#include <numbers>
#include <string>
#include <type_traits>
#include <vector>

#include "../../02-sphere/tests/test_support.hh"
#include "stage_04.hh"
#include "vl/object_list.hh"
#include "vl/primitive.hh"
#include "vl/scene.hh"

namespace vl::stage04::testing {

// ---------------------------------------------------------------------------------------
// Printing values in messages
// ---------------------------------------------------------------------------------------

// Numbers, points, vectors and rays in messages, at full precision (stage 02's helpers).
using stage02::testing::num;
using stage02::testing::ray_through;
using stage02::testing::show;

/// `(r, g, b)` of a colour (alpha is not shown: the tracer's colours all have alpha 0).
inline std::string show(const color& c) { return "(" + num(c.r) + ", " + num(c.g) + ", " + num(c.b) + ")"; }

/// True when every channel (red, green, blue) of `got` is within `tolerance` of `want`.
inline bool near(const color& got, const color& want, double tolerance) {
    return std::fabs(got.r - want.r) <= tolerance && std::fabs(got.g - want.g) <= tolerance &&
           std::fabs(got.b - want.b) <= tolerance;
}

}  // namespace vl::stage04::testing

/// Checks that the colour `got` is `want` within `tolerance` in each of red, green and
/// blue. On failure the message reads "WHAT: expected (..) ± tol, yours is (..)"; `what`
/// is streamed, so it can hold the ray and the reason for the expected value.
#define CHECK_COLOR(what, got, want, tolerance)                                                               \
    do {                                                                                                      \
        const ::vl::color got_color_ = (got), want_color_ = (want);                                           \
        const double tolerance_ = (tolerance);                                                                \
        if (::vl::stage04::testing::near(got_color_, want_color_, tolerance_)) {                              \
            SUCCEED();                                                                                        \
        } else {                                                                                              \
            FAIL_CHECK(what << "\n  expected " << ::vl::stage04::testing::show(want_color_) << " ± "          \
                            << ::vl::stage04::testing::num(tolerance_) << " in each channel\n  yours is "     \
                            << ::vl::stage04::testing::show(got_color_));                                     \
        }                                                                                                     \
    } while (false)

/// Asks your tracer what colour an emitter is, `seen` (what a ray aimed straight at it
/// returns), and stops the test unless that is clearly not black: the expected bounce is
/// then this colour times the weights, and a tracer that returns black everywhere must not
/// pass a test whose answer would be black too.
#define REQUIRE_EMITTER_SEEN(what, seen)                                                                     \
    do {                                                                                                      \
        const ::vl::color seen_ = (seen);                                                                     \
        if (!(::vl::stage04::testing::brightest(seen_) > 0.1))                                                \
            FAIL(what << "\n  a ray aimed straight at this emitter (kdr 1 under ambient 1, no lights) "      \
                      << "must see its colour, ambient * clr * kdr; yours is "                               \
                      << ::vl::stage04::testing::show(seen_));                                                \
    } while (false)

namespace vl::stage04::testing {

// ---------------------------------------------------------------------------------------
// Angles and optics (the answer keys)
// ---------------------------------------------------------------------------------------

/// Degrees to radians.
inline double radians(double degrees) { return degrees * std::numbers::pi / 180; }

/// The unit vector at `degrees` from the +y axis towards +x, in the x-y plane:
/// (sin a, cos a, 0). Seen from a floor y = 0 facing up, that is `degrees` from its normal.
inline vector from_vertical(double degrees) {
    return vector(std::sin(radians(degrees)), std::cos(radians(degrees)), 0);
}

/// Schlick's reflectance going from index `eta1` into index `eta2` at incidence cosine
/// `cos_i`, with the cosine on the side of the lower index (stage_04.hh, step 5). 1 for
/// total internal reflection. Computed in `number` (double unless asked for another).
template <class number = double>
number schlick(std::type_identity_t<number> eta1, std::type_identity_t<number> eta2,
               std::type_identity_t<number> cos_i) {
    const number eta = eta1 / eta2, k = 1 - eta * eta * (1 - cos_i * cos_i);
    if (k < 0) return 1;
    const number cos = eta1 <= eta2 ? cos_i : std::sqrt(k);
    const number r0 = ((eta1 - eta2) / (eta1 + eta2)) * ((eta1 - eta2) / (eta1 + eta2));
    return r0 + (1 - r0) * std::pow(1 - cos, 5);
}

/// The exact Fresnel reflectance for unpolarised light (the mean of the s and p parts),
/// also accepted by the contract. 1 for total internal reflection. Computed in `number`.
template <class number = double>
number fresnel_exact(std::type_identity_t<number> eta1, std::type_identity_t<number> eta2,
                     std::type_identity_t<number> cos_i) {
    const number eta = eta1 / eta2, k = 1 - eta * eta * (1 - cos_i * cos_i);
    if (k < 0) return 1;
    const number cos_t = std::sqrt(k);
    const number rs = (eta1 * cos_i - eta2 * cos_t) / (eta1 * cos_i + eta2 * cos_t);
    const number rp = (eta2 * cos_i - eta1 * cos_t) / (eta2 * cos_i + eta1 * cos_t);
    return (rs * rs + rp * rp) / 2;
}

// ---------------------------------------------------------------------------------------
// The tests' own objects
// ---------------------------------------------------------------------------------------

/// \brief A sphere whose hits are computed in long double. Its surface values are the
/// vl::surface it is given (`{.clr = ..., .kdr = ...}`); contains() is true strictly inside.
///
/// With `open_towards` not zero it is a bowl: the half of the surface on that side of the
/// centre is left out (no hits there), while contains() is still true in the whole ball.
/// A test uses it to look at the inside of a sphere along a path that meets nothing else.
class test_sphere final : public stage02::testing::test_ball<primitive> {
public:
    test_sphere(const point& center, double radius, const surface& looks = {},
                const vector& open_towards = vector(0, 0, 0))
        : test_ball(center, radius), open_(open_towards) {
        set_surface(looks);
    }
    std::string type_name() const override { return "TEST_SPHERE"; }

private:
    intersection find_intersection(const ray& r) const override {
        using ld = long double;
        const stage02::testing::sphere_roots h = stage02::testing::roots_in_long_double(center_, radius_, r);
        if (!h.meets) return intersection::none();
        const point o = r.origin().homogenized();
        const vector d = r.direction();
        const ld ox = ld(o.x) - center_.x, oy = ld(o.y) - center_.y, oz = ld(o.z) - center_.z;
        const ld limit = std::fabs(zero_t());
        for (const ld t : {h.t1, h.t2}) {
            const ld side = (ox + t * d.x) * open_.x + (oy + t * d.y) * open_.y + (oz + t * d.z) * open_.z;
            if (t > limit && !(side > 0)) return intersection::at(static_cast<double>(t), this);
        }
        return intersection::none();
    }

    vector open_;
};

/// \brief An infinite plane through `on` with the unit normal `normal` (made unit here),
/// hit in long double. contains() is false unless `solid`: then the plane is the top of
/// a solid that fills everything on the side its normal points away from (see
/// glass_below()), and contains(p) is true strictly on that side.
class test_plane final : public primitive {
public:
    test_plane(const point& on, const vector& normal, const surface& looks = {}, bool solid = false)
        : on_(on), normal_(normal.unit()), solid_(solid) {
        set_surface(looks);
    }
    std::string type_name() const override { return solid_ ? "TEST_SOLID" : "TEST_PLANE"; }
    vector normal(const point&) const override { return normal_; }
    bool contains(const point& p) const override { return solid_ && (p.homogenized() - on_) * normal_ < 0; }

private:
    intersection find_intersection(const ray& r) const override {
        using ld = long double;
        const point o = r.origin().homogenized();
        const vector d = r.direction();
        const ld dn = ld(d.x) * normal_.x + ld(d.y) * normal_.y + ld(d.z) * normal_.z;
        if (dn == 0) return intersection::none();
        const ld along = (ld(on_.x) - o.x) * normal_.x + (ld(on_.y) - o.y) * normal_.y + (ld(on_.z) - o.z) * normal_.z;
        const ld t = along / dn;
        if (t > std::fabs(zero_t())) return intersection::at(static_cast<double>(t), this);
        return intersection::none();
    }

    point on_;
    vector normal_;
    bool solid_;
};

/// The floor y = 0 facing up (+y), with the given surface; contains() is false.
inline std::unique_ptr<test_plane> floor_plane(const surface& looks = {}, double height = 0) {
    return std::make_unique<test_plane>(point(0, height, 0), vector(0, 1, 0), looks);
}

/// Glass (or any material) filling all of y < 0: its surface is the plane y = 0 with the
/// normal +y pointing out into the air, and contains(p) is true for p.y < 0.
inline std::unique_ptr<test_plane> glass_below(const surface& looks) {
    return std::make_unique<test_plane>(point(0, 0, 0), vector(0, 1, 0), looks, true);
}

/// An object that sends back exactly `c` when the scene has ambient (1, 1, 1) and no
/// lights: ambient * c * kdr with kdr 1, and nothing else.
inline surface emitter(const color& c) { return {.clr = c, .kdr = 1}; }

/// An object that sends back nothing whatever the light: black (clr (0, 0, 0)), so every
/// term, ambient * clr * kdr among them, is 0. A ray that should see nothing ends on one.
inline surface absorber() { return {.clr = color(0, 0, 0)}; }

/// \brief A scene root that, like a bounding volume, answers composite_only(this)
/// (intersection rule 2) when a ray passes within `radius` of `center` but hits none of
/// its children. (The scene's plain LIST root never does; this one lets a test show your
/// tracer a composite_only answer.)
class bounded_root final : public object_list {
public:
    bounded_root(const point& center, double radius) : center_(center), radius_(radius) {}
    std::string type_name() const override { return "TEST_BOUNDED_LIST"; }

private:
    intersection find_intersection(const ray& r) const override {
        const intersection i = nearest_child_hit(r);
        if (i.hit()) return i;
        if (stage02::testing::passes_within(r, center_, radius_)) return intersection::composite_only(this);
        return intersection::none();
    }
    point center_;
    double radius_;
};

// ---------------------------------------------------------------------------------------
// Scenes and tracing
// ---------------------------------------------------------------------------------------

/// Every piece this build links (the tracer `whitted` among them).
using stage02::testing::pieces;

/// \brief A scene built in a test: no lights, no ambient, a black background (unlike a
/// scene file's defaults), so each test switches on only what it looks at.
struct test_scene {
    scene s;

    test_scene() {
        s.ambient = BLACK;
        s.background = BLACK;
    }

    /// Puts `object` into the scene's root and returns it (still owned by the scene).
    template <class Object>
    Object* add(std::unique_ptr<Object> object) {
        Object* raw = object.get();
        s.root->insert(std::move(object));
        return raw;
    }
    /// Adds a point light of colour `c` at `position`.
    void light(const color& c, const point& position) { s.lights.push_back(color_point(c, position)); }

    /// What the tracer `whitted` (your whitted.cc) returns for `r` at `depth`.
    color trace(const ray& r, int depth = 0) const { return pieces().make_tracer("whitted", s)->trace(r, depth); }
};

/// Reads a scene from `text` as if it were the file `test.ray_trace`, with every piece
/// this build links.
inline scene read_scene_text(const std::string& text) { return parse_scene(text, "test.ray_trace", pieces()); }

/// What the tracer `whitted` returns for `r` at `depth` in the scene `s`.
inline color trace_in(const scene& s, const ray& r, int depth = 0) {
    return pieces().make_tracer("whitted", s)->trace(r, depth);
}

/// `looks` made dull: the same colour and kdr, but no mirror and no glass (ksr = kst = 0).
/// The baseline a bounce test subtracts: what the surface sends back without bouncing.
inline surface dull(surface looks) {
    looks.ksr = 0;
    looks.kst = 0;
    return looks;
}

/// What the bounces add to `r` at `depth`: `with` (the scene with its mirror or glass)
/// minus `without` (the same scene with that object dull()).
inline color bounce_part(const test_scene& with, const test_scene& without, const ray& r, int depth) {
    return with.trace(r, depth) - without.trace(r, depth);
}

/// The largest of red, green and blue.
inline double brightest(const color& c) { return std::fmax(c.r, std::fmax(c.g, c.b)); }

/// True when the two colours are the same bit for bit (so two NaNs of the same bits
/// count as the same, unlike `==`).
inline bool same_bits(const color& x, const color& y) {
    return std::memcmp(&x.r, &y.r, sizeof x.r) == 0 && std::memcmp(&x.g, &y.g, sizeof x.g) == 0 &&
           std::memcmp(&x.b, &y.b, sizeof x.b) == 0 && std::memcmp(&x.a, &y.a, sizeof x.a) == 0;
}

}  // namespace vl::stage04::testing
