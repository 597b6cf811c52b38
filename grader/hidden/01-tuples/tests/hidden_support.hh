#pragma once
// Helpers shared by stage 01's hidden tests (grader only): long-double answer keys that
// use none of the submission's functions, seeded inputs, and a tally that keeps the report
// of a loop short (the first few failing inputs, then a count).

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <random>
#include <sstream>
#include <string>

#include "01-tuples/tests/test_support.hh"
#include "grading.hh"
#include "stage_01.hh"
#include "vl/error.hh"

namespace vl::stage01::hidden {

using ld = long double;
using vl::grading::num;
using vl::grading::show;

inline constexpr ld pi_l = 3.141592653589793238462643383279502884L;
inline constexpr double pi = std::numbers::pi;
/// The unit round-off of double, 2^-53.
inline constexpr double u = 0x1p-53;

// --- a short report of a loop -----------------------------------------------------------

/// Counts the inputs a loop checks and the ones that fail; only the first `shown` failures
/// are reported one by one, the rest as a count at the end (finish()).
class tally {
public:
    explicit tally(int shown = 3) : shown_(shown) {}
    void checked() { ++checked_; }
    /// Records a failure; true when it is one of the first few, to be reported in full.
    bool report() { return ++failed_ <= shown_; }
    int failed() const { return failed_; }
    /// Ends the loop: a pass counts as an assertion; failures beyond the first few are
    /// counted in one line.
    void finish(const std::string& what) const {
        if (failed_ == 0) {
            SUCCEED();
        } else if (failed_ > shown_) {
            FAIL_CHECK("... and " << failed_ - shown_ << " more: " << failed_ << " of the " << checked_ << " "
                                  << what << " failed");
        }
    }

private:
    int shown_;
    int checked_ = 0;
    int failed_ = 0;
};

/// One check of a loop: counted in `t`; when it fails, `message` is reported if it is one
/// of the first few failures (and evaluated only then).
#define VL_CHECK_EACH(t, condition, message)           \
    do {                                               \
        (t).checked();                                 \
        if (!(condition) && (t).report()) {            \
            FAIL_CHECK(message);                       \
        }                                              \
    } while (false)

// --- long-double 3-vectors ----------------------------------------------------------------

struct vec3 {
    ld x = 0, y = 0, z = 0;
};
inline vec3 operator+(const vec3& a, const vec3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline vec3 operator-(const vec3& a, const vec3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline vec3 operator-(const vec3& a) { return {-a.x, -a.y, -a.z}; }
inline vec3 operator*(ld s, const vec3& a) { return {s * a.x, s * a.y, s * a.z}; }
inline vec3 operator*(const vec3& a, ld s) { return s * a; }
inline ld dot(const vec3& a, const vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline vec3 cross(const vec3& a, const vec3& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
/// The length, scaled so that neither 1e200 nor 1e-200 components overflow or underflow.
inline ld length(const vec3& a) {
    const ld m = std::max({std::fabs(a.x), std::fabs(a.y), std::fabs(a.z)});
    if (m == 0) return 0;
    const vec3 s{a.x / m, a.y / m, a.z / m};
    return m * std::sqrt(dot(s, s));
}
inline vec3 unit(const vec3& a) {
    const ld l = length(a);
    return {a.x / l, a.y / l, a.z / l};
}
/// The angle between two directions, accurate also when it is tiny or near 180 degrees.
inline ld angle_between(const vec3& a, const vec3& b) { return std::atan2(length(cross(a, b)), dot(a, b)); }

inline vec3 of(const vector& v) { return {v.x, v.y, v.z}; }
inline vec3 of(const point& p) { return {p.x, p.y, p.z}; }
inline vector to_vector(const vec3& a) {
    return {static_cast<double>(a.x), static_cast<double>(a.y), static_cast<double>(a.z)};
}
inline point to_point(const vec3& a) {
    return {static_cast<double>(a.x), static_cast<double>(a.y), static_cast<double>(a.z)};
}
inline std::string show(const vec3& a) { return show(to_vector(a)); }
/// The largest difference of the components.
inline ld distance(const vec3& a, const vec3& b) {
    return std::max({std::fabs(a.x - b.x), std::fabs(a.y - b.y), std::fabs(a.z - b.z)});
}

// --- long-double 4x4 matrices ---------------------------------------------------------------

struct mat4 {
    std::array<std::array<ld, 4>, 4> e{};
    ld& operator()(int r, int c) { return e[static_cast<std::size_t>(r)][static_cast<std::size_t>(c)]; }
    ld operator()(int r, int c) const { return e[static_cast<std::size_t>(r)][static_cast<std::size_t>(c)]; }
};
inline mat4 identity4() {
    mat4 m;
    for (int i = 0; i < 4; ++i) m(i, i) = 1;
    return m;
}
inline mat4 of(const matrix& m) {
    mat4 r;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) r(i, j) = m(i, j);
    return r;
}
inline matrix to_matrix(const mat4& m) {
    matrix r;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) r(i, j) = static_cast<double>(m(i, j));
    return r;
}
inline mat4 operator*(const mat4& a, const mat4& b) {
    mat4 r;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            ld s = 0;
            for (int k = 0; k < 4; ++k) s += a(i, k) * b(k, j);
            r(i, j) = s;
        }
    return r;
}
inline mat4 operator-(const mat4& a, const mat4& b) {
    mat4 r;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) r(i, j) = a(i, j) - b(i, j);
    return r;
}
inline mat4 operator+(const mat4& a, const mat4& b) {
    mat4 r;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) r(i, j) = a(i, j) + b(i, j);
    return r;
}
inline mat4 scaled(ld s, const mat4& a) {
    mat4 r;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) r(i, j) = s * a(i, j);
    return r;
}
inline mat4 transpose(const mat4& a) {
    mat4 r;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) r(i, j) = a(j, i);
    return r;
}
/// The infinity norm: the largest sum of absolute values along a row; NaN when any
/// element is NaN (so an error measured with it never hides a NaN).
inline ld norm(const mat4& m) {
    ld n = 0;
    for (int i = 0; i < 4; ++i) {
        const ld row = std::fabs(m(i, 0)) + std::fabs(m(i, 1)) + std::fabs(m(i, 2)) + std::fabs(m(i, 3));
        if (!(row <= n)) n = row;  // also takes a NaN, which then stays
        if (std::isnan(n)) return n;
    }
    return n;
}
/// `m` applied to the point (w = 1) or the vector (w = 0) `a`: x, y, z and w.
inline std::array<ld, 4> apply(const mat4& m, const vec3& a, ld w) {
    std::array<ld, 4> r{};
    for (int i = 0; i < 4; ++i)
        r[static_cast<std::size_t>(i)] = m(i, 0) * a.x + m(i, 1) * a.y + m(i, 2) * a.z + m(i, 3) * w;
    return r;
}

