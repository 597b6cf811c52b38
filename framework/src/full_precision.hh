#pragma once
// The framework's writers of scene text (tuples, surfaces, the staged shapes' parameters)
// write doubles with max_digits10 digits, so that reading them back gives the same
// doubles, and leave the stream's precision as they found it.

#include <limits>
#include <ostream>

namespace vl::detail {

/// Sets `s` to max_digits10 digits while it lives, then back to what it was.
class full_precision {
public:
    explicit full_precision(std::ostream& s) : s_(s), old_(s.precision(std::numeric_limits<double>::max_digits10)) {}
    ~full_precision() { s_.precision(old_); }
    full_precision(const full_precision&) = delete;
    full_precision& operator=(const full_precision&) = delete;

private:
    std::ostream& s_;
    std::streamsize old_;
};

}  // namespace vl::detail
