// Unit tests of the tuples (color, vector, point) and the tuples_based types (color_point,
// matrix): every operator of the thesis's tables (User's Manual, "tuples and tuples_based"),
// the constants, stream input and output, and algebraic properties checked over random inputs.
//
// Two conventions differ from the thesis, on purpose (see vl/tuples_based.hh):
//  - column vectors: the thesis writes `p * m` and `r * m`; we write `m * p` and `m * r`;
//  - the thesis's "protected" point operations live in vl::homogeneous and are found only
//    after `using namespace vl::homogeneous;`.
#include "vl/catch.hh"

#include <bit>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <limits>
#include <random>
#include <sstream>
#include <string>

#include "vl/ray.hh"
#include "vl/tuples.hh"
#include "vl/tuples_based.hh"

using vl::color;
using vl::color_point;
using vl::matrix;
using vl::point;
using vl::vector;

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

// ---------------------------------------------------------------------------------------
// Helpers for the property tests.
//
// Floating-point rounding makes algebraic identities such as (A * B) * p == A * (B * p)
// hold only approximately. The rounding error of a sum of products grows with the size of
// the *terms*, not with the size of the result, which may be close to zero (a dot product
// of perpendicular vectors, the determinant of a nearly singular matrix). So every
// tolerance below is relative to the magnitude of the operands, never to the result:
// |computed - expected| <= tolerance * scale, where scale is, e.g., |a| |b|.
// ---------------------------------------------------------------------------------------

/// About 4500 units in the last place of a double: far above the rounding error of these
/// short computations, far below any error a wrong formula would make.
constexpr double tolerance = 1e-12;

/// `|a - b| <= tolerance * scale`.
bool near(double a, double b, double scale) { return std::abs(a - b) <= tolerance * scale; }

double magnitude(const point& p) { return std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z + p.w * p.w); }
/// The Frobenius norm: the square root of the sum of the squares of the 16 elements.
double magnitude(const matrix& m) {
    double sum = 0;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) sum += m(r, c) * m(r, c);
    return std::sqrt(sum);
}

/// All four components of `a` and `b` agree to within tolerance * scale.
bool near(const point& a, const point& b, double scale) {
    return near(a.x, b.x, scale) && near(a.y, b.y, scale) && near(a.z, b.z, scale) && near(a.w, b.w, scale);
}
bool near(const matrix& a, const matrix& b, double scale) {
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c)
            if (!near(a(r, c), b(r, c), scale)) return false;
    return true;
}

/// Random inputs from a fixed seed, so a failure is reproducible.
class random_tuples {
public:
    /// A value in [-10, 10).
    double value() { return std::uniform_real_distribution<double>(-10, 10)(engine_); }
    vector any_vector() { return {value(), value(), value(), 0}; }
    point any_point() { return {value(), value(), value(), 1}; }
    matrix any_matrix() {
        matrix m;
        for (int r = 0; r < 4; ++r)
            for (int c = 0; c < 4; ++c) m(r, c) = value();
        return m;
    }
    /// Any finite double at all (any sign, exponent and mantissa, subnormals included):
    /// what a stream round trip must reproduce bit for bit.
    double any_finite_double() {
        for (;;) {
            const double d = std::bit_cast<double>(engine_());
            if (std::isfinite(d)) return d;
        }
    }
    /// A vector whose components differ in size by up to 2^40 in either direction.
    vector wide_vector() {
        std::uniform_int_distribution<int> exponent(-40, 40);
        return {std::ldexp(value(), exponent(engine_)), std::ldexp(value(), exponent(engine_)),
                std::ldexp(value(), exponent(engine_)), 0};
    }

private:
    std::mt19937_64 engine_{20240601};
};

constexpr int iterations = 1000;

/// True when `a` and `b` hold the same bits (so NaN payloads and -0.0 count).
bool same_bits(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }

template <class T>
std::string written(const T& t) {
    std::ostringstream s;
    s << t;
    return s.str();
}

/// Reads a T from `text`; `ok` tells whether the stream was still good afterwards.
template <class T>
T read(const std::string& text, T start, bool& ok) {
    std::istringstream s(text);
    s >> start;
    ok = !s.fail();
    return start;
}

}  // namespace

// =======================================================================================
// color
// =======================================================================================

TEST_CASE("color: the alpha channel defaults to 0", "[tuples][color]") {
    const color c(0.25, 0.5, 0.75);
    CHECK(c.r == 0.25);
    CHECK(c.g == 0.5);
    CHECK(c.b == 0.75);
    CHECK(c.a == 0);
    CHECK(color() == color(0, 0, 0, 0));
}

TEST_CASE("color: addition and subtraction work channel by channel", "[tuples][color]") {
    const color a(1, 2, 3, 4), b(0.5, 0.25, 0.125, 1);
    CHECK(a + b == color(1.5, 2.25, 3.125, 5));
    CHECK(a - b == color(0.5, 1.75, 2.875, 3));
}

TEST_CASE("color: scaling by a double scales every channel", "[tuples][color]") {
    const color c(1, 2, 3, 4);
    CHECK(c * 2 == color(2, 4, 6, 8));
    CHECK(2 * c == color(2, 4, 6, 8));
    CHECK(c / 2 == color(0.5, 1, 1.5, 2));
}

TEST_CASE("color: color times color is a channel-wise filter, not a dot product", "[tuples][color]") {
    const color light(1, 0.5, 0.25, 1), surface(0.5, 0.5, 0.5, 0);
    CHECK(light * surface == color(0.5, 0.25, 0.125, 0));
}

TEST_CASE("color: compound assignments change the color in place", "[tuples][color]") {
    color c(1, 2, 3, 4);
    CHECK(&(c += color(1, 1, 1, 1)) == &c);
    CHECK(c == color(2, 3, 4, 5));
    c -= color(2, 2, 2, 2);
    CHECK(c == color(0, 1, 2, 3));
    c *= 4;
    CHECK(c == color(0, 4, 8, 12));
    c /= 2;
    CHECK(c == color(0, 2, 4, 6));
}

