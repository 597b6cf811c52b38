#pragma once
/// \file
/// \brief Types built from tuples: `color_point` (a coloured point, e.g. a light) and the
/// 4x4 homogeneous `matrix`.

#include <array>
#include <iosfwd>

#include "vl/tuples.hh"

namespace vl {

class ray;

/// \brief A point with a colour: a point light, a coloured vertex.
///
/// Every point operation applies to the point part only and keeps the colour; `==` and
/// `!=` compare both parts. A `color_point` converts implicitly to its point, so it can
/// stand wherever a point is expected (`light - hit_point` is a vector).
class color_point {
public:
    /// BLACK at the origin.
    constexpr color_point() = default;
    /// \name Construction from a colour and a point
    ///@{

    /// Colour `c` at point `p`, in either order. A missing colour is BLACK, a missing
    /// point the origin; the one-argument forms are `explicit`.
    constexpr color_point(const color& c, const point& p) : clr_(c), pnt_(p) {}
    constexpr color_point(const point& p, const color& c) : clr_(c), pnt_(p) {}
    constexpr explicit color_point(const point& p) : pnt_(p) {}
    constexpr explicit color_point(const color& c) : clr_(c) {}
    ///@}
    /// Colour (r, g, b) at point (x, y, z).
    constexpr color_point(double r, double g, double b, double x, double y, double z)
        : clr_(r, g, b), pnt_(x, y, z) {}
    /// Colour `c` at point (x, y, z, w).
    constexpr color_point(const color& c, double x, double y, double z, double w = 1)
        : clr_(c), pnt_(x, y, z, w) {}
    /// Colour (r, g, b) at point `p`.
    constexpr color_point(double r, double g, double b, const point& p) : clr_(r, g, b), pnt_(p) {}

    constexpr const color& clr() const { return clr_; }   ///< the colour part
    constexpr const point& pnt() const { return pnt_; }   ///< the point part
    constexpr void set_clr(const color& c) { clr_ = c; }  ///< replaces the colour part
    constexpr void set_pnt(const point& p) { pnt_ = p; }  ///< replaces the point part
    /// The point part: a color_point can be used wherever a point is expected.
    constexpr operator const point&() const { return pnt_; }  // NOLINT: a color_point is a point

    /// The same colour at the homogenized point (see point::homogenized()).
    constexpr color_point homogenized() const { return {clr_, pnt_.homogenized()}; }
    /// \name Moving a color_point
    ///@{

    /// Moves the point part by `v`, as for a point; the colour is kept.
    constexpr color_point& operator+=(const vector& v) { pnt_ += v; return *this; }
    constexpr color_point& operator-=(const vector& v) { pnt_ -= v; return *this; }
    friend constexpr color_point operator+(color_point cp, const vector& v) { return cp += v; }
    friend constexpr color_point operator-(color_point cp, const vector& v) { return cp -= v; }
    ///@}
    /// The vector between the point parts (`a.pnt() - b.pnt()`); colours are ignored.
    friend constexpr vector operator-(const color_point& a, const color_point& b) { return a.pnt_ - b.pnt_; }
    /// Equal colours and equal points (points compared homogenized); `!=` is generated.
    friend constexpr bool operator==(const color_point& a, const color_point& b) {
        return a.clr_ == b.clr_ && a.pnt_ == b.pnt_;
    }

private:
    color clr_ = BLACK;
    point pnt_;
};

/// \name Stream input and output of a color_point
///@{

/// `color (r, g, b, a) point (x, y, z, w)`; `>>` reads an optional label of its own, then
/// the colour, then the point, each with its optional label (`light clr 1 1 1 0 at 0 10 0 1`).
std::ostream& operator<<(std::ostream& s, const color_point& cp);
std::istream& operator>>(std::istream& s, color_point& cp);
///@}

namespace homogeneous {
/// \name Scaling a color_point
///@{

/// The protected operations of the thesis, applied to the point part (see vl::homogeneous);
/// the colour is kept.
/// The dot products (`cp * v`, `v * cp`, `cp * cp`) need no overload: they use the
/// point's, through the conversion to `const point&`.
color_point operator*(const color_point& cp, double d);
color_point operator*(double d, const color_point& cp);
color_point operator/(const color_point& cp, double d);
///@}
/// \name Cross products with a color_point
///@{

/// Cross products; the result keeps the colour of the color_point operand (of `a` in `a % b`).
color_point operator%(const color_point& a, const color_point& b);
color_point operator%(const vector& v, const color_point& cp);
///@}
/// \name In-place color_point operations
///@{

/// `cp *= d`, `cp /= d` and `cp %= v` apply to the point part, keep the colour and
/// return `cp`.
color_point& operator*=(color_point& cp, double d);
color_point& operator/=(color_point& cp, double d);
color_point& operator%=(color_point& cp, const vector& v);
///@}
}  // namespace homogeneous

/// \brief A 4x4 homogeneous transformation, stored row by row.
///
/// **Convention: column vectors.** A matrix transforms by multiplying on the left:
/// `M * p`, `M * v`, `M * r`, and `(A * B) * p == A * (B * p)` applies B first. The
/// thesis's table writes the same products as `p * m` and `r * m` (row vectors); in
/// this framework write `m * p` and `m * r`. `M * v` ignores translation because a
/// vector's w is 0; `M * p` keeps it because a point's w is 1.
///
/// | expression | result |
/// |---|---|
/// | `m * m`, `m + m`, `m - m`, `m * d`, `d * m` | matrix |
/// | `m * p` | point (not homogenized: call `.homogenized()` after a projection) |
/// | `m * v` | vector |
/// | `m * cp` | color_point (the colour is kept) |
/// | `m * r` | ray: origin and direction transformed, direction made unit again |
/// | `m == m`, `m != m` | exact comparison of the 16 elements (no homogenizing) |
/// | `m.transpose()`, `m.determinant()` | matrix, double |
///
/// The inverse and the transform builders (translate, rotate, ...) are stage 01's
/// pieces: see assignments/01-tuples.
class matrix {
public:
    /// The identity.
    constexpr matrix() : e_{{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}} {}
    /// Sixteen elements, row by row: `m11, m12, m13, m14, m21, ...`.
    constexpr matrix(double m11, double m12, double m13, double m14,
                     double m21, double m22, double m23, double m24,
                     double m31, double m32, double m33, double m34,
                     double m41, double m42, double m43, double m44)
        : e_{{{m11, m12, m13, m14}, {m21, m22, m23, m24}, {m31, m32, m33, m34}, {m41, m42, m43, m44}}} {}
    /// Four row vectors (x, y, z, w of each become one row).
    constexpr matrix(const vector& r1, const vector& r2, const vector& r3, const vector& r4)
        : e_{{{r1.x, r1.y, r1.z, r1.w}, {r2.x, r2.y, r2.z, r2.w},
              {r3.x, r3.y, r3.z, r3.w}, {r4.x, r4.y, r4.z, r4.w}}} {}
    /// Four column points (x, y, z, w of each become one column). With column vectors,
    /// the columns of an affine matrix are the images of the axes and of the origin.
    constexpr matrix(const point& c1, const point& c2, const point& c3, const point& c4)
        : e_{{{c1.x, c2.x, c3.x, c4.x}, {c1.y, c2.y, c3.y, c4.y},
              {c1.z, c2.z, c3.z, c4.z}, {c1.w, c2.w, c3.w, c4.w}}} {}

