// Stream input and output of colours, vectors and points (see vl/tuples.hh).
#include "vl/tuples.hh"

#include <cctype>
#include <cstdlib>
#include <string>
#include <iomanip>
#include <istream>
#include <limits>
#include <ostream>

#include "full_precision.hh"
#include "tuple_io.hh"

namespace vl {

namespace tuple_io {

void write4(std::ostream& s, const char* name, double a, double b, double c, double d) {
    const detail::full_precision digits(s);
    if (*name != '\0') s << name << ' ';
    s << '(' << a << ", " << b << ", " << c << ", " << d << ')';
}

void skip_label(std::istream& s) {
    s >> std::ws;
    while (s && std::isalpha(s.peek())) s.get();
}

static bool is_number_char(int c) { return std::isalnum(c) || c == '+' || c == '-' || c == '.'; }

// Reads one number, accepting the `nan`, `inf` and `-inf` that `<<` writes for
// non-finite values (operator>> for double does not), so every tuple round-trips.
// Peeks once per character: a second peek after reaching the end of the input would set
// failbit, and a tuple that ends the input would then read as an error.
static bool read_number(std::istream& s, double& out) {
    s >> std::ws;
    std::string text;
    while (s && is_number_char(s.peek())) text += static_cast<char>(s.get());
    char* end = nullptr;
    const double v = text.empty() ? 0 : std::strtod(text.c_str(), &end);
    if (text.empty() || end != text.c_str() + text.size()) {
        s.setstate(std::ios::failbit);
        return false;
    }
    out = v;
    return true;
}

bool read_numbers(std::istream& s, double* out, int count) {
    skip_label(s);
    s >> std::ws;
    const bool bracketed = s.peek() == '(';
    if (bracketed) s.get();
    for (int i = 0; i < count; ++i) {
        if (!read_number(s, out[i])) return false;
        if (bracketed && i + 1 < count) {
            s >> std::ws;
            if (s.peek() == ',') s.get();
        }
    }
    if (bracketed) {
        s >> std::ws;
        if (s.get() != ')') {
            s.setstate(std::ios::failbit);
            return false;
        }
    }
    return true;
}

}  // namespace tuple_io

std::ostream& operator<<(std::ostream& s, const color& c) {
    tuple_io::write4(s, "color", c.r, c.g, c.b, c.a);
    return s;
}
std::ostream& operator<<(std::ostream& s, const vector& v) {
    tuple_io::write4(s, "vector", v.x, v.y, v.z, v.w);
    return s;
}
std::ostream& operator<<(std::ostream& s, const point& p) {
    tuple_io::write4(s, "point", p.x, p.y, p.z, p.w);
    return s;
}

std::istream& operator>>(std::istream& s, color& c) {
    double v[4];
    if (tuple_io::read_numbers(s, v, 4)) c = {v[0], v[1], v[2], v[3]};
    return s;
}
std::istream& operator>>(std::istream& s, vector& x) {
    double v[4];
    if (tuple_io::read_numbers(s, v, 4)) x = {v[0], v[1], v[2], v[3]};
    return s;
}
std::istream& operator>>(std::istream& s, point& p) {
    double v[4];
    if (tuple_io::read_numbers(s, v, 4)) p = {v[0], v[1], v[2], v[3]};
    return s;
}

}  // namespace vl