TEST_CASE("color: == and != compare all four channels exactly", "[tuples][color]") {
    CHECK(color(1, 2, 3, 4) == color(1, 2, 3, 4));
    CHECK_FALSE(color(1, 2, 3, 4) != color(1, 2, 3, 4));
    CHECK(color(1, 2, 3, 4) != color(1, 2, 3, 5));  // alpha counts
    CHECK(color(1, 2, 3) != color(1, 2, 3.0000000000000004));
}

TEST_CASE("color: BLACK, WHITE and NaN_color have the thesis's values", "[tuples][color][constants]") {
    CHECK(vl::BLACK == color(0, 0, 0, 0));
    CHECK(vl::WHITE == color(1, 1, 1, 0));
    CHECK(std::isnan(vl::NaN_color.r));
    CHECK(std::isnan(vl::NaN_color.g));
    CHECK(std::isnan(vl::NaN_color.b));
    CHECK(std::isnan(vl::NaN_color.a));
    CHECK(vl::is_nan(vl::NaN_color));
    CHECK_FALSE(vl::is_nan(vl::WHITE));
    // NaN is equal to nothing, not even itself.
    CHECK(vl::NaN_color != vl::NaN_color);
}

// =======================================================================================
// vector
// =======================================================================================

TEST_CASE("vector: w defaults to 0", "[tuples][vector]") {
    const vector v(1, 2, 3);
    CHECK(v.x == 1);
    CHECK(v.y == 2);
    CHECK(v.z == 3);
    CHECK(v.w == 0);
    CHECK(vector() == vector(0, 0, 0, 0));
}

TEST_CASE("vector: addition, subtraction and negation work component by component", "[tuples][vector]") {
    const vector a(1, 2, 3), b(4, 5, 6);
    CHECK(a + b == vector(5, 7, 9));
    CHECK(b - a == vector(3, 3, 3));
    CHECK(-a == vector(-1, -2, -3));
}

TEST_CASE("vector: scaling by a double scales every component", "[tuples][vector]") {
    const vector v(1, -2, 3);
    CHECK(v * 2 == vector(2, -4, 6));
    CHECK(2 * v == vector(2, -4, 6));
    CHECK(v / 2 == vector(0.5, -1, 1.5));
}

TEST_CASE("vector: vector times vector is the dot product of x, y, z", "[tuples][vector]") {
    CHECK(vector(1, 2, 3) * vector(4, 5, 6) == 32);
    CHECK(vector(1, 0, 0) * vector(0, 1, 0) == 0);
    CHECK(vector(1, 2, 3, 7) * vector(4, 5, 6, 9) == 32);  // w takes no part
}

TEST_CASE("vector: % is the right-handed cross product", "[tuples][vector]") {
    using vl::VECTOR_DIRECTION;
    CHECK(VECTOR_DIRECTION[vl::POS_X] % VECTOR_DIRECTION[vl::POS_Y] == VECTOR_DIRECTION[vl::POS_Z]);
    CHECK(VECTOR_DIRECTION[vl::POS_Y] % VECTOR_DIRECTION[vl::POS_Z] == VECTOR_DIRECTION[vl::POS_X]);
    CHECK(VECTOR_DIRECTION[vl::POS_Z] % VECTOR_DIRECTION[vl::POS_X] == VECTOR_DIRECTION[vl::POS_Y]);
    CHECK(VECTOR_DIRECTION[vl::POS_Y] % VECTOR_DIRECTION[vl::POS_X] == VECTOR_DIRECTION[vl::NEG_Z]);
    CHECK(vector(1, 2, 3) % vector(4, 5, 6) == vector(-3, 6, -3));
    CHECK(vector(1, 2, 3) % vector(2, 4, 6) == vector(0, 0, 0));  // parallel
}

TEST_CASE("vector: compound assignments change the vector in place", "[tuples][vector]") {
    vector v(1, 2, 3);
    CHECK(&(v += vector(1, 1, 1)) == &v);
    CHECK(v == vector(2, 3, 4));
    v -= vector(2, 2, 2);
    CHECK(v == vector(0, 1, 2));
    v *= 3;
    CHECK(v == vector(0, 3, 6));
    v /= 3;
    CHECK(v == vector(0, 1, 2));
    v = vector(1, 0, 0);
    v %= vector(0, 1, 0);
    CHECK(v == vector(0, 0, 1));
}

TEST_CASE("vector: length is the Euclidean length of x, y, z", "[tuples][vector]") {
    CHECK(vector(3, 4, 0).length() == 5);
    CHECK(vector(2, 3, 6).length() == 7);
    CHECK(vector(2, 3, 6, 100).length() == 7);  // w is a flag, not a dimension
    CHECK(vector().length() == 0);
}

TEST_CASE("vector: unit keeps the direction and makes the length 1", "[tuples][vector]") {
    CHECK(vector(0, 0, -5).unit() == vector(0, 0, -1));
    CHECK(vector(3, 4, 0).unit() == vector(0.6, 0.8, 0));
    const vector u = vector(1, 2, 3).unit();
    CHECK(u.length() == Approx(1));
    CHECK(u.x * 2 == Approx(u.y));
    CHECK(u.x * 3 == Approx(u.z));
}

TEST_CASE("vector: the zero vector has no direction, so its unit is NaN", "[tuples][vector]") {
    CHECK(vl::is_nan(vector(0, 0, 0).unit()));
    CHECK(vl::is_nan(vl::VECTOR_DIRECTION[vl::NO_DIRECTION].unit()));
}

TEST_CASE("vector: == and != compare all four components exactly", "[tuples][vector]") {
    CHECK(vector(1, 2, 3) == vector(1, 2, 3, 0));
    CHECK(vector(1, 2, 3) != vector(1, 2, 3, 1));
    CHECK_FALSE(vector(1, 2, 3) != vector(1, 2, 3));
    CHECK(vector(1, 2, 3) != vector(1, 2, 4));
}

