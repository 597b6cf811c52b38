// color_point and matrix: products, determinant, stream input and output.
#include "vl/tuples_based.hh"

#include <istream>
#include <ostream>

#include "tuple_io.hh"
#include "vl/ray.hh"

namespace vl {

std::ostream& operator<<(std::ostream& s, const color_point& cp) { return s << cp.clr() << ' ' << cp.pnt(); }

std::istream& operator>>(std::istream& s, color_point& cp) {
    tuple_io::skip_label(s);  // the color_point's own label; the colour may have one too
    color c;
    point p;
    if (s >> c >> p) cp = {c, p};
    return s;
}

namespace homogeneous {
color_point operator*(const color_point& cp, double d) { return {cp.clr(), cp.pnt() * d}; }
color_point operator*(double d, const color_point& cp) { return cp * d; }
color_point operator/(const color_point& cp, double d) { return {cp.clr(), cp.pnt() / d}; }
color_point operator%(const color_point& a, const color_point& b) { return {a.clr(), a.pnt() % b.pnt()}; }
color_point operator%(const vector& v, const color_point& cp) { return {cp.clr(), v % cp.pnt()}; }
color_point& operator*=(color_point& cp, double d) { return cp = cp * d; }
color_point& operator/=(color_point& cp, double d) { return cp = cp / d; }
color_point& operator%=(color_point& cp, const vector& v) {
    point p = cp.pnt();
    cp.set_pnt(p %= v);
    return cp;
}
}  // namespace homogeneous

double matrix::determinant() const {
    const matrix& m = *this;
    // Laplace expansion by complementary 2x2 minors of rows 0-1 and rows 2-3.
    const double s0 = m(0, 0) * m(1, 1) - m(1, 0) * m(0, 1);
    const double s1 = m(0, 0) * m(1, 2) - m(1, 0) * m(0, 2);
    const double s2 = m(0, 0) * m(1, 3) - m(1, 0) * m(0, 3);
    const double s3 = m(0, 1) * m(1, 2) - m(1, 1) * m(0, 2);
    const double s4 = m(0, 1) * m(1, 3) - m(1, 1) * m(0, 3);
    const double s5 = m(0, 2) * m(1, 3) - m(1, 2) * m(0, 3);
    const double c5 = m(2, 2) * m(3, 3) - m(3, 2) * m(2, 3);
    const double c4 = m(2, 1) * m(3, 3) - m(3, 1) * m(2, 3);
    const double c3 = m(2, 1) * m(3, 2) - m(3, 1) * m(2, 2);
    const double c2 = m(2, 0) * m(3, 3) - m(3, 0) * m(2, 3);
    const double c1 = m(2, 0) * m(3, 2) - m(3, 0) * m(2, 2);
    const double c0 = m(2, 0) * m(3, 1) - m(3, 0) * m(2, 1);
    return s0 * c5 - s1 * c4 + s2 * c3 + s3 * c2 - s4 * c1 + s5 * c0;
}

matrix& matrix::operator+=(const matrix& m) {
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) (*this)(r, c) += m(r, c);
    return *this;
}
matrix& matrix::operator-=(const matrix& m) {
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) (*this)(r, c) -= m(r, c);
    return *this;
}
matrix& matrix::operator*=(double d) {
    for (auto& row : e_)
        for (double& x : row) x *= d;
    return *this;
}

matrix operator*(const matrix& a, const matrix& b) {
    matrix p;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c)
            p(r, c) = a(r, 0) * b(0, c) + a(r, 1) * b(1, c) + a(r, 2) * b(2, c) + a(r, 3) * b(3, c);
    return p;
}

point operator*(const matrix& m, const point& p) {
    return {m.row(0).x * p.x + m.row(0).y * p.y + m.row(0).z * p.z + m.row(0).w * p.w,
            m.row(1).x * p.x + m.row(1).y * p.y + m.row(1).z * p.z + m.row(1).w * p.w,
            m.row(2).x * p.x + m.row(2).y * p.y + m.row(2).z * p.z + m.row(2).w * p.w,
            m.row(3).x * p.x + m.row(3).y * p.y + m.row(3).z * p.z + m.row(3).w * p.w};
}

vector operator*(const matrix& m, const vector& v) {
    const point p = m * point(v.x, v.y, v.z, v.w);
    return {p.x, p.y, p.z, p.w};
}

color_point operator*(const matrix& m, const color_point& cp) { return {cp.clr(), m * cp.pnt()}; }

ray operator*(const matrix& m, const ray& r) { return {m * r.origin(), m * r.direction()}; }

std::ostream& operator<<(std::ostream& s, const matrix& m) {
    s << "matrix [";
    for (int r = 0; r < 4; ++r) {
        const vector row = m.row(r);
        if (r > 0) s << ' ';
        tuple_io::write4(s, "", row.x, row.y, row.z, row.w);
    }
    return s << ']';
}

std::istream& operator>>(std::istream& s, matrix& m) {
    tuple_io::skip_label(s);
    s >> std::ws;
    const bool bracketed = s.peek() == '[';
    if (bracketed) s.get();
    double v[4][4];
    for (auto& row : v)
        if (!tuple_io::read_numbers(s, row, 4)) return s;
    if (bracketed) {
        s >> std::ws;
        if (s.get() != ']') {
            s.setstate(std::ios::failbit);
            return s;
        }
    }
    m = matrix(vector(v[0][0], v[0][1], v[0][2], v[0][3]), vector(v[1][0], v[1][1], v[1][2], v[1][3]),
               vector(v[2][0], v[2][1], v[2][2], v[2][3]), vector(v[3][0], v[3][1], v[3][2], v[3][3]));
    return s;
}

}  // namespace vl
