#pragma once
/// \file
/// \brief The grader's calibration cases (grader/tests/submissions/NN-name/CASE/ and the
/// attacks of grader/tests/adversarial/): each a submission, planted as a patch against the
/// reference or the stubs, made by a script or given as files, and its expected.toml.
/// `grader/run calibrate` grades one and checks it (calibration.cc); `demo` grades them all.
#include <filesystem>
#include <string>
#include <vector>

#include "install.hh"

namespace vl::grader {

/// \brief A calibration case: grader/tests/submissions/NN-name/CASE/expected.toml.
struct calibration_case {
    std::string stage, name, description;
    std::filesystem::path submission, expected;
    double budget_seconds = 0;  ///< expected.toml's budget_seconds: a shorter grade budget than the rubric's
    std::string variant;        ///< "-sandbox" when graded with the policy off (its own patched copy)
};

/// Every stage's cases in grader/tests/submissions, by stage and name; each submission
/// made (a patch applied, a script run) as it is read.
std::vector<calibration_case> all_cases(const installation& in);

}  // namespace vl::grader