/// The inverse of the double matrix `m`, in long double: Gauss-Jordan with complete
/// pivoting, then two steps of iterative refinement against `m` itself. Good to about
/// κ(m) · 1e-19 for the matrices of these tests, far below the bound they check.
inline mat4 exact_inverse(const matrix& md) {
    const mat4 m = of(md);
    mat4 a = m, x = identity4();
    std::array<int, 4> col{0, 1, 2, 3};
    for (int k = 0; k < 4; ++k) {
        int pr = k, pc = k;
        for (int r = k; r < 4; ++r)
            for (int c = k; c < 4; ++c)
                if (std::fabs(a(r, c)) > std::fabs(a(pr, pc))) pr = r, pc = c;
        for (int c = 0; c < 4; ++c) std::swap(a(k, c), a(pr, c)), std::swap(x(k, c), x(pr, c));
        for (int r = 0; r < 4; ++r) std::swap(a(r, k), a(r, pc));
        std::swap(col[static_cast<std::size_t>(k)], col[static_cast<std::size_t>(pc)]);
        const ld p = a(k, k);
        for (int c = 0; c < 4; ++c) a(k, c) /= p, x(k, c) /= p;
        for (int r = 0; r < 4; ++r) {
            if (r == k) continue;
            const ld f = a(r, k);
            for (int c = 0; c < 4; ++c) a(r, c) -= f * a(k, c), x(r, c) -= f * x(k, c);
        }
    }
    // Column swaps of a are row swaps of its inverse.
    mat4 inv;
    for (int k = 0; k < 4; ++k)
        for (int c = 0; c < 4; ++c) inv(col[static_cast<std::size_t>(k)], c) = x(k, c);
    for (int step = 0; step < 2; ++step) inv = inv + inv * (identity4() - m * inv);
    return inv;
}

