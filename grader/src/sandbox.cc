#include "sandbox.hh"

#include <fcntl.h>
#include <grp.h>
#include <poll.h>
#include <pwd.h>
#include <sched.h>
#include <signal.h>
#include <sys/mount.h>
#include <sys/prctl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <sstream>

#include "install.hh"
#include "sandbox_parts.hh"

namespace vl::grader {

namespace fs = std::filesystem;
using namespace sandbox_parts;

namespace {


/// Where a child that cannot start says why: the write end of a close-on-exec pipe, so
/// the grader hears from it only before the exec. What runs after the exec cannot reach
/// this pipe, so nothing a program prints or how it ends passes for a sandbox that failed.
int child_error_fd = -1;

/// Says why the child cannot start, with write(2): the only output allowed between fork
/// and exec.
void child_says(const char* a, const char* b = "") {
    (void)!write(child_error_fd, a, std::strlen(a));
    (void)!write(child_error_fd, b, std::strlen(b));
}

const char* signal_name(int sig) {
    switch (sig) {
        case SIGSEGV: return "SIGSEGV (segmentation fault: a bad pointer or a stack overflow)";
        case SIGABRT: return "SIGABRT (abort: a failed assert, an uncaught exception or memory exhausted)";
        case SIGFPE: return "SIGFPE (arithmetic error, such as an integer division by zero)";
        case SIGKILL: return "SIGKILL (killed: usually the memory limit)";
        case SIGXCPU: return "SIGXCPU (the CPU time limit)";
        case SIGXFSZ: return "SIGXFSZ (the file size limit)";
        case SIGBUS: return "SIGBUS (bus error)";
        case SIGILL: return "SIGILL (illegal instruction)";
        case SIGSYS: return "SIGSYS (a forbidden system call)";
        default: return strsignal(sig);
    }
}

bool probe_run(const std::vector<std::string>& argv, bool as_nobody, const sandbox_capabilities& caps) {
    const pid_t pid = fork();
    if (pid == 0) {
        const int null = open("/dev/null", O_RDWR);
        dup2(null, 0);
        dup2(null, 1);
        dup2(null, 2);
        if (as_nobody && (setgroups(0, nullptr) != 0 || setgid(caps.gid) != 0 || setuid(caps.uid) != 0)) _exit(126);
        std::vector<char*> args;
        for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
        args.push_back(nullptr);
        char* env[] = {nullptr};
        execve(args[0], args.data(), env);
        _exit(127);
    }
    int status = 0;
    return pid > 0 && waitpid(pid, &status, 0) == pid && WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

bool try_unshare_in_child(int flags) {
    const pid_t pid = fork();
    if (pid == 0) _exit(unshare(flags) == 0 ? 0 : 1);
    int status = 0;
    return pid > 0 && waitpid(pid, &status, 0) == pid && WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

}  // namespace

std::string sandbox_capabilities::summary() const {
    std::string s;
    if (mode == isolation::bubblewrap) {
        s = "bubblewrap: only the toolchain and the step's own files mounted, read-only; a private size-capped "
            "scratch; no network; own PID namespace; uid 65534 in its own user namespace without capabilities";
        s += drop_to_nobody ? " (started as nobody)" : "";
    } else {
        s = "WEAKER SANDBOX (no bubblewrap here): the grader's own files are NOT hidden from student code";
        s += network_isolated ? "; no network" : "; network NOT isolated";
    }
    s += "; timeouts; limits on CPU time, ";
    s += address_limit ? "memory, " : "(not memory: sanitizer build), ";
    s += "file size, open files and processes; output captured and capped";
    return s;
}

sandbox_capabilities probe_sandbox(bool sanitized, bool allow_weaker) {
    sandbox_capabilities c;
    c.address_limit = !sanitized;
    if (const char* other = std::getenv("VL_GRADER_BWRAP"); other && *other) c.bwrap = other;  // tests: "no bubblewrap here"
    if (geteuid() == 0) {
        c.drop_to_nobody = true;
        if (mkdir(staging_dir, 0755) != 0 && errno != EEXIST)
            throw grader_error(std::string("cannot make ") + staging_dir + ": " + std::strerror(errno));
        if (const passwd* p = getpwnam("nobody")) {
            c.uid = p->pw_uid;
            c.gid = p->pw_gid;
        }
    }
    std::string why;
    if (access(c.bwrap.c_str(), X_OK) != 0) {
        why = c.bwrap.string() + " is missing (install the Debian package bubblewrap: tools/setup does)";
    } else {
        std::vector<std::string> argv = {c.bwrap.string(), "--unshare-all", "--unshare-user", "--disable-userns",
                                         "--die-with-parent", "--new-session"};
        system_mounts(argv);
        argv.insert(argv.end(), {"--proc", "/proc", "--dev", "/dev", "--tmpfs", "/scratch", "/bin/true"});
        if (!probe_run(argv, c.drop_to_nobody, c))
            why = "bubblewrap cannot make its namespaces here (a container without unprivileged user "
                  "namespaces? try: " + c.bwrap.string() + " --unshare-all --ro-bind /usr /usr /usr/bin/true)";
    }
    if (why.empty()) return c;
    if (!allow_weaker)
        throw grader_error(why + ". Without it student code could read the hidden tests and the reference. "
                                 "To grade anyway with a weaker sandbox, add --weaker-sandbox; every report "
                                 "will say so");
    c.mode = isolation::weaker;
    c.network_isolated = try_unshare_in_child(CLONE_NEWNET);
    return c;
}

std::vector<std::string> child_environment(const std::string& home, std::vector<std::string> extra) {
    std::vector<std::string> env = {"PATH=/usr/bin:/bin", "HOME=" + home, "LANG=C.UTF-8", "TMPDIR=/tmp"};
    for (auto& e : extra) env.push_back(std::move(e));
    return env;
}

void make_sandbox_dir(const fs::path& dir, const sandbox_capabilities& caps) {
    if (mkdir(dir.c_str(), 0755) != 0)
        throw grader_error("cannot make " + dir.string() + ": " + std::strerror(errno));
    if (!caps.drop_to_nobody || caps.mode != isolation::bubblewrap) return;
    const int fd = open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
    struct stat st {};
    const bool ok = fd >= 0 && fstat(fd, &st) == 0 && S_ISDIR(st.st_mode) && st.st_nlink == 2 &&
                    fchown(fd, caps.uid, caps.gid) == 0;
    const int err = errno;
    if (fd >= 0) close(fd);
    if (!ok) throw grader_error("cannot hand " + dir.string() + " to the sandbox: " + std::strerror(err));
}

std::string run_result::describe(double timeout) const {
    std::ostringstream s;
    if (!started) s << "could not start: " << error;
    else if (timed_out) s << "timed out after " << timeout << " s (an endless loop, or far too slow)";
    else if (signal != 0) s << "killed by " << signal_name(signal);
    else s << "exit code " << exit_code;
    return s.str();
}

std::string run_result::output_head(std::size_t max_bytes) const {
    std::string s = output.substr(0, max_bytes);
    if (output_bytes > s.size())
        s += "\n[... " + std::to_string(output_bytes - s.size()) + " more bytes of output not shown]";
    return s;
}

std::string run_result::output_tail(std::size_t max_bytes) const {
    const std::size_t from = output.size() > max_bytes ? output.size() - max_bytes : 0;
    std::string s = output.substr(from);
    if (from > 0) s = "[... " + std::to_string(from) + " bytes of output before this not shown]\n" + s;
    if (output_bytes > output.size())
        s += "\n[... " + std::to_string(output_bytes - output.size()) + " more bytes of output not kept]";
    return s;
}

run_result run(const run_request& rq, const sandbox_capabilities& caps) {
    run_result result;
    const bool bwrap = rq.sandboxed && caps.mode == isolation::bubblewrap;
    const bool weak = rq.sandboxed && !bwrap;
    const run_limits& l = rq.limits;

    // Everything the child needs is made before fork: after it, only async-signal-safe calls.
    child_command cmd;
    cmd.cwd = rq.cwd;
    auto close_all = [&] {
        for (int fd : cmd.mount_fds) close(fd);
    };
    if (bwrap) {
        result.error = bubblewrap_command(rq, caps, cmd);
        if (!result.error.empty()) return result;
    } else if (weak) {
        weaker_command(rq, cmd);
    } else {
        cmd.args = rq.argv;
        cmd.environment = rq.environment;
    }
    std::vector<char*> argv, env;
    for (auto& a : cmd.args) argv.push_back(a.data());
    argv.push_back(nullptr);
    for (auto& e : cmd.environment) env.push_back(e.data());
    env.push_back(nullptr);

    int out_pipe[2] = {-1, -1}, report_pipe[2] = {-1, -1}, status_pipe[2] = {-1, -1}, exec_pipe[2] = {-1, -1};
    auto close_pipes = [&] {
        for (int fd : {out_pipe[0], out_pipe[1], report_pipe[0], report_pipe[1], status_pipe[0], status_pipe[1],
                       exec_pipe[0], exec_pipe[1]})
            if (fd >= 0) close(fd);
    };
    const int channel = rq.channel >= 0 ? fcntl(rq.channel, F_DUPFD_CLOEXEC, 64) : -1;
    if (rq.channel >= 0) close(rq.channel);
    auto close_channel = [&] {
        if (channel >= 0) close(channel);
    };
    if (pipe2(out_pipe, O_CLOEXEC) != 0 || pipe2(exec_pipe, O_CLOEXEC) != 0 ||
        (rq.report_fd && pipe2(report_pipe, O_CLOEXEC) != 0) || (bwrap && pipe2(status_pipe, O_CLOEXEC) != 0)) {
        result.error = std::string("pipe: ") + std::strerror(errno);
        close_pipes();
        close_all();
        close_channel();
        return result;
    }
    for (int* fd : {&out_pipe[0], &out_pipe[1], &report_pipe[0], &report_pipe[1], &status_pipe[0], &status_pipe[1],
                    &exec_pipe[0], &exec_pipe[1]})
        *fd = high_fd(*fd);
    const bool drop = bwrap && caps.drop_to_nobody;
    // A program reopens its fd 3 as /dev/fd/3 (Catch2's -o, rt's out.png): as nobody, it may
    // only if nobody owns the pipe.
    if (drop && report_pipe[1] >= 0) (void)fchown(report_pipe[1], caps.uid, caps.gid);
    const auto start = std::chrono::steady_clock::now();
    const pid_t child = fork();
    if (child < 0) {
        result.error = std::string("fork: ") + std::strerror(errno);
        close_pipes();
        close_all();
        close_channel();
        return result;
    }
    if (child == 0) {
        child_error_fd = exec_pipe[1];
        // Its own process group, so a timeout kills everything it started.
        setpgid(0, 0);
        prctl(PR_SET_PDEATHSIG, SIGKILL);
        const int null = open("/dev/null", O_RDONLY);
        dup2(null, 0);
        dup2(out_pipe[1], 1);
        dup2(out_pipe[1], 2);
        if (report_pipe[1] >= 0) dup2(report_pipe[1], report_fd_number);
        if (status_pipe[1] >= 0) dup2(status_pipe[1], status_fd_number);
        if (channel >= 0) dup2(channel, channel_fd_number);
        // The numbers below the mounts that this run does not use are closed: nothing the
        // grader happens to hold there reaches the program.
        if (report_pipe[1] < 0) close(report_fd_number);
        if (status_pipe[1] < 0) close(status_fd_number);
        if (channel < 0) close(channel_fd_number);
        // bubblewrap closes the descriptors it binds; as root they are attached by open_tree
        // below and never reach it (close-on-exec), so no host folder stays open inside.
        if (!drop)
            for (std::size_t k = 0; k < cmd.mount_fds.size(); ++k) dup2(cmd.mount_fds[k], first_mount_fd + static_cast<int>(k));
        if (rq.sandboxed) set_limits(l, caps);
        if (drop && !cmd.staged.empty()) {
            // Detached copies of the mounts first (a bind from another namespace is not
            // allowed), then a private namespace in which they are attached under staging_dir.
            int trees[64];
            for (std::size_t k = 0; k < cmd.staged.size() && k < 64; ++k) {
                trees[k] = open_tree(cmd.mount_fds[k], "", OPEN_TREE_CLONE | OPEN_TREE_CLOEXEC | AT_EMPTY_PATH);
                if (trees[k] < 0) {
                    child_says("sandbox: cannot stage a mount: ", std::strerror(errno));
                    _exit(125);
                }
            }
            if (cmd.staged.size() > 64 || unshare(CLONE_NEWNS) != 0 ||
                ::mount(nullptr, "/", nullptr, MS_REC | MS_PRIVATE, nullptr) != 0 ||
                ::mount("tmpfs", staging_dir, "tmpfs", MS_NOSUID | MS_NODEV, "mode=0755,size=64k") != 0) {
                child_says("sandbox: cannot stage the mounts: ", std::strerror(errno));
                _exit(125);
            }
            for (std::size_t k = 0; k < cmd.staged.size(); ++k) {
                const bool made = cmd.mount_is_dir[k] ? mkdir(cmd.staged[k].c_str(), 0755) == 0
                                                  : close(open(cmd.staged[k].c_str(), O_WRONLY | O_CREAT | O_EXCL, 0644)) == 0;
                if (!made || move_mount(trees[k], "", AT_FDCWD, cmd.staged[k].c_str(), MOVE_MOUNT_F_EMPTY_PATH) != 0) {
                    child_says("sandbox: cannot stage a mount: ", std::strerror(errno));
                    _exit(125);
                }
            }
        }
        if (drop && (setgroups(0, nullptr) != 0 || setgid(caps.gid) != 0 || setuid(caps.uid) != 0)) {
            child_says("sandbox: cannot become nobody: ", std::strerror(errno));
            _exit(125);
        }
        if (weak) {
            int flags = (caps.network_isolated ? CLONE_NEWNET : 0);
            if (flags != 0 && unshare(flags) != 0) {
                child_says("sandbox: cannot leave the network: ", std::strerror(errno));
                _exit(125);
            }
        }
        if (chdir(cmd.cwd.c_str()) != 0 && !bwrap) {
            child_says("sandbox: cannot enter the working folder: ", std::strerror(errno));
            _exit(125);
        }
        // Nothing else the grader inherited or opened reaches the program.
        const int keep = bwrap     ? first_mount_fd + (drop ? 0 : static_cast<int>(cmd.mount_fds.size()))
                         : channel >= 0 ? channel_fd_number + 1
                                        : report_fd_number + 1;
        // The error pipe stays open until the exec closes it.
        const auto error_fd = static_cast<unsigned>(exec_pipe[1]), first_closed = static_cast<unsigned>(keep);
        if (error_fd >= first_closed) {
            if (error_fd > first_closed) close_range(first_closed, error_fd - 1, 0);
            close_range(error_fd + 1, ~0U, 0);
        } else {
            close_range(first_closed, ~0U, 0);
        }
        execve(argv[0], argv.data(), env.data());
        child_says("sandbox: cannot run the program: ", std::strerror(errno));
        _exit(125);
    }
    close(out_pipe[1]);
    out_pipe[1] = -1;
    close(exec_pipe[1]);
    exec_pipe[1] = -1;
    // The child either execs (the pipe closes empty) or says why it cannot and ends.
    std::string cannot_start;
    for (char c[512]; cannot_start.size() < 4096;) {
        const ssize_t n = read(exec_pipe[0], c, sizeof c);
        if (n > 0) cannot_start.append(c, static_cast<std::size_t>(n));
        else if (n == 0 || errno != EINTR) break;
    }
    if (!cannot_start.empty()) {
        kill(child, SIGKILL);
        int ignored = 0;
        waitpid(child, &ignored, 0);
        close_pipes();
        close_all();
        close_channel();
        result.error = cannot_start.starts_with("sandbox: ") ? cannot_start.substr(9) : cannot_start;
        return result;
    }
    if (report_pipe[1] >= 0) close(report_pipe[1]), report_pipe[1] = -1;
    if (status_pipe[1] >= 0) close(status_pipe[1]), status_pipe[1] = -1;
    close_all();
    close_channel();
    setpgid(child, child);

    // Read the pipes until every one is closed or the time is up.
    const auto deadline = start + std::chrono::duration<double>(l.wall_seconds);
    std::string status_json;
    char buf[65536];
    struct source {
        int fd;
        std::string* into;
        std::size_t cap;
    };
    std::vector<source> open_sources = {{out_pipe[0], &result.output, l.output_bytes}};
    if (report_pipe[0] >= 0) open_sources.push_back({report_pipe[0], &result.report, l.report_bytes});
    if (status_pipe[0] >= 0) open_sources.push_back({status_pipe[0], &status_json, 1 << 16});
    while (!open_sources.empty()) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
        if (left.count() <= 0) {
            result.timed_out = true;
            break;
        }
        std::vector<pollfd> p;
        for (const source& s : open_sources) p.push_back({s.fd, POLLIN, 0});
        const int n = poll(p.data(), p.size(), static_cast<int>(std::min<long long>(left.count(), 1000)));
        if (n < 0 && errno != EINTR) break;
        for (std::size_t k = p.size(); k-- > 0;) {
            if (p[k].revents == 0) continue;
            source& s = open_sources[k];
            const ssize_t got = read(s.fd, buf, sizeof buf);
            if (got <= 0) {
                open_sources.erase(open_sources.begin() + static_cast<long>(k));
                continue;
            }
            if (s.into == &result.output) result.output_bytes += static_cast<std::uint64_t>(got);
            const std::size_t room = s.cap > s.into->size() ? s.cap - s.into->size() : 0;
            s.into->append(buf, std::min(room, static_cast<std::size_t>(got)));
            if (s.into == &result.report && static_cast<std::size_t>(got) > room) result.report_overflow = true;
        }
        if (result.report_overflow) break;
    }
    int status = 0;
    if (result.timed_out || result.report_overflow) {
        kill(-child, SIGKILL);
        kill(child, SIGKILL);
    } else {
        // Every pipe is closed: the program has ended; give it the rest of its time to be reaped.
        while (waitpid(child, &status, WNOHANG) == 0) {
            if (std::chrono::steady_clock::now() > deadline) {
                result.timed_out = true;
                kill(-child, SIGKILL);
                kill(child, SIGKILL);
                break;
            }
            usleep(2000);
        }
    }
    if (result.timed_out || result.report_overflow) waitpid(child, &status, 0);
    kill(-child, SIGKILL);  // anything left in the group
    close_pipes();
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (weak) {
        std::error_code ec;
        fs::remove_all(cmd.scratch, ec);
    }
    result.started = true;
    if (result.timed_out || result.report_overflow) return result;

    if (bwrap) {
        // bubblewrap reports the program's exit as {"exit-code": N}; without that record the
        // sandbox itself failed (a mount, the exec), which is the grader's problem.
        const auto at = status_json.find("\"exit-code\"");
        if (at == std::string::npos) {
            result.started = false;
            result.error = "the sandbox failed: " + result.output.substr(0, 600);
            return result;
        }
        const int code = std::atoi(status_json.c_str() + status_json.find(':', at) + 1);
        if (code > 128 && code < 128 + 65) result.signal = code - 128;
        else result.exit_code = code;
        return result;
    }
    if (WIFEXITED(status)) {
        result.exit_code = WEXITSTATUS(status);
    } else if (WIFSIGNALED(status)) {
        result.signal = WTERMSIG(status);
    }
    return result;
}

}  // namespace vl::grader
