#pragma once
// Numbers for scene files: printf's %.16e, 17 significant digits, which every double
// survives unchanged when it is read back.

#include <cstdio>
#include <ostream>

namespace vl::stage02 {

inline void write_number(std::ostream& s, double x) {
    char text[40];
    std::snprintf(text, sizeof text, "%.16e", x);
    s << text;
}

}  // namespace vl::stage02
