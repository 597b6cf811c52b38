#pragma once
/// \file
/// \brief The short summary `grade` prints: score, categories, what failed, where the
/// files are. Coloured when standard output is a terminal (and NO_COLOR is not set).
#include <filesystem>
#include <iosfwd>

#include "grade.hh"

namespace vl::grader {

/// Prints the summary of `g`, whose files are in `out`.
void print_summary(std::ostream& s, const graded_submission& g, const std::filesystem::path& out, bool colour);

/// True when standard output is a terminal that wants colour.
bool stdout_wants_colour();

}  // namespace vl::grader
