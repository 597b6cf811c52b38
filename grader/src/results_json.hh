#pragma once
/// \file
/// \brief results.json in Gradescope's autograder format
/// (https://gradescope-autograders.readthedocs.io/en/latest/specs/).
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "grade.hh"

namespace vl::grader {

/// The JSON text of `g`: score, execution_time, output, tests[] (name, number, score,
/// max_score, status, tags, visibility, output), with the categories in extra_data.
std::string results_json(const graded_submission& g);

/// Writes results_json(g) to `file`.
void write_results_json(const graded_submission& g, const std::filesystem::path& file);

/// What in `r` breaks Gradescope's documented results.json format (the autograder
/// specification: top-level score, execution_time, output, stdout_visibility, tests; each
/// test's score, max_score, status, name, number, output, tags, visibility); nothing when
/// it keeps to it. The calibration checks every grade's results.json with it.
std::vector<std::string> gradescope_format_problems(const nlohmann::json& r);

}  // namespace vl::grader