TEST_CASE("vector: VECTOR_DIRECTION names the six axis directions and the zero vector",
          "[tuples][vector][constants]") {
    using vl::VECTOR_DIRECTION;
    CHECK(VECTOR_DIRECTION[vl::NEG_Z] == vector(0, 0, -1));
    CHECK(VECTOR_DIRECTION[vl::POS_Z] == vector(0, 0, 1));
    CHECK(VECTOR_DIRECTION[vl::NEG_Y] == vector(0, -1, 0));
    CHECK(VECTOR_DIRECTION[vl::POS_Y] == vector(0, 1, 0));
    CHECK(VECTOR_DIRECTION[vl::NEG_X] == vector(-1, 0, 0));
    CHECK(VECTOR_DIRECTION[vl::POS_X] == vector(1, 0, 0));
    CHECK(VECTOR_DIRECTION[vl::NO_DIRECTION] == vector(0, 0, 0));
    STATIC_REQUIRE(std::size(VECTOR_DIRECTION) == vl::NO_DIRECTION + 1);
}

TEST_CASE("vector: NaN_vector is NaN in every component", "[tuples][vector][constants]") {
    CHECK(std::isnan(vl::NaN_vector.x));
    CHECK(std::isnan(vl::NaN_vector.y));
    CHECK(std::isnan(vl::NaN_vector.z));
    CHECK(std::isnan(vl::NaN_vector.w));
    CHECK(vl::is_nan(vl::NaN_vector));
    CHECK_FALSE(vl::is_nan(vector(1, 2, 3)));
    CHECK(vl::NaN_vector != vl::NaN_vector);
}

// =======================================================================================
// point
// =======================================================================================

TEST_CASE("point: w defaults to 1", "[tuples][point]") {
    const point p(1, 2, 3);
    CHECK(p.x == 1);
    CHECK(p.y == 2);
    CHECK(p.z == 3);
    CHECK(p.w == 1);
    const point origin;
    CHECK(origin.x == 0);
    CHECK(origin.y == 0);
    CHECK(origin.z == 0);
    CHECK(origin.w == 1);
}

TEST_CASE("point: a point moved by a vector is a point", "[tuples][point]") {
    const point p(1, 2, 3);
    const vector v(10, 20, 30);
    CHECK(p + v == point(11, 22, 33));
    CHECK((p + v).w == 1);
    CHECK(p - v == point(-9, -18, -27));
    CHECK((p - v).w == 1);
}

TEST_CASE("point: the difference of two points is the vector between them", "[tuples][point]") {
    const vector d = point(4, 6, 8) - point(1, 2, 3);
    CHECK(d == vector(3, 4, 5, 0));
}

TEST_CASE("point: += and -= move the point in place", "[tuples][point]") {
    point p(1, 2, 3);
    CHECK(&(p += vector(1, 1, 1)) == &p);
    CHECK(p == point(2, 3, 4));
    p -= vector(2, 3, 4);
    CHECK(p == point(0, 0, 0));
}

TEST_CASE("point: homogenized divides by w", "[tuples][point]") {
    const point h = point(2, 4, 6, 2).homogenized();
    CHECK(h.x == 1);
    CHECK(h.y == 2);
    CHECK(h.z == 3);
    CHECK(h.w == 1);
}

TEST_CASE("point: == and != compare the homogenized coordinates", "[tuples][point]") {
    CHECK(point(2, 4, 6, 2) == point(1, 2, 3));
    CHECK(point(-1, -2, -3, -1) == point(1, 2, 3));
    CHECK_FALSE(point(2, 4, 6, 2) != point(1, 2, 3));
    CHECK(point(2, 4, 6, 1) != point(1, 2, 3));
    CHECK(point(1, 2, 3) != point(1, 2, 3.5));
}

TEST_CASE("point: NaN_point is NaN in every component and equal to no point", "[tuples][point][constants]") {
    CHECK(std::isnan(vl::NaN_point.x));
    CHECK(std::isnan(vl::NaN_point.y));
    CHECK(std::isnan(vl::NaN_point.z));
    CHECK(std::isnan(vl::NaN_point.w));
    CHECK(vl::is_nan(vl::NaN_point));
    CHECK_FALSE(vl::is_nan(point(1, 2, 3)));
    CHECK(vl::NaN_point != vl::NaN_point);
    CHECK(vl::NaN_point != point(0, 0, 0));
}

// The thesis's protected point operations: each treats a point as the vector from
// point(0, 0, 0, 1) and turns a point result back by adding that origin again.

namespace {
template <class P>
concept scalable = requires(P p) { p * 2.0; };
template <class P>
concept crossable = requires(P p) { p % p; };
}  // namespace

TEST_CASE("point: the protected operations are hidden unless vl::homogeneous is used",
          "[tuples][point][homogeneous]") {
    // "Twice a location" makes no geometric sense, so ordinary code cannot write it.
    STATIC_REQUIRE_FALSE(scalable<point>);
    STATIC_REQUIRE_FALSE(crossable<point>);
    STATIC_REQUIRE_FALSE(scalable<color_point>);
    STATIC_REQUIRE(scalable<vector>);
}

TEST_CASE("point: protected scaling and division act on the displacement from the origin",
          "[tuples][point][homogeneous]") {
    using namespace vl::homogeneous;
    const point p(1, 2, 3);
    const point twice = p * 2;
    CHECK(twice.x == 2);
    CHECK(twice.y == 4);
    CHECK(twice.z == 6);
    CHECK(twice.w == 1);
    CHECK(2 * p == twice);
    const point half = p / 2;
    CHECK(half.x == 0.5);
    CHECK(half.y == 1);
    CHECK(half.z == 1.5);
    CHECK(half.w == 1);

    // w is treated the same way: (w - 1) * d + 1.
    const point q = point(1, 2, 3, 2) * 3;
    CHECK(q.x == 3);
    CHECK(q.y == 6);
    CHECK(q.z == 9);
    CHECK(q.w == 4);
}

