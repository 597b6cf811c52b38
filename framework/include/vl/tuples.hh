#pragma once
/// \file
/// \brief Homogeneous colours, vectors and points: the thesis's `tuples`.
///
/// The operators let shading code read like the equation on the page:
/// `dif += (N * L) * light.clr();`. Every tuple carries four doubles. The thesis's
/// operator tables (User's Manual, "tuples and tuples_based") are implemented in full;
/// the table is reproduced at each class.
///
/// Quiet NaNs flow through every operation without raising a floating-point exception:
/// nothing here uses an ordered comparison (`<`, `>`) on a value that may be NaN.

#include <cmath>
#include <iosfwd>
#include <limits>

namespace vl {

/// A quiet NaN, the value of "undefined" throughout the framework.
inline constexpr double NaN = std::numeric_limits<double>::quiet_NaN();

/// \brief An RGBA colour; channels are linear and usually within [0, 1].
///
/// | expression | result | meaning |
/// |---|---|---|
/// | `c + c`, `c - c` | color | channel-wise |
/// | `c * d`, `d * c`, `c / d` | color | scale every channel |
/// | `c * c` | color | channel-wise product (a filter), **not** a dot product |
/// | `c += c`, `c -= c`, `c *= d`, `c /= d` | color& | in place |
/// | `c == c`, `c != c` | bool | exact, all four channels |
class color {
public:
    double r = 0;  ///< red
    double g = 0;  ///< green
    double b = 0;  ///< blue
    double a = 0;  ///< alpha (opacity); 0 in every colour the framework defines

    /// Black: all four channels 0.
    constexpr color() = default;
    /// The colour (`red`, `green`, `blue`), with alpha 0 unless given.
    constexpr color(double red, double green, double blue, double alpha = 0)
        : r(red), g(green), b(blue), a(alpha) {}

    /// \name In-place arithmetic
    ///@{

    /// Channel-wise, like the binary operator; returns `*this`.
    constexpr color& operator+=(const color& c) { r += c.r; g += c.g; b += c.b; a += c.a; return *this; }
    constexpr color& operator-=(const color& c) { r -= c.r; g -= c.g; b -= c.b; a -= c.a; return *this; }
    constexpr color& operator*=(double d) { r *= d; g *= d; b *= d; a *= d; return *this; }
    constexpr color& operator/=(double d) { r /= d; g /= d; b /= d; a /= d; return *this; }
    ///@}

    /// \name Arithmetic
    ///@{

    /// Channel-wise sum and difference; scaling of every channel by a number.
    friend constexpr color operator+(color x, const color& y) { return x += y; }
    friend constexpr color operator-(color x, const color& y) { return x -= y; }
    friend constexpr color operator*(color x, double d) { return x *= d; }
    friend constexpr color operator*(double d, color x) { return x *= d; }
    friend constexpr color operator/(color x, double d) { return x /= d; }
    ///@}
    /// Channel-wise product: `c` seen through the filter `f` is `c * f`. Not a dot product.
    friend constexpr color operator*(const color& x, const color& y) {
        return {x.r * y.r, x.g * y.g, x.b * y.b, x.a * y.a};
    }
    /// Exact comparison of all four channels (`!=` is generated from it).
    friend constexpr bool operator==(const color&, const color&) = default;
};

/// \brief A direction or displacement; `w` is 0 for a true vector.
///
/// | expression | result | meaning |
/// |---|---|---|
/// | `v + v`, `v - v`, `-v` | vector | component-wise |
/// | `v * d`, `d * v`, `v / d` | vector | scale |
/// | `v * v` | double | **dot product** of x, y, z |
/// | `v % v` | vector | **cross product** |
/// | `v += v`, `v -= v`, `v *= d`, `v /= d`, `v %= v` | vector& | in place |
/// | `v.unit()` | vector | same direction, length 1 |
/// | `v.length()` | double | Euclidean length of x, y, z |
/// | `v == v`, `v != v` | bool | exact, all four components |
class vector {
public:
    double x = 0;  ///< x component
    double y = 0;  ///< y component
    double z = 0;  ///< z component
    double w = 0;  ///< homogeneous flag: 0 for a direction

    /// The zero vector.
    constexpr vector() = default;
    /// The vector (`vx`, `vy`, `vz`), with w 0 unless given.
    constexpr vector(double vx, double vy, double vz, double vw = 0) : x(vx), y(vy), z(vz), w(vw) {}

    /// \name In-place arithmetic
    ///@{

