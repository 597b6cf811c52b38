#pragma once
// Numbers for scene files in scientific notation with 17 significant digits (to_chars),
// enough for every double to read back as itself.

#include <charconv>
#include <ostream>
#include <string_view>

#include "vl/tuples.hh"

namespace vl::stage02 {

inline void put(std::ostream& s, double x) {
    char text[48];
    const auto result = std::to_chars(text, text + sizeof text, x, std::chars_format::scientific, 16);
    s << std::string_view(text, static_cast<std::size_t>(result.ptr - text));
}

inline void put(std::ostream& s, const point& p, const char* separator) {
    put(s, p.x);
    s << separator;
    put(s, p.y);
    s << separator;
    put(s, p.z);
}

}  // namespace vl::stage02