TEST_CASE("point: protected dot products use the displacement from the origin",
          "[tuples][point][homogeneous]") {
    using namespace vl::homogeneous;
    const point p(1, 2, 3);
    const vector v(4, 5, 6);
    CHECK(p * v == 32);
    CHECK(v * p == 32);
    CHECK(p * point(4, 5, 6) == 32);
    CHECK(p * p == 14);
}

TEST_CASE("point: protected cross products give a point", "[tuples][point][homogeneous]") {
    using namespace vl::homogeneous;
    const point x_axis(1, 0, 0), y_axis(0, 1, 0);
    const point z = x_axis % y_axis;
    CHECK(z.x == 0);
    CHECK(z.y == 0);
    CHECK(z.z == 1);
    CHECK(z.w == 1);
    CHECK(vector(1, 2, 3) % point(4, 5, 6) == point(-3, 6, -3));
}

TEST_CASE("point: protected compound assignments change the point in place", "[tuples][point][homogeneous]") {
    using namespace vl::homogeneous;
    point p(1, 2, 3);
    CHECK(&(p *= 2) == &p);
    CHECK(p == point(2, 4, 6));
    p /= 4;
    CHECK(p == point(0.5, 1, 1.5));
    p = point(1, 0, 0);
    p %= vector(0, 1, 0);
    CHECK(p == point(0, 0, 1));
    CHECK(p.w == 1);
}

// =======================================================================================
// color_point
// =======================================================================================

TEST_CASE("color_point: every constructor sets the colour and the point", "[tuples_based][color_point]") {
    const color c(1, 0.5, 0.25);
    const point p(1, 2, 3);
    CHECK(color_point().clr() == vl::BLACK);
    CHECK(color_point().pnt() == point(0, 0, 0));
    CHECK(color_point(c, p).clr() == c);
    CHECK(color_point(c, p).pnt() == p);
    CHECK(color_point(p, c) == color_point(c, p));
    CHECK(color_point(p) == color_point(vl::BLACK, p));
    CHECK(color_point(c) == color_point(c, point(0, 0, 0)));
    CHECK(color_point(1, 0.5, 0.25, 1, 2, 3) == color_point(c, p));
    CHECK(color_point(c, 1, 2, 3) == color_point(c, p));
    CHECK(color_point(c, 2, 4, 6, 2).pnt().w == 2);
    CHECK(color_point(1, 0.5, 0.25, p) == color_point(c, p));
}

TEST_CASE("color_point: the colour and the point can be read and replaced", "[tuples_based][color_point]") {
    color_point cp(vl::WHITE, point(1, 2, 3));
    cp.set_clr(color(0.5, 0.5, 0.5));
    cp.set_pnt(point(4, 5, 6));
    CHECK(cp.clr() == color(0.5, 0.5, 0.5));
    CHECK(cp.pnt() == point(4, 5, 6));
}

TEST_CASE("color_point: a color_point can stand wherever a point is expected", "[tuples_based][color_point]") {
    const color_point light(vl::WHITE, point(0, 10, 0));
    const point& where = light;
    CHECK(where == point(0, 10, 0));
    CHECK(light - point(0, 0, 0) == vector(0, 10, 0));
    CHECK(point(0, 0, 0) - light == vector(0, -10, 0));
}

TEST_CASE("color_point: moving by a vector moves the point and keeps the colour", "[tuples_based][color_point]") {
    const color c(1, 0, 0);
    color_point cp(c, point(1, 2, 3));
    CHECK(cp + vector(1, 1, 1) == color_point(c, point(2, 3, 4)));
    CHECK(cp - vector(1, 1, 1) == color_point(c, point(0, 1, 2)));
    cp += vector(1, 1, 1);
    CHECK(cp == color_point(c, point(2, 3, 4)));
    cp -= vector(2, 3, 4);
    CHECK(cp == color_point(c, point(0, 0, 0)));
}

TEST_CASE("color_point: the difference of two color_points is the vector between the points",
          "[tuples_based][color_point]") {
    const color_point a(vl::WHITE, point(4, 6, 8)), b(vl::BLACK, point(1, 2, 3));
    CHECK(a - b == vector(3, 4, 5));
}

TEST_CASE("color_point: homogenized homogenizes the point and keeps the colour", "[tuples_based][color_point]") {
    const color c(0.5, 0.5, 0.5);
    const color_point h = color_point(c, point(2, 4, 6, 2)).homogenized();
    CHECK(h.clr() == c);
    CHECK(h.pnt().x == 1);
    CHECK(h.pnt().y == 2);
    CHECK(h.pnt().z == 3);
    CHECK(h.pnt().w == 1);
}

TEST_CASE("color_point: == and != compare both the colour and the homogenized point",
          "[tuples_based][color_point]") {
    const color red(1, 0, 0), blue(0, 0, 1);
    CHECK(color_point(red, point(2, 4, 6, 2)) == color_point(red, point(1, 2, 3)));
    CHECK(color_point(red, point(1, 2, 3)) != color_point(blue, point(1, 2, 3)));
    CHECK(color_point(red, point(1, 2, 3)) != color_point(red, point(1, 2, 4)));
    CHECK_FALSE(color_point(red, point(1, 2, 3)) != color_point(red, point(1, 2, 3)));
}