    /// Like the binary operator of the same name; returns `*this`.
    constexpr vector& operator+=(const vector& v) { x += v.x; y += v.y; z += v.z; w += v.w; return *this; }
    constexpr vector& operator-=(const vector& v) { x -= v.x; y -= v.y; z -= v.z; w -= v.w; return *this; }
    constexpr vector& operator*=(double d) { x *= d; y *= d; z *= d; w *= d; return *this; }
    constexpr vector& operator/=(double d) { x /= d; y /= d; z /= d; w /= d; return *this; }
    constexpr vector& operator%=(const vector& v) { return *this = *this % v; }
    ///@}

    /// Length of the x, y, z part (w is a homogeneous flag, not a dimension).
    double length() const { return std::sqrt(x * x + y * y + z * z); }
    /// The vector of length 1 in the same direction. The zero vector has no direction:
    /// its unit() is NaN in every component, which later tests can see.
    vector unit() const {
        const double len = length();
        return len == 0 ? vector(NaN, NaN, NaN, NaN) : vector(x / len, y / len, z / len, w);
    }

    /// \name Arithmetic
    ///@{

    /// Component-wise sum, difference and negation; scaling by a number.
    friend constexpr vector operator+(vector a, const vector& b) { return a += b; }
    friend constexpr vector operator-(vector a, const vector& b) { return a -= b; }
    friend constexpr vector operator-(const vector& a) { return {-a.x, -a.y, -a.z, -a.w}; }
    friend constexpr vector operator*(vector a, double d) { return a *= d; }
    friend constexpr vector operator*(double d, vector a) { return a *= d; }
    friend constexpr vector operator/(vector a, double d) { return a /= d; }
    ///@}
    /// Dot product.
    friend constexpr double operator*(const vector& a, const vector& b) {
        return a.x * b.x + a.y * b.y + a.z * b.z;
    }
    /// Cross product (right-handed: `POS_X % POS_Y == POS_Z`).
    friend constexpr vector operator%(const vector& a, const vector& b) {
        return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x, 0};
    }
    /// Exact comparison of all four components (`!=` is generated from it).
    friend constexpr bool operator==(const vector&, const vector&) = default;
};

/// \brief A location; `w` is 1 for an ordinary (homogenized) point.
///
/// | expression | result | meaning |
/// |---|---|---|
/// | `p + v`, `p - v` | point | move by a vector |
/// | `p - p` | vector | displacement between two points |
/// | `p += v`, `p -= v` | point& | in place |
/// | `p == p`, `p != p` | bool | compare the **homogenized** coordinates |
/// | `p.homogenized()` | point | `point(x/w, y/w, z/w, 1)` |
///
/// The thesis's *protected* point operations (scaling, dot and cross products of points)
/// exist only so a matrix can treat points as column vectors. They live in
/// vl::homogeneous and are opt-in: see there.
class point {
public:
    double x = 0;  ///< x coordinate
    double y = 0;  ///< y coordinate
    double z = 0;  ///< z coordinate
    double w = 1;  ///< homogeneous weight: 1 for an ordinary point

    /// The origin `(0, 0, 0, 1)`.
    constexpr point() = default;
    /// The point (`px`, `py`, `pz`), with w 1 unless given.
    constexpr point(double px, double py, double pz, double pw = 1) : x(px), y(py), z(pz), w(pw) {}

    /// `point(x/w, y/w, z/w, 1)`. A point at infinity (w == 0) has no homogenized form:
    /// the result is infinite or NaN.
    constexpr point homogenized() const { return {x / w, y / w, z / w, 1}; }

    /// \name Moving a point
    ///@{

    /// Moves the point by the vector `v` (all four components, so w gains v's w).
    constexpr point& operator+=(const vector& v) { x += v.x; y += v.y; z += v.z; w += v.w; return *this; }
    constexpr point& operator-=(const vector& v) { x -= v.x; y -= v.y; z -= v.z; w -= v.w; return *this; }

    friend constexpr point operator+(point p, const vector& v) { return p += v; }
    friend constexpr point operator-(point p, const vector& v) { return p -= v; }
    ///@}
    /// The vector from `q` to `p`: `q + (p - q) == p`.
    friend constexpr vector operator-(const point& p, const point& q) {
        return {p.x - q.x, p.y - q.y, p.z - q.z, p.w - q.w};
    }
    /// Compares the homogenized x, y, z, so `point(2, 4, 6, 2) == point(1, 2, 3)`
    /// (`!=` is generated from it).
    friend constexpr bool operator==(const point& p, const point& q) {
        const point a = p.homogenized(), b = q.homogenized();
        return a.x == b.x && a.y == b.y && a.z == b.z;
    }
};

/// Names for the indices of VECTOR_DIRECTION.
enum direction { NEG_Z, POS_Z, NEG_Y, POS_Y, NEG_X, POS_X, NO_DIRECTION };

