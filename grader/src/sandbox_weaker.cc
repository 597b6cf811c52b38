// The weaker sandbox's command line, where bubblewrap cannot run (--weaker-sandbox): no
// mounts, so the program is given host paths in place of the paths inside its mounts, and
// a scratch folder of its own under the host's temporary folder in place of /scratch.
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cctype>

#include "sandbox_parts.hh"

namespace vl::grader::sandbox_parts {

namespace fs = std::filesystem;

namespace {

/// `text` (an argument) with every mount's inside path replaced by its host path, longest
/// first: the weaker sandbox has no mounts, so its programs are given host paths.
std::string to_host(std::string text, const std::vector<mount>& mounts, const fs::path& scratch) {
    std::vector<std::pair<std::string, std::string>> map;
    for (const mount& m : mounts) map.push_back({m.inside, m.host.string()});
    map.push_back({"/scratch", scratch.string()});
    std::sort(map.begin(), map.end(), [](const auto& a, const auto& b) { return a.first.size() > b.first.size(); });
    for (const auto& [inside, host] : map) {
        for (std::size_t at = text.find(inside); at != std::string::npos; at = text.find(inside, at + host.size())) {
            const std::size_t end = at + inside.size();
            const bool starts = at == 0 || (at >= 2 && text[at - 2] == '-') ||  // -I/vl/contract
                                !(std::isalnum(static_cast<unsigned char>(text[at - 1])) || text[at - 1] == '/' ||
                                  text[at - 1] == '_' || text[at - 1] == '.');
            const bool ends = end == text.size() || !(std::isalnum(static_cast<unsigned char>(text[end])) ||
                                                      text[end] == '_' || text[end] == '-' || text[end] == '.');
            if (!starts || !ends) {
                at += 1;
                if (at >= text.size()) break;
                continue;
            }
            text.replace(at, inside.size(), host);
        }
    }
    return text;
}

std::atomic<unsigned> weak_scratch_counter{0};

}  // namespace

void weaker_command(const run_request& rq, child_command& c) {
    c.scratch = fs::temp_directory_path() /
                ("vl-grader-scratch-" + std::to_string(getpid()) + "-" + std::to_string(weak_scratch_counter++));
    std::error_code ec;
    fs::remove_all(c.scratch, ec);
    fs::create_directories(c.scratch, ec);
    for (const auto& [target, link] : rq.symlinks) {
        const std::string t = target.starts_with("/proc/self/fd/") ? "/dev/fd/" + target.substr(14) : target;
        fs::create_symlink(to_host(t, rq.mounts, c.scratch), to_host(link, rq.mounts, c.scratch), ec);
    }
    for (const std::string& a : rq.argv) c.args.push_back(to_host(a, rq.mounts, c.scratch));
    c.cwd = to_host(rq.cwd, rq.mounts, c.scratch);
    fs::create_directories(c.scratch / "tmp", ec);
    c.environment = rq.environment;
    for (std::string& e : c.environment) {
        if (e == "TMPDIR=/tmp") e = "TMPDIR=" + (c.scratch / "tmp").string();
        else if (e.starts_with("HOME=")) e = "HOME=" + to_host(e.substr(5), rq.mounts, c.scratch);
    }
}

}  // namespace vl::grader::sandbox_parts