TEST_CASE("color_point: protected operations act on the point and keep the colour",
          "[tuples_based][color_point][homogeneous]") {
    using namespace vl::homogeneous;
    const color c(0.25, 0.5, 1);
    const color_point cp(c, point(1, 2, 3));

    CHECK(cp * 2 == color_point(c, point(2, 4, 6)));
    CHECK(2 * cp == color_point(c, point(2, 4, 6)));
    CHECK(cp / 2 == color_point(c, point(0.5, 1, 1.5)));
    CHECK((cp * 2).pnt().w == 1);

    CHECK(cp * vector(4, 5, 6) == 32);
    CHECK(vector(4, 5, 6) * cp == 32);
    CHECK(cp * cp == 14);

    const color_point x_axis(c, point(1, 0, 0)), y_axis(vl::WHITE, point(0, 1, 0));
    CHECK(x_axis % y_axis == color_point(c, point(0, 0, 1)));  // the left operand's colour
    CHECK(vector(1, 0, 0) % y_axis == color_point(vl::WHITE, point(0, 0, 1)));

    color_point m = cp;
    CHECK(&(m *= 2) == &m);
    CHECK(m == color_point(c, point(2, 4, 6)));
    m /= 4;
    CHECK(m == color_point(c, point(0.5, 1, 1.5)));
    m = x_axis;
    m %= vector(0, 1, 0);
    CHECK(m == color_point(c, point(0, 0, 1)));
}

// =======================================================================================
// matrix
// =======================================================================================

namespace {
/// A matrix whose elements are all different: m(r, c) == 10 * (r + 1) + (c + 1).
constexpr matrix numbered(11, 12, 13, 14, 21, 22, 23, 24, 31, 32, 33, 34, 41, 42, 43, 44);

/// Translation by (tx, ty, tz) in the column-vector convention: the offset is column 3.
constexpr matrix translation(double tx, double ty, double tz) {
    return {1, 0, 0, tx, 0, 1, 0, ty, 0, 0, 1, tz, 0, 0, 0, 1};
}
constexpr matrix scaling(double sx, double sy, double sz) {
    return {sx, 0, 0, 0, 0, sy, 0, 0, 0, 0, sz, 0, 0, 0, 0, 1};
}
}  // namespace

TEST_CASE("matrix: the default matrix and IDENTITY are the identity", "[tuples_based][matrix][constants]") {
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) {
            CHECK(matrix()(r, c) == (r == c ? 1 : 0));
            CHECK(vl::IDENTITY(r, c) == (r == c ? 1 : 0));
        }
    CHECK(vl::IDENTITY * point(1, 2, 3) == point(1, 2, 3));
    CHECK(vl::IDENTITY * numbered == numbered);
    CHECK(numbered * vl::IDENTITY == numbered);
}

TEST_CASE("matrix: 16 doubles fill the matrix row by row", "[tuples_based][matrix]") {
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) CHECK(numbered(r, c) == 10 * (r + 1) + (c + 1));
}

TEST_CASE("matrix: four vectors become the rows and four points the columns", "[tuples_based][matrix]") {
    const matrix from_rows(vector(11, 12, 13, 14), vector(21, 22, 23, 24), vector(31, 32, 33, 34),
                           vector(41, 42, 43, 44));
    CHECK(from_rows == numbered);
    const matrix from_columns(point(11, 21, 31, 41), point(12, 22, 32, 42), point(13, 23, 33, 43),
                              point(14, 24, 34, 44));
    CHECK(from_columns == numbered);
}

TEST_CASE("matrix: elements can be read and written by row and column", "[tuples_based][matrix]") {
    matrix m = numbered;
    CHECK(m(0, 3) == 14);
    CHECK(m(3, 0) == 41);
    m(2, 1) = -1;
    CHECK(m(2, 1) == -1);
    CHECK(m(1, 2) == 23);
}

TEST_CASE("matrix: row() is a vector and column() is a point", "[tuples_based][matrix]") {
    CHECK(numbered.row(0) == vector(11, 12, 13, 14));
    CHECK(numbered.row(3) == vector(41, 42, 43, 44));
    const point c = numbered.column(2);
    CHECK(c.x == 13);
    CHECK(c.y == 23);
    CHECK(c.z == 33);
    CHECK(c.w == 43);
    CHECK(matrix(numbered.row(0), numbered.row(1), numbered.row(2), numbered.row(3)) == numbered);
    CHECK(matrix(numbered.column(0), numbered.column(1), numbered.column(2), numbered.column(3)) == numbered);
}

TEST_CASE("matrix: matrix times matrix is the matrix product", "[tuples_based][matrix]") {
    const matrix a(1, 2, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1);
    const matrix b(1, 0, 0, 0, 3, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1);
    CHECK(a * b == matrix(7, 2, 0, 0, 3, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1));
    CHECK(b * a == matrix(1, 2, 0, 0, 3, 7, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1));
    // Column vectors: (A * B) * p applies B first.
    const matrix move_then_scale = scaling(2, 2, 2) * translation(1, 0, 0);
    CHECK(move_then_scale * point(0, 0, 0) == point(2, 0, 0));
}

TEST_CASE("matrix: matrix times point transforms the point, translation included", "[tuples_based][matrix]") {
    CHECK(translation(1, 2, 3) * point(10, 20, 30) == point(11, 22, 33));
    CHECK(scaling(2, 3, 4) * point(1, 1, 1) == point(2, 3, 4));
    const point p = numbered * point(1, 0, 0, 0);
    CHECK(p.x == 11);
    CHECK(p.y == 21);
    CHECK(p.z == 31);
    CHECK(p.w == 41);
}

TEST_CASE("matrix: the result of matrix times point is not homogenized", "[tuples_based][matrix]") {
    const matrix doubles_w(1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 2);
    const point p = doubles_w * point(1, 2, 3);
    CHECK(p.w == 2);
    CHECK(p.x == 1);
    CHECK(p.homogenized().x == 0.5);
}

TEST_CASE("matrix: matrix times vector ignores translation", "[tuples_based][matrix]") {
    CHECK(translation(1, 2, 3) * vector(10, 20, 30) == vector(10, 20, 30));
    CHECK(scaling(2, 3, 4) * vector(1, 1, 1) == vector(2, 3, 4));
    CHECK(numbered * vector(0, 0, 1, 0) == vector(13, 23, 33, 43));
}

