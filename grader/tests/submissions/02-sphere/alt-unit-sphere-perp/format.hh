#pragma once
// Numbers in scene files: 17 significant digits (%.17g) are enough for any double to read
// back as exactly itself.

#include <cstdio>
#include <string>

namespace vl::stage02 {

inline std::string exact(double x) {
    char text[40];
    std::snprintf(text, sizeof text, "%.17g", x);
    return text;
}

}  // namespace vl::stage02
