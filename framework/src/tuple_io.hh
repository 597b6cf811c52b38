#pragma once
// Shared by the stream operators of tuples and tuples_based (not installed).
#include <iosfwd>

namespace vl::tuple_io {
/// `name (a, b, c, d)` with round-trip precision; an empty name writes `(a, b, c, d)`.
void write4(std::ostream& s, const char* name, double a, double b, double c, double d);
/// Skips white space and an optional alphabetic label.
void skip_label(std::istream& s);
/// Reads an optional label, then `count` numbers, bare or as `(a, b, ...)`.
bool read_numbers(std::istream& s, double* out, int count);
}  // namespace vl::tuple_io
