#pragma once
/// \file
/// \brief Building a submitted stage, every step in its own sandbox: each of its .cc files
/// is preprocessed and compiled (seeing only the framework's headers, the pristine
/// contracts and the student's own files), its objects and sources are checked against the
/// policy (policy.hh), and then they are linked, with no source in sight, to the prebuilt
/// framework, the other stages' reference and the hidden tests (as objects) into two
/// programs: hidden_tests and render.
#include <filesystem>
#include <string>

#include "install.hh"
#include "sandbox.hh"
#include "submission.hh"

namespace vl::grader {

/// \brief The result of a submission's build.
struct build_outcome {
    bool ok = false;
    bool refused = false;                 ///< built, but the policy refused it
    std::string errors;                   ///< the first compiler errors, or the refusals
    double seconds = 0;
    std::filesystem::path tests_program;  ///< hidden tests with the submitted stage (may be absent)
    std::filesystem::path render_program; ///< rt with the submitted stage
};

/// \brief How to build.
struct build_options {
    bool policy = true;           ///< false only to test the sandbox alone (calibration)
    double wall_seconds = 600;    ///< what is left of the grade's time
};

/// Compiles, checks and links `sub` in `work` (a fresh folder of the grader's).
build_outcome build_submission(const prepared_submission& sub, const stage_info& stage, const installation& in,
                               const std::filesystem::path& work, const sandbox_capabilities& caps,
                               const build_options& options);

/// The first errors of a compiler's output, with the sandbox's folders named for a reader
/// (the student's files by name, `<framework>/vl/...`, `<contract>/...`), at most about
/// `max_lines` lines.
std::string trim_compiler_errors(const std::string& log, int max_lines = 30);

/// What a failed link says, in terms a student can act on: the missing and the doubly
/// defined symbols, never the paths or names of the grader's parts.
std::string explain_link_errors(const std::string& log);

}  // namespace vl::grader