    /// \name Element access
    ///@{

    /// Element at row `r`, column `c`, both counted from 0.
    constexpr double& operator()(int r, int c) { return e_[static_cast<std::size_t>(r)][static_cast<std::size_t>(c)]; }
    constexpr double operator()(int r, int c) const { return e_[static_cast<std::size_t>(r)][static_cast<std::size_t>(c)]; }
    ///@}
    /// Row `r` (0..3) as a vector: `(m(r,0), m(r,1), m(r,2), m(r,3))`.
    constexpr vector row(int r) const { return {(*this)(r, 0), (*this)(r, 1), (*this)(r, 2), (*this)(r, 3)}; }
    /// Column `c` (0..3) as a point: `(m(0,c), m(1,c), m(2,c), m(3,c))`.
    constexpr point column(int c) const { return {(*this)(0, c), (*this)(1, c), (*this)(2, c), (*this)(3, c)}; }

    /// The matrix mirrored at its diagonal: element (r, c) becomes (c, r).
    constexpr matrix transpose() const {
        matrix t;
        for (int r = 0; r < 4; ++r)
            for (int c = 0; c < 4; ++c) t(r, c) = (*this)(c, r);
        return t;
    }
    /// Determinant by cofactor expansion over 2x2 minors (exact for integer entries).
    double determinant() const;

    /// \name Element-wise arithmetic
    ///@{

    /// Element by element: sum, difference, every element times a number (not a
    /// matrix product: that is `m * m`).
    matrix& operator+=(const matrix& m);
    matrix& operator-=(const matrix& m);
    matrix& operator*=(double d);
    friend matrix operator+(matrix a, const matrix& b) { return a += b; }
    friend matrix operator-(matrix a, const matrix& b) { return a -= b; }
    friend matrix operator*(matrix m, double d) { return m *= d; }
    friend matrix operator*(double d, matrix m) { return m *= d; }
    ///@}

    /// Matrix product: `(a * b) * p == a * (b * p)`, so b is applied first.
    friend matrix operator*(const matrix& a, const matrix& b);
    /// \name Transforming tuples and rays
    ///@{

    /// Applies the matrix to a column vector (see the class table): a point keeps the
    /// translation and is not homogenized, a vector ignores it, a color_point keeps its
    /// colour, a ray gets a transformed origin and a unit transformed direction.
    friend point operator*(const matrix& m, const point& p);
    friend vector operator*(const matrix& m, const vector& v);
    friend color_point operator*(const matrix& m, const color_point& cp);
    friend ray operator*(const matrix& m, const ray& r);
    ///@}
    /// Exact comparison of the 16 elements, no homogenizing (`!=` is generated from it).
    friend constexpr bool operator==(const matrix&, const matrix&) = default;

private:
    std::array<std::array<double, 4>, 4> e_;
};

/// The identity matrix.
inline constexpr matrix IDENTITY{};

/// \name Stream input and output of a matrix
///@{

/// Four rows, each `(a, b, c, d)`, between brackets: `matrix [(1, 0, 0, 0) ...]`.
/// `>>` reads an optional label then either that form or 16 numbers.
std::ostream& operator<<(std::ostream& s, const matrix& m);
std::istream& operator>>(std::istream& s, matrix& m);
///@}

}  // namespace vl