/// ‖x − exact‖∞ / ‖exact‖∞ in long double.
inline ld relative_error(const matrix& x, const mat4& exact) { return norm(of(x) - exact) / norm(exact); }

/// True when every element of `m` is NaN (the public tests' helper).
using test01::all_nan;

// --- seeded inputs --------------------------------------------------------------------------

/// Seeded random inputs: the same numbers on every run.
class inputs {
public:
    explicit inputs(std::uint64_t seed) : engine_(seed) {}
    double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(engine_); }
    int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(engine_); }
    /// 10^e with e uniform in [lo, hi].
    double log_uniform(double lo, double hi) { return std::pow(10.0, uniform(lo, hi)); }
    vector direction() {
        const double z = uniform(-1, 1), phi = uniform(0, 2 * pi);
        const double s = std::sqrt(1 - z * z);
        return {s * std::cos(phi), s * std::sin(phi), z};
    }
    vector in_box(double s) { return {uniform(-s, s), uniform(-s, s), uniform(-s, s)}; }
    point point_in_box(double s) { return {uniform(-s, s), uniform(-s, s), uniform(-s, s)}; }
    /// A random orthogonal matrix, in long double (Gram-Schmidt, twice).
    mat4 orthogonal() {
        mat4 q;
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j) q(i, j) = uniform(-1, 1);
        for (int pass = 0; pass < 2; ++pass)
            for (int j = 0; j < 4; ++j) {
                for (int k = 0; k < j; ++k) {
                    ld d = 0;
                    for (int i = 0; i < 4; ++i) d += q(i, j) * q(i, k);
                    for (int i = 0; i < 4; ++i) q(i, j) -= d * q(i, k);
                }
                ld n = 0;
                for (int i = 0; i < 4; ++i) n += q(i, j) * q(i, j);
                n = std::sqrt(n);
                for (int i = 0; i < 4; ++i) q(i, j) /= n;
            }
        return q;
    }
    std::mt19937_64& engine() { return engine_; }

private:
    std::mt19937_64 engine_;
};

// --- answer keys for the transforms and the camera -----------------------------------------------

/// Rodrigues' rotation matrix (long double) about the unit axis `a` by `radians`.
inline mat4 rodrigues(const vec3& a, ld radians) {
    const ld c = std::cos(radians), s = std::sin(radians), h = std::sin(radians / 2), t = 2 * h * h;
    mat4 r = identity4();
    r(0, 0) = t * a.x * a.x + c, r(0, 1) = t * a.x * a.y - s * a.z, r(0, 2) = t * a.x * a.z + s * a.y;
    r(1, 0) = t * a.x * a.y + s * a.z, r(1, 1) = t * a.y * a.y + c, r(1, 2) = t * a.y * a.z - s * a.x;
    r(2, 0) = t * a.x * a.z - s * a.y, r(2, 1) = t * a.y * a.z + s * a.x, r(2, 2) = t * a.z * a.z + c;
    return r;
}