inline constexpr color BLACK{0, 0, 0, 0};                  ///< no light at all
inline constexpr color WHITE{1, 1, 1, 0};                  ///< full intensity in r, g and b
inline constexpr color NaN_color{NaN, NaN, NaN, NaN};      ///< the undefined colour
inline constexpr vector NaN_vector{NaN, NaN, NaN, NaN};    ///< the undefined vector
inline constexpr point NaN_point{NaN, NaN, NaN, NaN};      ///< the undefined point
/// The six axis directions and the zero vector, indexed by vl::direction.
inline constexpr vector VECTOR_DIRECTION[] = {
    {0, 0, -1}, {0, 0, 1}, {0, -1, 0}, {0, 1, 0}, {-1, 0, 0}, {1, 0, 0}, {0, 0, 0}};

/// \name Undefined values
///@{

/// True when any component is NaN (the framework's "undefined").
inline bool is_nan(const color& c) { return std::isnan(c.r) || std::isnan(c.g) || std::isnan(c.b) || std::isnan(c.a); }
inline bool is_nan(const vector& v) { return std::isnan(v.x) || std::isnan(v.y) || std::isnan(v.z) || std::isnan(v.w); }
inline bool is_nan(const point& p) { return std::isnan(p.x) || std::isnan(p.y) || std::isnan(p.z) || std::isnan(p.w); }
///@}

/// \brief The thesis's protected point operations, for code that treats points as
/// column vectors (class matrix, and tests).
///
/// Each converts its point operands to vectors as if `point(0, 0, 0, 1)` had been
/// subtracted, and a point result back by adding that origin again. They make no
/// geometric sense for ordinary code ("twice a location"?), which is why the thesis hid
/// them; here they are found only after `using namespace vl::homogeneous;`.
namespace homogeneous {
/// The point as a displacement from the origin, w reduced by 1 (`p - point(0,0,0,1)`).
constexpr vector as_vector(const point& p) { return {p.x, p.y, p.z, p.w - 1}; }
/// The point `point(0,0,0,1) + v`.
constexpr point as_point(const vector& v) { return {v.x, v.y, v.z, v.w + 1}; }

/// \name Scaling a point
///@{

/// Scales the point's displacement from the origin: `p * d` is `as_point(as_vector(p) * d)`.
constexpr point operator*(const point& p, double d) { return as_point(as_vector(p) * d); }
constexpr point operator*(double d, const point& p) { return p * d; }
constexpr point operator/(const point& p, double d) { return as_point(as_vector(p) / d); }
///@}

/// \name Dot products with points
///@{

/// The dot product of the operands' displacements from the origin (see as_vector()).
constexpr double operator*(const point& p, const vector& v) { return as_vector(p) * v; }
constexpr double operator*(const vector& v, const point& p) { return v * as_vector(p); }
constexpr double operator*(const point& p, const point& q) { return as_vector(p) * as_vector(q); }
///@}

/// \name Cross products with points
///@{

/// The cross product of the operands' displacements from the origin, made a point again:
/// `p % q` is `as_point(as_vector(p) % as_vector(q))`.
constexpr point operator%(const point& p, const point& q) { return as_point(as_vector(p) % as_vector(q)); }
constexpr point operator%(const vector& v, const point& p) { return as_point(v % as_vector(p)); }
///@}

/// \name In-place point operations
///@{

/// `p *= d` is `p = p * d`, `p /= d` is `p = p / d`, `p %= v` crosses p's displacement
/// from the origin with `v`; each returns `p`.
constexpr point& operator*=(point& p, double d) { return p = p * d; }
constexpr point& operator/=(point& p, double d) { return p = p / d; }
constexpr point& operator%=(point& p, const vector& v) { return p = as_point(as_vector(p) % v); }
///@}
}  // namespace homogeneous

/// \name Stream input and output
/// `<<` writes `color (r, g, b, a)`, `vector (x, y, z, w)` or `point (x, y, z, w)` with
/// full round-trip precision. `>>` reads an optional alphabetic label (ignored, as in
/// the thesis: `center 0 0 0 1`) and then four numbers, either separated by white space
/// or in the written form `(x, y, z, w)`, so whatever `<<` wrote `>>` reads back. On
/// malformed input it sets `failbit` and leaves the tuple unchanged.
///@{

/// Writes or reads one tuple in the text form described above for the group.
std::ostream& operator<<(std::ostream& s, const color& c);
std::ostream& operator<<(std::ostream& s, const vector& v);
std::ostream& operator<<(std::ostream& s, const point& p);
std::istream& operator>>(std::istream& s, color& c);
std::istream& operator>>(std::istream& s, vector& v);
std::istream& operator>>(std::istream& s, point& p);
///@}

}  // namespace vl
