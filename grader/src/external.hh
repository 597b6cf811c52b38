#pragma once
/// \file
/// \brief The trusted programs the grader runs outside any sandbox, on its own files only:
/// ImageMagick's `compare` (the report's highlighted difference) and the reference
/// renderer (calibrate-thresholds).
#include <filesystem>
#include <string>
#include <vector>

namespace vl::grader {

/// Runs `argv` (argv[0] is looked up on PATH) with stdin from /dev/null and its output
/// into `log`; stops it after `timeout_seconds`. Returns "" when it exited with a status
/// of at most `ok_status`, else why not (with the head of its output); never throws.
std::string run_tool(const std::vector<std::string>& argv, const std::filesystem::path& log, int timeout_seconds,
                     int ok_status = 0);

/// Runs `compare -fuzz FUZZ% png:reference png:test png:out`: the reference faded, the
/// pixels that differ in red. Both inputs must be PNGs the grader wrote itself, never a
/// submission's bytes. Returns "" when `out` was written, else why not.
std::string highlight_difference(const std::filesystem::path& reference, const std::filesystem::path& test,
                                 const std::filesystem::path& out, double fuzz_percent = 2);

}  // namespace vl::grader
