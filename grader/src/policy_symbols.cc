// The symbol half of the policy (policy.hh): reading `nm` and checking an object file's
// symbols, the C functions and C++ names a piece never uses and the definitions it may not
// replace. The source half, and what a finding says, are in policy.cc.
#include <algorithm>
#include <cctype>
#include <map>
#include <sstream>
#include <string_view>

#include "policy.hh"
#include "policy_reasons.hh"

namespace vl::grader {

using namespace policy_reasons;

namespace {

/// C functions a piece never calls, by what calling them means.
const std::map<std::string, const char*, std::less<>>& denied_functions() {
    static const std::map<std::string, const char*, std::less<>> m = [] {
        std::map<std::string, const char*, std::less<>> d;
        auto add = [&](const char* reason, std::initializer_list<const char*> names) {
            for (const char* n : names) d[n] = reason;
        };
        add(files, {"open", "open64", "openat", "openat64", "openat2", "creat", "creat64", "fopen", "fopen64",
                    "freopen", "freopen64", "fdopen", "tmpfile", "tmpfile64", "mkstemp", "mkstemp64", "mkstemps",
                    "mkostemp", "mkostemps", "mkdtemp", "tmpnam", "tempnam", "opendir", "fdopendir", "scandir",
                    "name_to_handle_at", "open_by_handle_at", "write", "pwrite", "pwrite64", "writev", "pwritev",
                    "pwritev2", "read", "pread", "pread64", "readv", "preadv", "preadv2", "sendfile", "sendfile64",
                    "splice", "tee", "vmsplice", "copy_file_range", "truncate", "truncate64", "ftruncate",
                    "ftruncate64", "fallocate", "posix_fallocate", "unlink", "unlinkat", "remove", "rename",
                    "renameat", "renameat2", "mkdir", "mkdirat", "rmdir", "mknod", "mknodat", "mkfifo",
                    "chmod", "fchmod", "fchmodat", "chown", "fchown", "lchown", "fchownat", "link", "linkat",
                    "symlink", "symlinkat", "chdir", "fchdir", "chroot", "mount", "umount", "umount2", "dup",
                    "dup2", "dup3", "fcntl", "fcntl64", "ioctl", "pipe", "pipe2", "close_range", "utime",
                    "utimes", "utimensat", "futimens", "setxattr", "fsetxattr", "lsetxattr", "memfd_create",
                    "inotify_init", "fanotify_init", "flock", "lockf", "dprintf", "vdprintf", "aio_write", "aio_read",
                    "lio_listio", "io_uring_setup", "fmemopen_fd"});
        add(ends, {"exit", "_exit", "_Exit", "quick_exit", "at_quick_exit", "on_exit", "pthread_exit"});
        add(spawns, {"fork", "vfork", "clone", "clone3", "__clone", "execve", "execv", "execvp", "execvpe", "execl",
                     "execlp", "execle", "fexecve", "execveat", "posix_spawn", "posix_spawnp", "system", "popen",
                     "pclose", "daemon", "setsid", "setpgid", "unshare", "setns"});
        add(signals, {"kill", "killpg", "raise", "tgkill", "tkill", "pthread_kill", "pthread_sigqueue", "sigqueue",
                      "signal", "sigaction", "sigset", "bsd_signal", "sysv_signal", "alarm", "setitimer",
                      "timer_create", "sigprocmask", "pthread_sigmask"});
        add(network, {"socket", "socketpair", "connect", "bind", "listen", "accept", "accept4", "send", "sendto",
                      "sendmsg", "sendmmsg", "recv", "recvfrom", "recvmsg", "recvmmsg", "getaddrinfo",
                      "gethostbyname", "shutdown", "setsockopt"});
        add(loads, {"dlopen", "dlmopen", "dlsym", "dlvsym", "dladdr", "dladdr1", "dlinfo", "dl_iterate_phdr",
                    "_r_debug", "_DYNAMIC", "getauxval", "__libc_stack_end", "_dl_argv"});
        add(maps, {"mmap", "mmap64", "mprotect", "pkey_mprotect", "mremap", "munmap", "madvise", "mlock", "shmget",
                   "shmat", "shm_open", "brk", "sbrk"});
        add(syscalls, {"syscall", "ptrace", "prctl", "arch_prctl", "seccomp", "personality", "setrlimit",
                       "prlimit", "prlimit64", "setuid", "seteuid", "setreuid", "setresuid", "setgid", "setegid",
                       "setregid", "setresgid", "capset", "process_vm_readv", "process_vm_writev",
                       "sched_setaffinity", "sched_setscheduler", "setpriority", "nice"});
        add(environment, {"setenv", "putenv", "unsetenv", "clearenv", "getenv", "secure_getenv", "environ",
                          "program_invocation_name", "program_invocation_short_name", "progname", "progname_full"});
        return d;
    }();
    return m;
}

/// C++ names a piece never uses: file streams and the file system, the test framework.
const std::vector<std::pair<std::string_view, const char*>>& denied_prefixes() {
    static const std::vector<std::pair<std::string_view, const char*>> p = {
        {"std::basic_ifstream", files},  {"std::basic_ofstream", files},   {"std::basic_fstream", files},
        {"std::basic_filebuf", files},   {"std::__basic_file", files},      {"std::filesystem::", files},
        {"std::experimental::filesystem", files}, {"std::__cxx11::basic_ifstream", files},
        {"Catch::", harness},            {"vl::clear_counts", counters},
        {"vl::reference_stage", reference},
    };
    return p;
}

/// The C name behind a fortified or internal alias: __open_2 -> open, __read_chk -> read,
/// __write -> write (glibc exports such aliases of most of its calls).
std::string plain_name(const std::string& name) {
    std::string n = name;
    if (const auto at = n.find('@'); at != std::string::npos) n.erase(at);
    if (!n.starts_with("__")) return n;
    n.erase(0, n.find_first_not_of('_'));
    if (n.ends_with("_chk")) n.resize(n.size() - 4);
    else if (n.ends_with("_2")) n.resize(n.size() - 2);
    return n;
}

bool is_hex(std::string_view s) {
    return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return std::isxdigit(static_cast<unsigned char>(c)); });
}

