#pragma once
/// \file
/// \brief What an unfinished stub throws: `not yet implemented: FUNCTION (FILE:LINE)`.

#include <source_location>
#include <stdexcept>
#include <string>

namespace vl {

/// \brief Thrown by a stub that a student has not written yet. The message names the
/// function and where its stub is, so a failing test says which file to open.
class not_implemented_error : public std::logic_error {
public:
    /// The error for the stub at `where` (default: the caller's position).
    explicit not_implemented_error(std::source_location where = std::source_location::current())
        : std::logic_error("not yet implemented: " + function_name(where) + " (" + file_name(where) + ":" +
                           std::to_string(where.line()) + ")") {}

private:
    // "std::unique_ptr<vl::camera> vl::stageNN::make_camera(const ...)" -> "vl::stageNN::make_camera"
    static std::string function_name(const std::source_location& where) {
        std::string f = where.function_name();
        const auto paren = f.find('(');
        if (paren != std::string::npos) f.erase(paren);
        const auto space = f.rfind(' ');
        if (space != std::string::npos) f.erase(0, space + 1);
        return f;
    }
    // The path from "assignments/" on, when it is there: the file a student edits.
    static std::string file_name(const std::source_location& where) {
        const std::string f = where.file_name();
        const auto a = f.rfind("assignments/");
        return a == std::string::npos ? f : f.substr(a);
    }
};

}  // namespace vl