TEST_CASE("matrix: matrix times color_point moves the point and keeps the colour", "[tuples_based][matrix]") {
    const color c(1, 0.5, 0);
    const color_point moved = translation(1, 2, 3) * color_point(c, point(1, 1, 1));
    CHECK(moved.clr() == c);
    CHECK(moved.pnt() == point(2, 3, 4));
}

TEST_CASE("matrix: matrix times ray transforms the origin and the direction, which stays unit",
          "[tuples_based][matrix][ray]") {
    const vl::ray r(point(1, 2, 3), vector(0, 0, -1));
    const vl::ray moved = translation(10, 0, 0) * r;
    CHECK(moved.origin() == point(11, 2, 3));
    CHECK(moved.direction() == vector(0, 0, -1));  // a direction does not move
    const vl::ray stretched = scaling(1, 1, 5) * r;
    CHECK(stretched.origin() == point(1, 2, 15));
    CHECK(stretched.direction() == vector(0, 0, -1));  // made unit again
}

TEST_CASE("matrix: scaling by a double scales every element", "[tuples_based][matrix]") {
    const matrix twice = 2 * numbered;
    CHECK(numbered * 2 == twice);
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) CHECK(twice(r, c) == 2 * numbered(r, c));
    matrix m = numbered;
    m *= 2;
    CHECK(m == twice);
}

TEST_CASE("matrix: addition and subtraction work element by element", "[tuples_based][matrix]") {
    const matrix sum = numbered + vl::IDENTITY;
    CHECK(sum == matrix(12, 12, 13, 14, 21, 23, 23, 24, 31, 32, 34, 34, 41, 42, 43, 45));
    CHECK(sum - vl::IDENTITY == numbered);
    matrix m = numbered;
    m += numbered;
    CHECK(m == 2 * numbered);
    m -= numbered;
    CHECK(m == numbered);
}

TEST_CASE("matrix: == and != compare the 16 elements exactly, without homogenizing",
          "[tuples_based][matrix]") {
    CHECK(numbered == matrix(numbered));
    CHECK_FALSE(numbered != matrix(numbered));
    matrix changed = numbered;
    changed(3, 3) = 45;
    CHECK(changed != numbered);
    // Columns point(2, 4, 6, 2) and point(1, 2, 3, 1) are equal points, but not equal columns.
    const matrix a(point(2, 4, 6, 2), point(0, 1, 0, 0), point(0, 0, 1, 0), point(0, 0, 0, 1));
    const matrix b(point(1, 2, 3, 1), point(0, 1, 0, 0), point(0, 0, 1, 0), point(0, 0, 0, 1));
    CHECK(a.column(0) == b.column(0));
    CHECK(a != b);
}

TEST_CASE("matrix: transpose swaps rows and columns", "[tuples_based][matrix]") {
    const matrix t = numbered.transpose();
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) CHECK(t(r, c) == numbered(c, r));
    CHECK(vl::IDENTITY.transpose() == vl::IDENTITY);
}

TEST_CASE("matrix: determinant of known matrices", "[tuples_based][matrix]") {
    CHECK(vl::IDENTITY.determinant() == 1);
    CHECK(scaling(2, 3, 4).determinant() == 24);
    CHECK(translation(5, 6, 7).determinant() == 1);
    CHECK(numbered.determinant() == 0);  // rows in arithmetic progression are dependent
    // A triangular matrix: the product of the diagonal.
    CHECK(matrix(2, 5, 7, 1, 0, 3, 4, 2, 0, 0, -1, 6, 0, 0, 0, 4).determinant() == -24);
    CHECK(matrix(2, 0, 0, 0, 5, 3, 0, 0, 7, 4, -1, 0, 1, 2, 6, 4).determinant() == -24);
    // Worked by cofactor expansion along the first row; swapping two rows changes the sign.
    const matrix m(2, 0, 1, 3, 1, 1, 0, 2, 0, 4, 1, 1, 3, 0, 2, 1);
    const matrix swapped(m.row(1), m.row(0), m.row(2), m.row(3));
    CHECK(m.determinant() == -20);
    CHECK(swapped.determinant() == 20);
}

// =======================================================================================
// Stream output and input
// =======================================================================================

TEST_CASE("streams: << writes the thesis's form, name (a, b, c, d)", "[tuples][streams]") {
    CHECK(written(color(0.5, 0.25, 1)) == "color (0.5, 0.25, 1, 0)");
    CHECK(written(vector(1, -2, 3)) == "vector (1, -2, 3, 0)");
    CHECK(written(point(1, 2, 3)) == "point (1, 2, 3, 1)");
    CHECK(written(color_point(vl::WHITE, point(0, 10, 0))) == "color (1, 1, 1, 0) point (0, 10, 0, 1)");
    CHECK(written(vl::IDENTITY) == "matrix [(1, 0, 0, 0) (0, 1, 0, 0) (0, 0, 1, 0) (0, 0, 0, 1)]");
}

TEST_CASE("streams: << writes enough digits to read the same double back", "[tuples][streams]") {
    CHECK(written(vector(0.1, 0, 0)) == "vector (0.10000000000000001, 0, 0, 0)");
}

TEST_CASE("streams: << leaves the stream's precision as it was", "[tuples][streams]") {
    std::ostringstream s;
    s.precision(3);
    s << point(1, 2, 3) << vl::IDENTITY;
    CHECK(s.precision() == 3);
    s << ' ' << 3.14159;
    CHECK(s.str().ends_with(" 3.14"));
}

TEST_CASE("streams: >> reads four bare numbers", "[tuples][streams]") {
    bool ok = false;
    const point p = read<point>("1 2 3 4", {}, ok);
    CHECK(ok);
    CHECK(p.x == 1);
    CHECK(p.y == 2);
    CHECK(p.z == 3);
    CHECK(p.w == 4);
    CHECK(read<color>("0.5 0.25 1 0", {}, ok) == color(0.5, 0.25, 1, 0));
    CHECK(read<vector>("  -1\n2\t3e2 0 ", {}, ok) == vector(-1, 2, 300, 0));
    CHECK(ok);
}

