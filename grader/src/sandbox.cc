#include "sandbox.hh"

#include <fcntl.h>
#include <grp.h>
#include <poll.h>
#include <pwd.h>
#include <sched.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <fstream>
#include <sstream>
#include <thread>

namespace vl::grader {

namespace fs = std::filesystem;

namespace {

void set_limit(int resource, rlim_t value) {
    const rlimit r{value, value};
    setrlimit(resource, &r);
}

/// In the child, after fork: limits, user, then exec. Never returns.
[[noreturn]] void exec_child(const run_request& rq, const sandbox_capabilities& caps, const std::vector<char*>& argv,
                             const std::vector<char*>& env) {
    if (rq.sandboxed) {
        const run_limits& l = rq.limits;
        const double cpu = l.cpu_seconds > 0 ? l.cpu_seconds : l.wall_seconds + 1;
        set_limit(RLIMIT_CPU, static_cast<rlim_t>(cpu + 0.999));
        if (caps.address_limit && l.memory_bytes > 0) set_limit(RLIMIT_AS, l.memory_bytes);
        set_limit(RLIMIT_FSIZE, l.file_bytes);
        set_limit(RLIMIT_NOFILE, 256);
        set_limit(RLIMIT_CORE, 0);
        if (caps.unprivileged) {
            set_limit(RLIMIT_NPROC, static_cast<rlim_t>(l.processes));
            if (setgroups(0, nullptr) != 0 || setgid(caps.gid) != 0 || setuid(caps.uid) != 0) {
                std::fprintf(stderr, "sandbox: cannot drop privileges: %s\n", std::strerror(errno));
                _exit(126);
            }
        }
    }
    if (chdir(rq.cwd.c_str()) != 0) {
        std::fprintf(stderr, "sandbox: cannot enter %s: %s\n", rq.cwd.c_str(), std::strerror(errno));
        _exit(126);
    }
    execve(argv[0], argv.data(), env.data());
    std::fprintf(stderr, "sandbox: cannot run %s: %s\n", argv[0], std::strerror(errno));
    _exit(127);
}

bool try_unshare_in_child(int flags) {
    const pid_t pid = fork();
    if (pid == 0) _exit(unshare(flags) == 0 ? 0 : 1);
    int status = 0;
    return pid > 0 && waitpid(pid, &status, 0) == pid && WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

const char* signal_name(int sig) {
    switch (sig) {
        case SIGSEGV: return "SIGSEGV (segmentation fault: a bad pointer or a stack overflow)";
        case SIGABRT: return "SIGABRT (abort: a failed assert or an uncaught exception)";
        case SIGFPE: return "SIGFPE (arithmetic error, such as an integer division by zero)";
        case SIGKILL: return "SIGKILL (killed: usually the memory limit)";
        case SIGXCPU: return "SIGXCPU (the CPU time limit)";
        case SIGXFSZ: return "SIGXFSZ (the file size limit)";
        case SIGBUS: return "SIGBUS (bus error)";
        case SIGILL: return "SIGILL (illegal instruction)";
        default: return strsignal(sig);
    }
}

}  // namespace

std::string sandbox_capabilities::summary() const {
    std::string s = "timeouts; limits on CPU time, ";
    s += address_limit ? "memory, " : "(not memory: sanitizer build), ";
    s += "file size and open files";
    s += unprivileged ? "; runs as an unprivileged user with a process limit" : "; same user as the grader (no process limit)";
    s += network_isolated ? "; no network" : "; network NOT isolated (no namespaces here)";
    s += pid_isolated ? "; own PID namespace" : "";
    return s;
}

sandbox_capabilities probe_sandbox(bool sanitized) {
    sandbox_capabilities c;
    c.address_limit = !sanitized;
    c.network_isolated = try_unshare_in_child(CLONE_NEWNET);
    c.pid_isolated = try_unshare_in_child(CLONE_NEWPID);
    if (geteuid() == 0) {
        if (const passwd* p = getpwnam("nobody")) {
            c.unprivileged = true;
            c.uid = p->pw_uid;
            c.gid = p->pw_gid;
        }
    }
    return c;
}

std::vector<std::string> child_environment(const fs::path& home, std::vector<std::string> extra) {
    std::vector<std::string> env = {"PATH=/usr/local/bin:/usr/bin:/bin", "HOME=" + home.string(), "LANG=C.UTF-8"};
    for (auto& e : extra) env.push_back(std::move(e));
    return env;
}

void give_to_sandbox(const fs::path& dir, const sandbox_capabilities& caps) {
    if (!caps.unprivileged) return;
    std::error_code ec;
    if (lchown(dir.c_str(), caps.uid, caps.gid) != 0) return;
    for (auto it = fs::recursive_directory_iterator(dir, ec); !ec && it != fs::recursive_directory_iterator();
         it.increment(ec))
        (void)lchown(it->path().c_str(), caps.uid, caps.gid);
}

std::string read_head(const fs::path& file, std::size_t max_bytes) {
    std::ifstream in(file, std::ios::binary);
    std::string s(max_bytes + 1, '\0');
    in.read(s.data(), static_cast<std::streamsize>(s.size()));
    s.resize(static_cast<std::size_t>(in.gcount()));
    if (s.size() > max_bytes) {
        s.resize(max_bytes);
        s += "\n[... cut: more output than " + std::to_string(max_bytes) + " bytes]";
    }
    return s;
}

std::string run_result::describe(double timeout) const {
    std::ostringstream s;
    if (!started) s << "could not start: " << error;
    else if (timed_out) s << "timed out after " << timeout << " s (an endless loop, or far too slow)";
    else if (signal != 0) s << "killed by " << signal_name(signal);
    else s << "exit code " << exit_code;
    return s.str();
}

run_result run(const run_request& rq, const sandbox_capabilities& caps) {
    run_result result;
    std::vector<std::string> args = rq.argv, env_strings = rq.environment;
    std::vector<char*> argv, env;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    for (auto& e : env_strings) env.push_back(e.data());
    env.push_back(nullptr);

    const int out = open(rq.output.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (out < 0) {
        result.error = "cannot create " + rq.output.string() + ": " + std::strerror(errno);
        return result;
    }
    if (rq.sandboxed && caps.unprivileged) (void)fchown(out, caps.uid, caps.gid);
    // The status pipe: the PID namespace's first process reports how the program ended.
    int status_pipe[2];
    if (pipe2(status_pipe, O_CLOEXEC) != 0) {
        close(out);
        result.error = std::string("pipe: ") + std::strerror(errno);
        return result;
    }
    const bool namespaces = rq.sandboxed && (caps.network_isolated || caps.pid_isolated);
    const auto start = std::chrono::steady_clock::now();
    const pid_t leader = fork();
    if (leader < 0) {
        close(out);
        result.error = std::string("fork: ") + std::strerror(errno);
        return result;
    }
    if (leader == 0) {
        // Its own process group, so a timeout kills everything it started.
        setpgid(0, 0);
        prctl(PR_SET_PDEATHSIG, SIGKILL);
        const int in = open("/dev/null", O_RDONLY);
        dup2(in, 0);
        dup2(out, 1);
        dup2(out, 2);
        close(status_pipe[0]);
        if (!namespaces) exec_child(rq, caps, argv, env);
        int flags = 0;
        if (caps.network_isolated) flags |= CLONE_NEWNET;
        if (caps.pid_isolated) flags |= CLONE_NEWPID;
        if (unshare(flags) != 0) _exit(125);
        // The next child is process 1 of the new namespace: when it ends, the kernel ends
        // every process the program left behind. It only waits for the program.
        const pid_t init = fork();
        if (init == 0) {
            const pid_t program = fork();
            if (program == 0) {
                close(status_pipe[1]);
                exec_child(rq, caps, argv, env);
            }
            int status = 0;
            while (waitpid(program, &status, 0) < 0 && errno == EINTR) {
            }
            (void)!write(status_pipe[1], &status, sizeof status);
            _exit(0);
        }
        int status = 0;
        while (waitpid(init, &status, 0) < 0 && errno == EINTR) {
        }
        _exit(0);
    }
    close(status_pipe[1]);
    close(out);
    setpgid(leader, leader);

    const auto deadline = start + std::chrono::duration<double>(rq.limits.wall_seconds);
    int status = 0;
    for (;;) {
        const pid_t done = waitpid(leader, &status, WNOHANG);
        if (done == leader) break;
        if (std::chrono::steady_clock::now() > deadline) {
            result.timed_out = true;
            kill(-leader, SIGKILL);
            waitpid(leader, &status, 0);
            break;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    result.started = true;
    if (namespaces) {
        int program_status = 0;
        if (read(status_pipe[0], &program_status, sizeof program_status) == static_cast<ssize_t>(sizeof program_status)) {
            status = program_status;
        } else if (!result.timed_out) {
            result.started = false;
            result.error = "the sandbox could not start the program";
        }
    }
    close(status_pipe[0]);
    kill(-leader, SIGKILL);  // anything left in the group
    if (result.timed_out) return result;
    if (WIFEXITED(status)) {
        result.exit_code = WEXITSTATUS(status);
    } else if (WIFSIGNALED(status)) {
        result.signal = WTERMSIG(status);
    }
    if (result.exit_code == 126 || result.exit_code == 127) {
        const std::string head = read_head(rq.output, 400);
        if (head.starts_with("sandbox: ")) {
            result.started = false;
            result.error = head.substr(9);
        }
    }
    return result;
}

}  // namespace vl::grader
