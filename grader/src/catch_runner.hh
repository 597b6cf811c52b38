#pragma once
/// \file
/// \brief Running Catch2 test programs one test case per process, and reading only what
/// Catch2's XML reporter wrote to a pipe the grader gave it (never the program's output).
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "item_result.hh"
#include "sandbox.hh"

namespace vl::grader {

/// \brief A hidden test case, as the trusted build (hidden tests + reference) lists it.
struct test_case_info {
    std::string name;
    std::vector<std::string> tags;  ///< without brackets: "02", "sphere", "hits"
    std::string raw_tags;           ///< as Catch2 reports them: "[02][sphere][hits]"
    std::string file, line;         ///< where the test is defined, as Catch2 reports it
};

/// \brief How one test case went.
struct test_outcome {
    item_result result = item_result::not_run;  ///< passed, failed, crashed, timed out or not run
    std::string message;  ///< what failed, where, with which values
    double seconds = 0;
    /// The test's Catch2 warnings, in order (a sweep or chart test reports its points so);
    /// only from a genuine report of this test.
    std::vector<std::string> warnings;
};

/// Runs the trusted program once and returns its test cases. Throws grader_error when it
/// cannot run, or when a hidden test fails with the reference (the test or the reference
/// is wrong, and no student should lose points for it).
std::vector<test_case_info> list_trusted_tests(const std::filesystem::path& program, const std::filesystem::path& work,
                                               const sandbox_capabilities& caps);

/// Runs the graded tests linked with the untouched stubs (`program`) and returns the names
/// of those that pass: they check what the kit already supplies, and earn nothing.
std::set<std::string> tests_passing_on_stubs(const std::filesystem::path& program, const std::filesystem::path& work,
                                             const sandbox_capabilities& caps);

/// Runs the test case `name` of `program` alone, in a sandbox of its own.
/// A report counts only when the test case in it is `test` as the trusted program knows it
/// (the same name, tags, file and line: details a report forged from outside Catch2 lacks).
test_outcome run_test_case(const std::filesystem::path& program, const test_case_info& test, const run_limits& limits,
                           const sandbox_capabilities& caps);

/// The descriptor on which the judge and the subject find their connection
/// (vl::remote::channel_fd in grader/remote/channel.hh).
inline constexpr int remote_channel_fd = 5;

/// Runs the test case `test` as a judge and a subject (grader/README.md, "Who holds
/// what"): `judge` holds the test and decides; `subject` holds the submission's code and
/// answers the judge's calls over a socket. Each runs in a sandbox of its own. The
/// verdict is the judge's; a subject that crashes, ends, hangs or answers out of turn
/// fails the test (or, having crashed, makes it crashed), never the grader.
test_outcome run_judged_test_case(const std::filesystem::path& judge, const std::filesystem::path& subject,
                                  const test_case_info& test, const run_limits& limits, const sandbox_capabilities& caps);

/// \brief The programs that run a submission's graded tests.
struct test_programs {
    std::filesystem::path judge;    ///< the stage's judge (the main build's); empty: the tests are not split
    std::filesystem::path subject;  ///< the submission's subject; with no judge, the one program of tests and code
    bool empty() const { return subject.empty(); }
};

/// Runs `test` with `programs`: judged, or (a stage whose tests are not split yet) in one program.
test_outcome run_graded_test(const test_programs& programs, const test_case_info& test, const run_limits& limits,
                             const sandbox_capabilities& caps);

/// True when `file` (a test's source, as Catch2 reports it) is one of a stage's public
/// tests, which the student has in their tests/ folder.
bool is_public_test_file(const std::string& file);

/// The test named `name` among `tests`; throws grader_error when there is none (the
/// rubric names a test the hidden tests do not have).
const test_case_info& named_test(const std::vector<test_case_info>& tests, const std::string& name);

/// A Catch2 test spec that matches exactly `name` (its special characters escaped).
std::string exact_test_spec(const std::string& name);

}  // namespace vl::grader
