#pragma once
/// \file
/// \brief Running untrusted programs (a submission's unpacking, compiles, links, tests and
/// renders) inside bubblewrap.
///
/// Each sandboxed program sees only what its run_request mounts, read-only unless a mount
/// says otherwise: the toolchain (/usr), the mounts (each handed to bubblewrap as an open
/// file descriptor, so no path the program could have planted is ever followed), a private
/// size-capped tmpfs at /scratch (its working folder) and another at /tmp, a fresh /proc
/// and /dev. It has no network and its own PID, IPC and UTS namespaces; it runs as uid
/// 65534 in a user namespace of its own, with no capabilities and no way to make another
/// user namespace. When the grader runs as root, bubblewrap itself is started as `nobody`,
/// so nothing in the sandbox is root outside it either. Limits: wall-clock time (the whole
/// sandbox is killed), CPU time, address space (not under AddressSanitizer), file size,
/// open files and processes (threads count).
///
/// Its stdout and stderr come back through a pipe (the first limits.output_bytes kept, the
/// rest counted); with report_fd, a second pipe is its fd 3 (a Catch2 report, a PNG).
/// Nothing the program writes reaches the host's disk except through a writable mount.
///
/// Where bubblewrap cannot run (no user namespaces), probe_sandbox() refuses unless the
/// weaker sandbox was asked for: the same limits and pipes, namespaces where the machine
/// allows them, host paths in place of mounts. sandbox_capabilities::summary() says which.
#include <cstdint>
#include <filesystem>
#include <string>
#include <sys/types.h>
#include <vector>

namespace vl::grader {

/// \brief Limits for one run.
struct run_limits {
    double wall_seconds = 10;
    double cpu_seconds = 0;                               ///< 0: wall_seconds + 1
    std::uint64_t memory_bytes = std::uint64_t{1} << 31;  ///< address space; 0: no limit
    std::uint64_t file_bytes = std::uint64_t{64} << 20;   ///< largest file it may write
    std::uint64_t scratch_bytes = std::uint64_t{64} << 20;  ///< the tmpfs at /scratch (and at /tmp)
    int processes = 16;                                   ///< threads count too
    std::size_t output_bytes = 64 << 10;                  ///< stdout+stderr kept (the rest is counted)
    std::size_t report_bytes = 32 << 20;                  ///< fd 3: more than this ends the run
};

/// \brief How programs are isolated here.
enum class isolation {
    bubblewrap,  ///< everything in the file comment
    weaker,      ///< no bubblewrap: limits, pipes and what namespaces the machine allows
};

/// \brief What this machine lets the sandbox do (probed once per grade).
struct sandbox_capabilities {
    isolation mode = isolation::bubblewrap;
    std::filesystem::path bwrap = "/usr/bin/bwrap";
    bool drop_to_nobody = false;    ///< the grader is root: bubblewrap runs as nobody
    uid_t uid = 65534;
    gid_t gid = 65534;
    bool address_limit = true;      ///< RLIMIT_AS applies (not under AddressSanitizer)
    bool network_isolated = false;  ///< weaker mode: a new network namespace worked
    /// One line for the report: what is isolated and what is not.
    std::string summary() const;
};

/// Finds out what the sandbox can do here. Without a working bubblewrap it throws
/// grader_error saying why and what to do, unless `allow_weaker`.
sandbox_capabilities probe_sandbox(bool sanitized, bool allow_weaker);

/// \brief A host file or folder that a sandboxed program sees at `inside`.
struct mount {
    std::filesystem::path host;
    std::string inside;
    bool writable = false;
};

/// \brief One program to run.
struct run_request {
    std::vector<std::string> argv;         ///< paths as the program sees them
    std::string cwd = "/scratch";          ///< as the program sees it
    std::vector<mount> mounts;
    std::vector<std::pair<std::string, std::string>> symlinks;  ///< {target, link}, both inside
    std::vector<std::string> environment;  ///< the whole environment of the child
    run_limits limits;
    bool report_fd = false;                ///< fd 3 is a pipe into run_result::report
    /// A connected socket (close-on-exec) that the program gets as descriptor 5: the judge's
    /// and the subject's connection (grader/remote/channel.hh). run() closes it once the
    /// program has started, so that the other end sees the connection end with the program.
    int channel = -1;
    /// false: a trusted program of the grader's own build; argv and cwd are host paths and
    /// only the timeout and the pipes apply.
    bool sandboxed = true;
};

/// \brief How it ended.
struct run_result {
    bool started = false;        ///< false: the sandbox could not start it (the grader's failure)
    bool timed_out = false;
    bool report_overflow = false;  ///< fd 3 got more than limits.report_bytes
    int exit_code = -1;          ///< when it exited
    int signal = 0;              ///< when a signal ended it
    double seconds = 0;
    std::string error;           ///< why it could not start
    std::string output;          ///< the first limits.output_bytes of stdout and stderr
    std::uint64_t output_bytes = 0;  ///< all it printed
    std::string report;          ///< what it wrote to fd 3
    bool succeeded() const { return started && !timed_out && signal == 0 && exit_code == 0; }
    /// "exit code 1", "killed by SIGSEGV (segmentation fault)", "timed out after 10 s", ...
    std::string describe(double timeout) const;
    /// The output, with a note of how much more there was.
    std::string output_head(std::size_t max_bytes) const;
    /// The last `max_bytes` of the output kept (where a program's last words, its error,
    /// are), saying how much came before and how much was not kept.
    std::string output_tail(std::size_t max_bytes) const;
};

/// Runs `request`, waiting for it to end or time out.
run_result run(const run_request& request, const sandbox_capabilities& caps);

/// A minimal environment for children: PATH, HOME=`home`, LANG=C.UTF-8, plus `extra`.
std::vector<std::string> child_environment(const std::string& home, std::vector<std::string> extra = {});

/// Makes `dir` (which must not exist; its parent must be the grader's) an empty folder a
/// sandboxed program may write into through a writable mount: as root, handed to the
/// sandbox's user by descriptor while it is still empty. Throws grader_error.
void make_sandbox_dir(const std::filesystem::path& dir, const sandbox_capabilities& caps);

}  // namespace vl::grader
