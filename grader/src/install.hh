#pragma once
/// \file
/// \brief Where the grader's parts are: read from `grader.toml`, which the build writes
/// next to the grader program (grader/CMakeLists.txt).
#include <filesystem>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace vl::grader {

/// \brief A problem that stops the grader itself (not a problem of a submission): the
/// message says what is wrong and what to do; the program exits non-zero.
class grader_error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// \brief One gradable stage of this build.
struct stage_info {
    std::string name;                    ///< "02-sphere"
    std::string number;                  ///< "02"
    std::filesystem::path trusted_tests; ///< hidden tests linked with the reference (empty: none)
    std::filesystem::path tests_on_stubs; ///< the same tests linked with the untouched stubs
    std::filesystem::path reference_library;          ///< the stage's reference, a static library
    /// The oracle, the reference again in namespace vl::reference_stageNN: the map of its
    /// objects and of the pieces they hold (oracle.hh).
    std::filesystem::path oracle_map;
    std::vector<std::filesystem::path> hidden_objects;  ///< the hidden tests, compiled
    /// The stage's judge: the graded tests, whose calls into the stage cross to a subject
    /// (empty: the stage's tests still run in one program with the submission's code).
    std::filesystem::path judge;
    /// The subject's own parts (its main, the stage's calls), linked with a submission.
    std::vector<std::filesystem::path> subject_objects;
    /// The stages ("02") whose pieces the subject asks of the judge: their reference is not
    /// linked into the subject.
    std::vector<std::string> subject_without;
};

/// \brief The grader's installation: the source tree, the main build and its parts.
struct installation {
    std::filesystem::path source_dir, build_dir, grader_build_dir;
    std::filesystem::path reference_renderer, reference_renders;
    /// How a submission is compiled and linked: the same compiler and code generation as
    /// the prebuilt parts it is linked with.
    std::filesystem::path cxx_compiler;
    std::vector<std::string> cxx_flags, link_flags, system_libraries;
    std::vector<std::filesystem::path> framework_libraries, renderer_objects;
    std::filesystem::path catch_main;
    std::string build_type;
    bool sanitized = false;             ///< built with AddressSanitizer (no address-space limit then)
    std::map<std::string, stage_info> stages;

    /// grader/hidden/NN-name.
    std::filesystem::path hidden_dir(const stage_info& s) const { return source_dir / "grader" / "hidden" / s.name; }
    /// assignments/NN-name: the contract header and the stubs.
    std::filesystem::path assignment_dir(const stage_info& s) const { return source_dir / "assignments" / s.name; }
    /// assignments/NN-name/stage_NN.hh: the stage's contract, which the grader always uses
    /// as handed out. Other headers beside it (stage 03's bounding_sphere.hh) are the
    /// student's to change, like the .cc files.
    std::filesystem::path contract_header(const stage_info& s) const {
        return assignment_dir(s) / ("stage_" + s.number + ".hh");
    }
    /// assignments/NN-name/register.cc: the stage's scene-file names, complete in the stubs
    /// and shared by the reference. Like the contract, the grader always compiles it as
    /// handed out: a submission need not hold it, and its own copy is replaced.
    std::filesystem::path registration(const stage_info& s) const { return assignment_dir(s) / "register.cc"; }

    /// The stage an instructor means by `what`: "02", "02-sphere" or "sphere".
    const stage_info& find_stage(const std::string& what) const;
};

/// Reads grader.toml beside the running program.
installation load_installation();

}  // namespace vl::grader