TEST_CASE("streams: >> skips an optional alphabetic label before the numbers", "[tuples][streams]") {
    bool ok = false;
    CHECK(read<point>("center 1 2 3 1", {}, ok) == point(1, 2, 3));
    CHECK(ok);
    CHECK(read<vector>("up 0 1 0 0", {}, ok) == vector(0, 1, 0));
    CHECK(ok);
    CHECK(read<color>("Ambient 0.5 0.5 0.5 0", {}, ok) == color(0.5, 0.5, 0.5));
    CHECK(ok);
}

TEST_CASE("streams: >> reads the written form and the bracketed form", "[tuples][streams]") {
    bool ok = false;
    CHECK(read<point>("point (1, 2, 3, 1)", {}, ok) == point(1, 2, 3));
    CHECK(ok);
    CHECK(read<vector>("(1, 2, 3, 0)", {}, ok) == vector(1, 2, 3));
    CHECK(ok);
    CHECK(read<vector>("(1 2 3 0)", {}, ok) == vector(1, 2, 3));
    CHECK(ok);
    CHECK(read<color>("tint( 1 ,0.5 , 0,0 )", {}, ok) == color(1, 0.5, 0, 0));
    CHECK(ok);
}

TEST_CASE("streams: >> reads several labelled tuples one after the other", "[tuples][streams]") {
    std::istringstream s("from 0 0 5 1 toward (0, 0, -1, 0) tint 1 1 1 0");
    point from;
    vector toward;
    color tint;
    CHECK(s >> from >> toward >> tint);
    CHECK(from == point(0, 0, 5));
    CHECK(toward == vector(0, 0, -1));
    CHECK(tint == vl::WHITE);
}

TEST_CASE("streams: >> on malformed input sets failbit and leaves the tuple unchanged", "[tuples][streams]") {
    const point start(7, 8, 9);
    for (const char* text : {"", "point", "1 2 3", "1 2 x 4", "point (1, 2, 3)", "(1, 2, 3, 4",
                             "(1, 2, 3, 4]", "1..5 2 3 4", "1 2 3 4e", "(1; 2; 3; 4)"}) {
        CAPTURE(text);
        bool ok = true;
        const point p = read<point>(text, start, ok);
        CHECK_FALSE(ok);
        CHECK(p.x == 7);
        CHECK(p.y == 8);
        CHECK(p.z == 9);
        CHECK(p.w == 1);
    }
    bool ok = true;
    CHECK(read<color>("color (1, 2)", vl::WHITE, ok) == vl::WHITE);
    CHECK_FALSE(ok);
    CHECK(read<vector>("up 0 one 0 0", vector(1, 2, 3), ok) == vector(1, 2, 3));
    CHECK_FALSE(ok);
}

TEST_CASE("streams: non-finite components are written and read back", "[tuples][streams]") {
    const std::string text = written(point(vl::NaN, inf, -inf, 1));
    CHECK(text == "point (nan, inf, -inf, 1)");
    bool ok = false;
    const point p = read<point>(text, {}, ok);
    CHECK(ok);
    CHECK(std::isnan(p.x));
    CHECK(p.y == inf);
    CHECK(p.z == -inf);
    CHECK(p.w == 1);
    CHECK(vl::is_nan(read<color>(written(vl::NaN_color), {}, ok)));
    CHECK(ok);
    CHECK(vl::is_nan(read<vector>(written(vl::NaN_vector), {}, ok)));
    CHECK(ok);
}

TEST_CASE("streams: a color_point reads a label, then a colour, then a point, each with a label",
          "[tuples_based][color_point][streams]") {
    bool ok = false;
    const color_point light(color(1, 1, 1, 0), point(0, 10, 0));
    CHECK(read<color_point>("light clr 1 1 1 0 at 0 10 0 1", {}, ok) == light);
    CHECK(ok);
    CHECK(read<color_point>("1 1 1 0 0 10 0 1", {}, ok) == light);
    CHECK(ok);
    CHECK(read<color_point>(written(light), {}, ok) == light);
    CHECK(ok);
    const color_point start(vl::BLACK, point(1, 2, 3));
    CHECK(read<color_point>("light clr 1 1 1 0 at 0 10", start, ok) == start);
    CHECK_FALSE(ok);
}

TEST_CASE("streams: a matrix reads a label, then 16 numbers, bare or as bracketed rows",
          "[tuples_based][matrix][streams]") {
    bool ok = false;
    CHECK(read<matrix>(written(numbered), {}, ok) == numbered);
    CHECK(ok);
    CHECK(read<matrix>("11 12 13 14 21 22 23 24 31 32 33 34 41 42 43 44", {}, ok) == numbered);
    CHECK(ok);
    CHECK(read<matrix>("transform [(11, 12, 13, 14) (21, 22, 23, 24)\n"
                       "           (31, 32, 33, 34) (41, 42, 43, 44)]",
                       {}, ok) == numbered);
    CHECK(ok);
    for (const char* text : {"", "matrix", "matrix [(1, 0, 0, 0) (0, 1, 0, 0)]",
                             "matrix [(1, 0, 0, 0) (0, 1, 0, 0) (0, 0, 1, 0) (0, 0, 0, 1)",
                             "1 0 0 0 0 1 0 0 0 0 1 0 0 0 0"}) {
        CAPTURE(text);
        CHECK(read<matrix>(text, numbered, ok) == numbered);
        CHECK_FALSE(ok);
    }
}

// =======================================================================================
// Properties over random inputs (fixed seed, so failures are reproducible)
// =======================================================================================

