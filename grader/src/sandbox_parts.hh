#pragma once
/// \file
/// \brief What the sandbox's files share (sandbox.hh is the interface): the descriptors a
/// child is given, the command lines made before fork, bubblewrap's
/// (sandbox_bubblewrap.cc) and the weaker sandbox's (sandbox_weaker.cc), and the resource
/// limits a child sets on itself after fork (sandbox_limits.cc). sandbox.cc runs them.
#include <filesystem>
#include <string>
#include <vector>

#include "sandbox.hh"

namespace vl::grader::sandbox_parts {

constexpr int report_fd_number = 3;
constexpr int status_fd_number = 4;  // bubblewrap's --json-status-fd
constexpr int channel_fd_number = 5;  // run_request::channel (vl::remote::channel_fd)
constexpr int first_mount_fd = 6;
// As root, the mounts are first bound here, in a private mount namespace of the child, so
// that bubblewrap, started as nobody, can reach them whatever folders (a 0700 mktemp -d)
// lie above them on the host. The host sees only this empty folder.
constexpr const char* staging_dir = "/run/vl-grader-mounts";

/// `fd` moved to a number of 64 or more (close-on-exec), so that the child's dup2 onto
/// 0..63 never overwrites a descriptor it has still to duplicate.
int high_fd(int fd);

/// The system folders every sandbox gets, read-only: the toolchain and what it needs.
void system_mounts(std::vector<std::string>& a);

/// \brief What a child runs, made before fork (after it, only async-signal-safe calls).
struct child_command {
    std::vector<std::string> args;         ///< what it execs: the program first
    std::string cwd;                       ///< where it starts (bubblewrap: its own --chdir)
    std::vector<std::string> environment;  ///< the whole environment (bubblewrap: none, it sets it)
    std::vector<int> mount_fds;            ///< bubblewrap: each mount, opened O_PATH
    std::vector<bool> mount_is_dir;
    std::vector<std::string> staged;       ///< as root: where each mount is attached first
    std::filesystem::path scratch;         ///< weaker: the host folder in place of /scratch
};

/// bubblewrap's command line for `rq` into `c`, every mount opened; "" when it is made,
/// else why not (with nothing left open): the grader's failure, never the program's.
std::string bubblewrap_command(const run_request& rq, const sandbox_capabilities& caps, child_command& c);

/// The weaker sandbox's command line for `rq` into `c`: a scratch folder of its own on the
/// host, and host paths wherever `rq` names a path inside a mount.
void weaker_command(const run_request& rq, child_command& c);

/// Sets `l` on the calling process (the child, between fork and exec: async-signal-safe):
/// CPU time, address space (when caps.address_limit), file size, open files, no core.
void set_limits(const run_limits& l, const sandbox_capabilities& caps);

}  // namespace vl::grader::sandbox_parts
