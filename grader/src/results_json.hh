#pragma once
/// \file
/// \brief results.json in Gradescope's autograder format
/// (https://gradescope-autograders.readthedocs.io/en/latest/specs/).
#include <filesystem>
#include <string>

#include "grade.hh"

namespace vl::grader {

/// The JSON text of `g`: score, execution_time, output, tests[] (name, number, score,
/// max_score, status, tags, visibility, output), with the categories in extra_data.
std::string results_json(const graded_submission& g);

/// Writes results_json(g) to `file`.
void write_results_json(const graded_submission& g, const std::filesystem::path& file);

}  // namespace vl::grader
