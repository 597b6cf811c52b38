#pragma once
/// \file
/// \brief Running untrusted programs (a submission's build, tests and renders).
///
/// Each program runs in a child process with:
/// - a wall-clock timeout, after which its whole process group is killed;
/// - resource limits (setrlimit in the child): CPU seconds, address space (not under
///   AddressSanitizer, which reserves terabytes of it), file size, open files, processes;
/// - when the machine allows it (root, or unprivileged namespaces): no network (a new,
///   empty network namespace) and its own PID namespace, so every process it started dies
///   with it;
/// - when the grader runs as root: the user `nobody`, so it cannot touch the grader's files.
/// What the machine does not allow is skipped and said in sandbox_capabilities::summary().
#include <cstdint>
#include <filesystem>
#include <string>
#include <sys/types.h>
#include <vector>

namespace vl::grader {

/// \brief Limits for one run.
struct run_limits {
    double wall_seconds = 10;
    double cpu_seconds = 0;                            ///< 0: wall_seconds + 1
    std::uint64_t memory_bytes = std::uint64_t{1} << 31;  ///< address space; 0: no limit
    std::uint64_t file_bytes = std::uint64_t{256} << 20;  ///< largest file it may write
    int processes = 256;                               ///< threads count too
};

/// \brief What this machine lets the sandbox do (probed once).
struct sandbox_capabilities {
    bool network_isolated = false;  ///< new network namespace
    bool pid_isolated = false;      ///< new PID namespace
    bool unprivileged = false;      ///< children run as `uid`
    uid_t uid = 0;
    gid_t gid = 0;
    bool address_limit = true;      ///< RLIMIT_AS applies (not under AddressSanitizer)
    /// One line for the report: what is isolated and what is not.
    std::string summary() const;
};

/// Finds out what the sandbox can do here.
sandbox_capabilities probe_sandbox(bool sanitized);

/// \brief One program to run.
struct run_request {
    std::vector<std::string> argv;
    std::filesystem::path cwd;
    std::filesystem::path output;         ///< stdout and stderr go here (created)
    std::vector<std::string> environment; ///< the whole environment of the child
    run_limits limits;
    bool sandboxed = true;                ///< false: only the timeout (trusted programs)
};

/// \brief How it ended.
struct run_result {
    bool started = false;
    bool timed_out = false;
    int exit_code = -1;  ///< when it exited
    int signal = 0;      ///< when a signal ended it
    double seconds = 0;
    std::string error;   ///< why it could not start
    bool succeeded() const { return started && !timed_out && signal == 0 && exit_code == 0; }
    /// "exit code 1", "killed by SIGSEGV (segmentation fault)", "timed out after 10 s", ...
    std::string describe(double timeout) const;
};

/// Runs `request`, waiting for it to end or time out.
run_result run(const run_request& request, const sandbox_capabilities& caps);

/// A minimal environment for children: PATH, HOME=`home`, LANG=C.UTF-8, plus `extra`.
std::vector<std::string> child_environment(const std::filesystem::path& home, std::vector<std::string> extra = {});

/// Hands `dir` and everything under it to the sandbox's user, so children can write there.
void give_to_sandbox(const std::filesystem::path& dir, const sandbox_capabilities& caps);

/// The first `max_bytes` of a file (a child's output), with a note when there is more.
std::string read_head(const std::filesystem::path& file, std::size_t max_bytes);

}  // namespace vl::grader