/// The size of the terms that make up each element of rodrigues(a, radians): what its
/// rounding error is measured against. Diagonal elements are near 1 in size whatever the
/// angle (c + t a_i^2 is also 1 - t (1 - a_i^2)).
inline mat4 rodrigues_scale(const vec3& a, ld radians) {
    const ld s = std::fabs(std::sin(radians)), h = std::sin(radians / 2), t = 2 * h * h;
    const ld ax = std::fabs(a.x), ay = std::fabs(a.y), az = std::fabs(a.z);
    mat4 r;
    for (int i = 0; i < 3; ++i) r(i, i) = 1 + t;
    r(0, 1) = r(1, 0) = t * ax * ay + s * az;
    r(0, 2) = r(2, 0) = t * ax * az + s * ay;
    r(1, 2) = r(2, 1) = t * ay * az + s * ax;
    return r;
}

/// The eye's frame: unit right, up and forward (towards look_at), in long double.
struct frame {
    vec3 right, up, forward;
};
inline frame eye_frame(const point& eye, const point& look_at, const vector& up) {
    frame f;
    f.forward = unit(of(look_at) - of(eye));
    f.right = unit(cross(f.forward, of(up)));
    f.up = cross(f.right, f.forward);
    return f;
}

/// The view matrix of (eye, look_at, up), in long double: rows right, up, backwards, and
/// the translation that takes the eye to the origin.
inline mat4 view_matrix(const point& eye, const point& look_at, const vector& up) {
    const frame f = eye_frame(eye, look_at, up);
    const vec3 e = of(eye), back = -f.forward;
    mat4 m = identity4();
    const vec3 rows[3] = {f.right, f.up, back};
    for (int i = 0; i < 3; ++i) {
        const vec3& r = rows[i];
        m(i, 0) = r.x, m(i, 1) = r.y, m(i, 2) = r.z, m(i, 3) = -dot(r, e);
    }
    return m;
}

/// The sine of the angle between `up` and the view direction.
inline ld sine_up_view(const point& eye, const point& look_at, const vector& up) {
    const vec3 f = unit(of(look_at) - of(eye)), v = unit(of(up));
    return length(cross(f, v));
}

/// The pinhole model, in long double: the unit direction of the ray through image position
/// (x, y) of a width x height image, (0, 0) at the lower left, fov across the height.
struct pinhole {
    frame f;
    ld pixel = 0;  ///< one pixel's side on the image plane at distance 1
    ld half_width = 0, half_height = 0;
    vec3 eye;

    pinhole(const camera_settings& s, int width, int height)
        : f(eye_frame(s.eye, s.look_at, s.up)),
          pixel(2 * std::tan(static_cast<ld>(s.fov_degrees) * pi_l / 360) / height),
          half_width(static_cast<ld>(width) / 2),
          half_height(static_cast<ld>(height) / 2),
          eye(of(s.eye)) {}

    /// Relative to the eye, on the image plane one unit in front of it.
    vec3 on_plane(ld x, ld y) const {
        return f.forward + ((x - half_width) * pixel) * f.right + ((y - half_height) * pixel) * f.up;
    }
    vec3 direction(ld x, ld y) const { return unit(on_plane(x, y)); }
};

using test01::settings;

/// "eye (..) look_at (..) up (..) fov F on a W x H image", for messages.
inline std::string describe(const camera_settings& s, int width, int height) {
    std::ostringstream o;
    o << "the camera with eye " << show(s.eye) << ", look_at " << show(s.look_at) << ", up " << show(s.up)
      << " and fov " << num(s.fov_degrees) << " on a " << width << " x " << height << " image";
    return o.str();
}

/// Where a ray meets the plane one unit in front of the eye along `forward`, relative to
/// the eye (the image plane, whatever the length of the ray's direction).
inline vec3 on_plane(const ray& r, const vec3& forward) {
    const vec3 d = of(r.direction());
    return (1 / dot(d, forward)) * d;
}

}  // namespace vl::stage01::hidden
