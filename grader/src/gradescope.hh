#pragma once
/// \file
/// \brief A Gradescope autograder bundle: a zip with setup.sh, run_autograder and
/// autograder.conf at its top (Gradescope's layout: unpacked into /autograder/source) and
/// the project source that grading one assignment needs (grader/README.md, "Gradescope").
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "install.hh"

namespace vl::grader {

/// \brief What went into a bundle.
struct gradescope_bundle {
    std::filesystem::path zip;         ///< the bundle written
    std::string assignment;            ///< the stage it grades, "02-sphere"
    std::size_t files = 0;             ///< project files in it (besides the three at its top)
    bool from_git = false;             ///< the files are `git ls-files` of the source folder
    std::vector<std::string> untracked;  ///< files git does not track, so left out (a few)
    std::size_t untracked_count = 0;   ///< how many there are in all
    /// What the command prints: where the bundle is, what it holds, what to do with it.
    std::string summary() const;
};

/// The project files of `source_dir` a grade needs, relative to it and sorted: `git
/// ls-files` when it is a git checkout (and git is there), else every regular file but
/// build/ and .git; without what a grade never reads (.ci/, bench/, kit/, docs/ but the
/// two files CMake configures with). Sets `bundle.from_git` and the untracked files.
/// Throws grader_error when git refuses the checkout.
std::vector<std::filesystem::path> bundle_files(const std::filesystem::path& source_dir, gradescope_bundle& bundle);

/// Writes the bundle that grades `stage` to `zip` (a name ending in .zip; written whole or
/// not at all): setup.sh and run_autograder (from grader/gradescope/), autograder.conf
/// naming the stage, and bundle_files(). File times and modes are fixed and the names
/// sorted, so the same tree gives the same bytes. Throws grader_error.
gradescope_bundle write_gradescope_bundle(const installation& in, const stage_info& stage,
                                          const std::filesystem::path& zip);

}  // namespace vl::grader
