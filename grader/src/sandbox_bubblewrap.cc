// bubblewrap's command line for one sandboxed run (sandbox.hh's file comment says what it
// isolates): namespaces, the system folders, a size-capped /scratch and /tmp, each mount
// handed over as an open descriptor (or, as root, staged under staging_dir), the
// environment, a read-only root, and prlimit's process limit around the program.
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "sandbox_parts.hh"

namespace vl::grader::sandbox_parts {

namespace fs = std::filesystem;

/// `fd` moved to a number of 64 or more (close-on-exec), so that the child's dup2 onto
/// 0..63 never overwrites a descriptor it has still to duplicate.
int high_fd(int fd) {
    if (fd < 0 || fd >= 64) return fd;
    const int moved = fcntl(fd, F_DUPFD_CLOEXEC, 64);
    close(fd);
    return moved;
}

/// The system folders every sandbox gets, read-only: the toolchain and what it needs.
void system_mounts(std::vector<std::string>& a) {
    a.insert(a.end(), {"--ro-bind", "/usr", "/usr", "--symlink", "usr/bin", "/bin", "--symlink", "usr/sbin", "/sbin",
                       "--symlink", "usr/lib", "/lib", "--symlink", "usr/lib64", "/lib64"});
    for (const char* etc : {"/etc/ld.so.cache", "/etc/alternatives"})
        if (fs::exists(etc)) a.insert(a.end(), {"--ro-bind", etc, etc});
}

std::string bubblewrap_command(const run_request& rq, const sandbox_capabilities& caps, child_command& c) {
    c.args = {caps.bwrap.string(), "--unshare-all", "--unshare-user", "--disable-userns", "--die-with-parent",
              "--new-session", "--uid", std::to_string(caps.uid), "--gid", std::to_string(caps.gid),
              "--json-status-fd", std::to_string(status_fd_number), "--clearenv"};
    system_mounts(c.args);
    const std::string scratch_bytes = std::to_string(rq.limits.scratch_bytes);
    c.args.insert(c.args.end(), {"--proc", "/proc", "--dev", "/dev", "--size", scratch_bytes, "--tmpfs", "/tmp", "--size",
                                 scratch_bytes, "--tmpfs", "/scratch"});
    for (const mount& m : rq.mounts) {
        const int fd = high_fd(open(m.host.c_str(), O_PATH | O_NOFOLLOW | O_CLOEXEC));
        struct stat st {};
        if (fd < 0 || fstat(fd, &st) != 0 || !(S_ISREG(st.st_mode) || S_ISDIR(st.st_mode))) {
            const int err = errno;
            if (fd >= 0) close(fd);
            for (const int opened : c.mount_fds) close(opened);
            return "cannot mount " + m.host.string() + ": " + (fd < 0 ? std::strerror(err) : "not a regular file or folder");
        }
        c.mount_fds.push_back(fd);
        c.mount_is_dir.push_back(S_ISDIR(st.st_mode));
        if (caps.drop_to_nobody) {
            c.staged.push_back(std::string(staging_dir) + "/" + std::to_string(c.staged.size()));
            c.args.insert(c.args.end(), {m.writable ? "--bind" : "--ro-bind", c.staged.back(), m.inside});
        } else {
            c.args.insert(c.args.end(), {m.writable ? "--bind-fd" : "--ro-bind-fd",
                                         std::to_string(first_mount_fd + static_cast<int>(c.mount_fds.size()) - 1),
                                         m.inside});
        }
    }
    for (const auto& [target, link] : rq.symlinks) c.args.insert(c.args.end(), {"--symlink", target, link});
    for (const std::string& e : rq.environment) {
        const auto eq = e.find('=');
        c.args.insert(c.args.end(), {"--setenv", e.substr(0, eq), e.substr(eq + 1)});
    }
    // The root and /dev are bubblewrap's own tmpfs, uncapped: read-only once every mount
    // point is made, so /scratch and /tmp are the only places to write.
    c.args.insert(c.args.end(), {"--remount-ro", "/dev", "--remount-ro", "/"});
    c.args.insert(c.args.end(), {"--chdir", rq.cwd, "--", "/usr/bin/prlimit",
                                 "--nproc=" + std::to_string(rq.limits.processes), "--"});
    c.args.insert(c.args.end(), rq.argv.begin(), rq.argv.end());
    return {};
}

}  // namespace vl::grader::sandbox_parts