/// One `nm -A -P` line: "FILE: NAME TYPE [VALUE [SIZE]]"; NAME may hold spaces (-C).
bool parse_nm_line(const std::string& line, std::string& file, std::string& name, char& type) {
    const auto colon = line.find(": ");
    if (colon == std::string::npos) return false;
    file = line.substr(0, colon);
    std::string_view rest(line);
    rest.remove_prefix(colon + 2);
    while (!rest.empty() && (rest.back() == ' ' || rest.back() == '\t' || rest.back() == '\r')) rest.remove_suffix(1);
    std::size_t end = rest.size();
    // From the right: at most two hex numbers, then the one-letter type.
    for (int k = 0; k < 3; ++k) {
        const auto space = rest.rfind(' ', end - 1);
        if (space == std::string_view::npos) return false;
        const std::string_view word = rest.substr(space + 1, end - space - 1);
        if (word.size() == 1 && std::isalpha(static_cast<unsigned char>(word[0]))) {
            type = word[0];
            name = std::string(rest.substr(0, space));
            return true;
        }
        if (!is_hex(word)) return false;
        end = space;
    }
    return false;
}

}  // namespace

std::vector<std::pair<std::string, object_symbol>> parse_nm(const std::string& mangled, const std::string& demangled) {
    std::vector<std::pair<std::string, object_symbol>> out;
    std::istringstream a(mangled), b(demangled);
    std::string la, lb;
    while (std::getline(a, la)) {
        if (!std::getline(b, lb)) lb = la;
        std::string file, name, dfile, dname;
        char type = '?', dtype = '?';
        if (!parse_nm_line(la, file, name, type)) continue;
        if (!parse_nm_line(lb, dfile, dname, dtype) || dfile != file) dname = name;
        out.push_back({file, {name, dname, type}});
    }
    return out;
}

std::vector<policy_finding> check_symbols(const std::string& file, const std::vector<object_symbol>& symbols,
                                          const std::set<std::string>& protected_symbols,
                                          const std::set<std::string>& strong) {
    std::vector<policy_finding> found;
    std::set<std::string> seen;
    auto add = [&](const object_symbol& s, const char* reason) {
        if (seen.insert(s.demangled).second) found.push_back({file, 0, s.demangled, reason});
    };
    for (const object_symbol& s : symbols) {
        const bool undefined = s.type == 'U' || s.type == 'w' || s.type == 'v';
        const bool local = std::islower(static_cast<unsigned char>(s.type)) && !undefined && s.type != 'u' &&
                           s.type != 'i';
        if (undefined) {
            const std::string plain = plain_name(s.name);
            auto d = denied_functions().find(s.name.substr(0, s.name.find('@')));
            if (d == denied_functions().end()) d = denied_functions().find(plain);
            if (d != denied_functions().end()) {
                add(s, d->second);
                continue;
            }
            // libstdc++'s own inline code reads __libc_single_threaded (a flag, not a call):
            // copying a std::shared_ptr refers to it.
            const bool from_the_standard_library = s.name.substr(0, s.name.find('@')) == "__libc_single_threaded";
            if (!from_the_standard_library &&
                (s.name.starts_with("__libc_") || s.name.starts_with("_IO_") || s.name.starts_with("_dl_") ||
                 plain.ends_with("_nocancel") || s.name.starts_with("__GI_"))) {
                add(s, syscalls);
                continue;
            }
            for (const auto& [prefix, reason] : denied_prefixes())
                if (std::string_view(s.demangled).starts_with(prefix)) {
                    // Named by the class or namespace, not by each of its members.
                    std::string what(prefix);
                    if (what.ends_with("::")) what.resize(what.size() - 2);
                    add({s.name, what, s.type}, reason);
                    break;
                }
            continue;
        }
        if (local) continue;
        // A global definition: it must not take the place of one the rest of the program has.
        if (s.type == 'i') {
            add(s, replaces);
            continue;
        }
        if (s.name == "main" || s.name == "_start" || s.name == "_init" || s.name == "_fini") {
            add(s, replaces);
            continue;
        }
        if (!protected_symbols.contains(s.name)) continue;
        const bool weak_here = s.type == 'W' || s.type == 'V' || s.type == 'u';
        // Two weak copies of one inline function (from a shared header) are the normal case.
        if (weak_here && !strong.contains(s.name)) continue;
        add(s, replaces);
    }
    return found;
}

}  // namespace vl::grader
