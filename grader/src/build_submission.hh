#pragma once
/// \file
/// \brief Building a submitted stage: grader/submission/CMakeLists.txt compiles only its
/// .cc files and links them with the prebuilt framework and the other stages' reference.
#include <filesystem>
#include <string>

#include "install.hh"
#include "sandbox.hh"
#include "submission.hh"

namespace vl::grader {

/// \brief The result of a submission's build.
struct build_outcome {
    bool ok = false;
    std::string errors;                  ///< the first compiler errors, trimmed for a reader
    double seconds = 0;
    std::filesystem::path tests_program; ///< hidden tests with the submitted stage (may be absent)
    std::filesystem::path render_program;///< rt with the submitted stage
};

/// Configures and builds `sub` in `build_dir`, sandboxed.
build_outcome build_submission(const prepared_submission& sub, const stage_info& stage, const installation& in,
                               const std::filesystem::path& build_dir, const sandbox_capabilities& caps);

/// The first errors of a compiler's output: paths made relative to `sources`, the
/// build tool's command lines dropped, at most about `max_lines` lines.
std::string trim_compiler_errors(const std::string& log, const std::filesystem::path& sources, int max_lines = 30);

}  // namespace vl::grader
