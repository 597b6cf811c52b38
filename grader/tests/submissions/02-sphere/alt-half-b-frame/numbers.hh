#pragma once
// Writing numbers for scene files: the shortest decimal text that reads back as exactly
// the same double (std::to_chars), so write() followed by read() changes nothing.

#include <ostream>

namespace vl::stage02 {

/// Writes `x` as the shortest text that std::from_chars turns back into `x`.
void write_number(std::ostream& s, double x);

}  // namespace vl::stage02
