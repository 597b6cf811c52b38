#pragma once
/// \file
/// \brief The student kit: the project without reference/ and without the grader's hidden
/// parts, as a folder and a .tar.gz, checked for leaks before it is handed out.
#include <filesystem>
#include <string>
#include <vector>

#include "install.hh"

namespace vl::grader {

/// Writes the kit to `dir` (which must not exist or be empty) and `dir`.tar.gz, then runs
/// find_leaks() on it. Throws grader_error on a leak (the kit is removed) or I/O problem.
void export_kit(const installation& in, const std::filesystem::path& dir);

/// Everything of reference/ and grader/hidden/ found in `kit`: each code line of a
/// reference source that appears nowhere in assignments/ or framework/ (so: a line of a
/// reference function body), and each hidden test's name. Empty when nothing leaked.
std::vector<std::string> find_leaks(const std::filesystem::path& source_dir, const std::filesystem::path& kit);

}  // namespace vl::grader
