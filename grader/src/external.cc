#include "external.hh"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <fstream>
#include <iterator>
#include <thread>

extern char** environ;

namespace vl::grader {

namespace fs = std::filesystem;

std::string run_tool(const std::vector<std::string>& args, const fs::path& log, int timeout_seconds, int ok_status) {
    if (args.empty()) return "no program to run";
    std::vector<std::string> copy = args;
    std::vector<char*> argv;
    for (std::string& a : copy) argv.push_back(a.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
    pid_t pid = 0;
    const int spawned = posix_spawnp(&pid, argv[0], &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (spawned != 0) return args[0] + " could not be started: " + std::strerror(spawned);
    int status = 0;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(timeout_seconds);
    for (;;) {
        const pid_t done = waitpid(pid, &status, WNOHANG);
        if (done == pid) break;
        if (done < 0 && errno != EINTR) return "waiting for " + args[0] + " failed: " + std::strerror(errno);
        if (std::chrono::steady_clock::now() > deadline) {
            kill(pid, SIGKILL);
            waitpid(pid, &status, 0);
            return args[0] + " took more than " + std::to_string(timeout_seconds) + " s and was stopped";
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    if (WIFEXITED(status) && WEXITSTATUS(status) <= ok_status) return "";
    std::ifstream in(log);
    std::string output(std::istreambuf_iterator<char>(in), {});
    if (output.size() > 400) output.resize(400);
    const std::string how = WIFEXITED(status) ? "exited with status " + std::to_string(WEXITSTATUS(status))
                                              : "was killed by signal " + std::to_string(WTERMSIG(status));
    return args[0] + " " + how + (output.empty() ? std::string() : ": " + output);
}

std::string highlight_difference(const fs::path& reference, const fs::path& test, const fs::path& out, double fuzz_percent) {
    const fs::path log = fs::path(out).replace_extension(".compare.log");
    // compare exits 0 (alike) or 1 (different) when it wrote the image, 2 on an error.
    // ImageMagick on two small PNGs takes well under a second; 30 s means it is stuck.
    std::string problem = run_tool({"compare", "-fuzz", std::to_string(fuzz_percent) + "%", "-highlight-color", "red",
                                    "-lowlight-color", "rgba(255,255,255,0.6)", "png:" + reference.string(),
                                    "png:" + test.string(), "png:" + out.string()},
                                   log, 30, 1);
    std::error_code ec;
    if (problem.empty() && !fs::is_regular_file(out, ec)) problem = "compare wrote no image";
    fs::remove(log, ec);
    return problem;
}

}  // namespace vl::grader
