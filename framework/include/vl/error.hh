#pragma once
/// \file
/// \brief The framework's exceptions: what went wrong, where, and what to do.

#include <stdexcept>
#include <string>

namespace vl {

/// \brief A program used the framework wrongly (inserting into a sphere, an unknown
/// type name registered twice, ...). The message names the object and the fix.
class usage_error : public std::logic_error {
public:
    using std::logic_error::logic_error;
};

/// \brief A file (scene, image) could not be used. The message starts with the file
/// name, and with `:LINE:COL` when the problem has a place in the file.
class file_error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace vl