TEST_CASE("property: the cross product is perpendicular to both operands", "[tuples][vector][property]") {
    random_tuples random;
    for (int i = 0; i < iterations; ++i) {
        const vector a = random.any_vector(), b = random.any_vector();
        const vector n = a % b;
        // |a % b| is of the order |a||b|, so (a % b) * a is of the order |a|^2 |b|.
        const double scale = a.length() * a.length() * b.length() + a.length() * b.length() * b.length();
        CAPTURE(a, b, n);
        CHECK(near(n * a, 0, scale));
        CHECK(near(n * b, 0, scale));
    }
}

TEST_CASE("property: |a % b|^2 + (a * b)^2 == |a|^2 |b|^2 (Lagrange's identity)", "[tuples][vector][property]") {
    random_tuples random;
    for (int i = 0; i < iterations; ++i) {
        const vector a = random.any_vector(), b = random.any_vector();
        const vector n = a % b;
        const double product = (a * a) * (b * b);
        CAPTURE(a, b);
        CHECK(near(n * n + (a * b) * (a * b), product, product));
    }
}

TEST_CASE("property: unit() has length 1", "[tuples][vector][property]") {
    random_tuples random;
    for (int i = 0; i < iterations; ++i) {
        const vector v = random.wide_vector();
        CAPTURE(v);
        // A few roundings in length() and in the divisions: a few ulps.
        CHECK(v.unit().length() == Approx(1).epsilon(1e-14));
    }
}

TEST_CASE("property: p + (q - p) == q", "[tuples][point][property]") {
    random_tuples random;
    for (int i = 0; i < iterations; ++i) {
        const point p = random.any_point(), q = random.any_point();
        CAPTURE(p, q);
        // Each subtraction and addition rounds once, relative to the larger operand.
        CHECK(near(p + (q - p), q, magnitude(p) + magnitude(q)));
    }
}

TEST_CASE("property: (m1 * m2) * p == m1 * (m2 * p)", "[tuples_based][matrix][property]") {
    random_tuples random;
    for (int i = 0; i < iterations; ++i) {
        const matrix m1 = random.any_matrix(), m2 = random.any_matrix();
        const point p = random.any_point();
        CAPTURE(m1, m2, p);
        CHECK(near((m1 * m2) * p, m1 * (m2 * p), magnitude(m1) * magnitude(m2) * magnitude(p)));
    }
}

TEST_CASE("property: (m1 * m2) * m3 == m1 * (m2 * m3)", "[tuples_based][matrix][property]") {
    random_tuples random;
    for (int i = 0; i < iterations; ++i) {
        const matrix m1 = random.any_matrix(), m2 = random.any_matrix(), m3 = random.any_matrix();
        CAPTURE(m1, m2, m3);
        CHECK(near((m1 * m2) * m3, m1 * (m2 * m3), magnitude(m1) * magnitude(m2) * magnitude(m3)));
    }
}

TEST_CASE("property: transposing twice gives the matrix back exactly", "[tuples_based][matrix][property]") {
    random_tuples random;
    for (int i = 0; i < iterations; ++i) {
        const matrix m = random.any_matrix();
        CHECK(m.transpose().transpose() == m);
    }
}

TEST_CASE("property: det(m1 * m2) == det(m1) * det(m2)", "[tuples_based][matrix][property]") {
    random_tuples random;
    for (int i = 0; i < iterations; ++i) {
        const matrix m1 = random.any_matrix(), m2 = random.any_matrix();
        CAPTURE(m1, m2);
        // A determinant is a sum of products of four elements, each bounded by the norm.
        const double scale = std::pow(magnitude(m1) * magnitude(m2), 4);
        CHECK(near((m1 * m2).determinant(), m1.determinant() * m2.determinant(), scale));
    }
}

TEST_CASE("property: det(transpose(m)) == det(m)", "[tuples_based][matrix][property]") {
    random_tuples random;
    for (int i = 0; i < iterations; ++i) {
        const matrix m = random.any_matrix();
        CAPTURE(m);
        CHECK(near(m.transpose().determinant(), m.determinant(), std::pow(magnitude(m), 4)));
    }
}

TEST_CASE("property: writing then reading gives bit-identical tuples and matrices", "[tuples][streams][property]") {
    random_tuples random;
    for (int i = 0; i < iterations; ++i) {
        const color c(random.any_finite_double(), random.any_finite_double(), random.any_finite_double(),
                      random.any_finite_double());
        const vector v(random.any_finite_double(), random.any_finite_double(), random.any_finite_double(),
                       random.any_finite_double());
        const point p(random.any_finite_double(), random.any_finite_double(), random.any_finite_double(),
                      random.any_finite_double());
        matrix m;
        for (int r = 0; r < 4; ++r)
            for (int col = 0; col < 4; ++col) m(r, col) = random.any_finite_double();

        std::stringstream s;
        s << c << ' ' << v << ' ' << p << ' ' << color_point(c, p) << ' ' << m;
        color c2;
        vector v2;
        point p2;
        color_point cp2;
        matrix m2;
        CAPTURE(s.str());
        REQUIRE(s >> c2 >> v2 >> p2 >> cp2 >> m2);

        CHECK((same_bits(c2.r, c.r) && same_bits(c2.g, c.g) && same_bits(c2.b, c.b) && same_bits(c2.a, c.a)));
        CHECK((same_bits(v2.x, v.x) && same_bits(v2.y, v.y) && same_bits(v2.z, v.z) && same_bits(v2.w, v.w)));
        CHECK((same_bits(p2.x, p.x) && same_bits(p2.y, p.y) && same_bits(p2.z, p.z) && same_bits(p2.w, p.w)));
        CHECK(same_bits(cp2.clr().r, c.r));
        CHECK(same_bits(cp2.pnt().w, p.w));
        bool same_matrix = true;
        for (int r = 0; r < 4; ++r)
            for (int col = 0; col < 4; ++col) same_matrix = same_matrix && same_bits(m2(r, col), m(r, col));
        CHECK(same_matrix);
    }
}
