#pragma once
/// \file
/// \brief Building a submitted stage, every step in its own sandbox: each of its .cc files
/// is preprocessed and compiled (seeing only the framework's headers, the pristine
/// contracts and the student's own files), its objects and sources are checked against the
/// policy (policy.hh), and then they are linked, with no source in sight, to the prebuilt
/// framework, the other stages' reference and the hidden tests (as objects) into the test
/// program (hidden_tests, or the subject of a judge) and, with the renderer and the graded
/// stage's oracle (oracle.hh), into one render program per set of pieces the scenes grade.
#include <filesystem>
#include <string>
#include <vector>

#include "install.hh"
#include "sandbox.hh"
#include "catch_runner.hh"
#include "scenes.hh"
#include "submission.hh"

namespace vl::grader {

/// \brief The result of a submission's build.
struct build_outcome {
    bool ok = false;
    bool refused = false;                 ///< built, but the policy refused it
    std::string errors;                   ///< the first compiler errors, or the refusals
    double seconds = 0;
    test_programs tests;                  ///< what runs the graded tests (may be empty)
    std::vector<render_program> renders;  ///< one per distinct set of oracle objects left out
    std::vector<std::size_t> render_of;   ///< for each of build_options::scene_pieces, its render
};

/// \brief How to build.
struct build_options {
    bool policy = true;           ///< false only to test the sandbox alone (calibration)
    double wall_seconds = 600;    ///< what is left of the grade's time
    /// The pieces each graded scene takes from the submission (its student_pieces; empty:
    /// all of the stage's): they decide the render programs.
    std::vector<std::vector<std::string>> scene_pieces;
};

/// \brief How a compile uses the grader's compile cache (ccache, in the build tree).
enum class cache_use { none, read_only, write };

/// \brief What compiling a set of files gave.
struct compile_outcome {
    std::string errors;          ///< the compiler's messages for the files that failed
    std::string grader_failure;  ///< the sandbox could not run the compiler
};

/// Preprocesses and compiles `files` of `sources` (with the contracts of `contract`) into
/// `objects` (made by make_sandbox_dir), each in its own sandbox, two at a time. Only
/// seed_compile_cache writes to the cache; a submission reads it.
compile_outcome compile_sources(const installation& in, const stage_info& stage, const std::filesystem::path& sources,
                                const std::filesystem::path& contract, const std::vector<std::string>& files,
                                const std::filesystem::path& objects, const sandbox_capabilities& caps, cache_use cache,
                                double wall_seconds);

/// Compiles the stage's reference and stubs (trusted sources) into the compile cache, when
/// they or the framework's headers changed since the last time; `work` is a scratch folder.
void seed_compile_cache(const installation& in, const stage_info& stage, const std::filesystem::path& work,
                        const sandbox_capabilities& caps);

/// Compiles, checks and links `sub` in `work` (a fresh folder of the grader's).
build_outcome build_submission(const prepared_submission& sub, const stage_info& stage, const installation& in,
                               const std::filesystem::path& work, const sandbox_capabilities& caps,
                               const build_options& options);

/// The first errors of a compiler's output, with the sandbox's folders named for a reader
/// (the student's files by name, `<framework>/vl/...`, `<contract>/...`), at most about
/// `max_lines` lines.
std::string trim_compiler_errors(const std::string& log, int max_lines = 30);

/// `errors` with, first, a note for each contract header the student had changed: the
/// grader used the original, which is often why their code no longer compiles or links.
std::string with_contract_note(const prepared_submission& sub, std::string errors);

/// What a failed link says, in terms a student can act on: the missing and the doubly
/// defined symbols (with which of `files`, the submission's .cc files, define them), never
/// the paths or names of the grader's parts.
std::string explain_link_errors(const std::string& log, const std::vector<std::string>& files);

}  // namespace vl::grader
