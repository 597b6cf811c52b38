#pragma once
// Numbers for scene files: std::to_chars with 17 significant digits, which every double
// survives unchanged on the way back through std::from_chars.

#include <charconv>
#include <ostream>
#include <string_view>

namespace vl::stage02 {

struct number {
    double value;
};

inline std::ostream& operator<<(std::ostream& s, number n) {
    char text[48];
    const auto result = std::to_chars(text, text + sizeof text, n.value, std::chars_format::general, 17);
    return s << std::string_view(text, static_cast<std::size_t>(result.ptr - text));
}

}  // namespace vl::stage02
