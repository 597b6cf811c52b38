#pragma once
/// \file
/// \brief What a stage's code may do: it computes. Before anything built from a submission
/// runs, every student object file (its symbols, through `nm`) and every student source
/// (as the compiler saw it, preprocessed) is checked against this policy. Pieces do not
/// open or write files, end the process, start processes, send signals, use the network,
/// load code, map memory, make system calls, use inline assembly, run code before main,
/// touch the intersection counters or the test framework, replace a symbol that the
/// framework, the tests or the runtime define, or hide where their lines come from
/// (`#line`). Printing to stdout and stderr is allowed.
///
/// The sandbox would contain most of this anyway; the policy is what keeps a test's
/// verdict honest, since the test and the student's code share one process.
#include <set>
#include <string>
#include <vector>

namespace vl::grader {

/// \brief One thing a submission may not do, and where it does it.
struct policy_finding {
    std::string file;    ///< the student's file ("sphere.cc")
    int line = 0;        ///< 0: found in the object file, not at a line
    std::string what;    ///< the symbol or the words ("fopen", "asm")
    std::string reason;  ///< "opens or writes files", ...
    /// "sphere.cc:12: uses 'asm' (uses inline assembly)"
    std::string describe() const;
};

/// \brief One symbol of an object file, as `nm -P` lists it.
struct object_symbol {
    std::string name;       ///< mangled
    std::string demangled;  ///< as `nm -C` shows it
    char type = '?';        ///< nm's letter: U undefined, T text, W weak, ...
};

/// Parses `nm -A -P` output (and the same with -C, line for line) into symbols per file.
std::vector<std::pair<std::string, object_symbol>> parse_nm(const std::string& mangled, const std::string& demangled);

/// Checks one object's symbols. `protected_symbols` holds every global symbol that the
/// prebuilt parts linked with it and the shared libraries define (the stage's own
/// reference excluded); `strong` marks those that not even a weak definition may shadow:
/// the prebuilt parts' strong definitions and the runtime's C functions (open, malloc).
std::vector<policy_finding> check_symbols(const std::string& file, const std::vector<object_symbol>& symbols,
                                          const std::set<std::string>& protected_symbols,
                                          const std::set<std::string>& strong);

/// Checks a preprocessed source (`g++ -E` output): only the lines that come from the
/// student's own files: those whose line markers name a path under `student_prefix`, or
/// any path not under one of the `trusted` folders (the toolchain's and the framework's
/// headers), whatever its spelling.
std::vector<policy_finding> check_preprocessed(const std::string& text, const std::string& student_prefix,
                                               const std::vector<std::string>& trusted = {"/usr/", "/vl/framework/",
                                                                                          "/vl/contract/"});

/// Checks a student's file as written: a `#line` directive would make the preprocessed
/// text say its code comes from another file (a system header), out of check_preprocessed's sight.
std::vector<policy_finding> check_raw_source(const std::string& file, const std::string& text);

}  // namespace vl::grader
