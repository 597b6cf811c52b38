#include "build_submission.hh"

#include <sstream>
#include <vector>

namespace vl::grader {

namespace fs = std::filesystem;

namespace {

void replace_all(std::string& s, const std::string& from, const std::string& to) {
    if (from.empty()) return;
    for (std::size_t at = s.find(from); at != std::string::npos; at = s.find(from, at + to.size()))
        s.replace(at, from.size(), to);
}

}  // namespace

std::string trim_compiler_errors(const std::string& log, const fs::path& sources, int max_lines) {
    std::vector<std::string> lines;
    std::istringstream in(log);
    for (std::string line; std::getline(in, line);) {
        // Ninja's progress and the failed command lines say nothing a student can use.
        if (line.starts_with("[") || line.starts_with("FAILED: ") || line.starts_with("ninja: ") ||
            line.find("/usr/bin/c++") != std::string::npos || line.find("ccache ") != std::string::npos)
            continue;
        replace_all(line, sources.string() + "/", "");
        // The build runs beside the sources, so the compiler also names them relatively.
        replace_all(line, "../" + sources.parent_path().filename().string() + "/" + sources.filename().string() + "/", "");
        lines.push_back(line);
    }
    std::size_t first = 0;
    while (first < lines.size() && lines[first].find("error") == std::string::npos) ++first;
    if (first == lines.size()) first = 0;
    // Keep the "In function ..." line that names where the error is.
    if (first > 0 && lines[first - 1].find("In ") != std::string::npos) --first;
    std::string out;
    const std::size_t last = std::min(lines.size(), first + static_cast<std::size_t>(max_lines));
    for (std::size_t k = first; k < last; ++k) out += lines[k] + "\n";
    if (last < lines.size()) out += "[... " + std::to_string(lines.size() - last) + " more lines]\n";
    return out;
}

build_outcome build_submission(const prepared_submission& sub, const stage_info& stage, const installation& in,
                               const fs::path& build_dir, const sandbox_capabilities& caps) {
    build_outcome b;
    fs::create_directories(build_dir);
    const fs::path ccache_dir = in.grader_build_dir / "ccache";
    fs::create_directories(ccache_dir);
    give_to_sandbox(build_dir, caps);
    give_to_sandbox(sub.sources.parent_path(), caps);
    give_to_sandbox(ccache_dir, caps);

    run_request rq;
    rq.cwd = build_dir;
    // Paths relative to the work folder, and no build folder in the hash: the same file in
    // two submissions (an untouched stub, a helper copied from the handout) compiles once.
    rq.environment = child_environment(build_dir, {"CCACHE_DIR=" + ccache_dir.string(), "CCACHE_UMASK=002",
                                                   "CCACHE_BASEDIR=" + build_dir.parent_path().string(),
                                                   "CCACHE_NOHASHDIR=1"});
    rq.limits.memory_bytes = std::uint64_t{4} << 30;
    rq.limits.file_bytes = std::uint64_t{1} << 30;
    rq.limits.processes = 512;

    rq.argv = {in.cmake.string(), "-S", (in.source_dir / "grader" / "submission").string(), "-B", build_dir.string(),
               "-G", in.generator, "-DCMAKE_MAKE_PROGRAM=" + in.make_program.string(),
               "-DCMAKE_CXX_COMPILER=" + in.cxx_compiler, "-DCMAKE_CXX_COMPILER_LAUNCHER=" + in.compiler_launcher,
               "-DVL_PREBUILT=" + in.prebuilt.string(), "-DVL_STAGE=" + stage.number,
               "-DVL_SUBMISSION_DIR=" + sub.sources.string(), "-DVL_CONTRACT_DIR=" + sub.contract.string()};
    rq.output = build_dir / "configure.log";
    rq.limits.wall_seconds = 120;
    const run_result configured = run(rq, caps);
    b.seconds = configured.seconds;
    if (!configured.succeeded()) {
        b.errors = "configuring the build failed (" + configured.describe(120) + "):\n" +
                   trim_compiler_errors(read_head(rq.output, 64 << 10), sub.sources);
        return b;
    }
    rq.argv = {in.cmake.string(), "--build", build_dir.string(), "--", "-k", "0"};
    rq.output = build_dir / "build.log";
    rq.limits.wall_seconds = 300;
    const run_result built = run(rq, caps);
    b.seconds += built.seconds;
    if (!built.succeeded()) {
        b.errors = (built.timed_out ? "the build " + built.describe(300) + "\n" : std::string()) +
                   trim_compiler_errors(read_head(rq.output, 256 << 10), sub.sources);
        return b;
    }
    b.ok = true;
    if (fs::exists(build_dir / "hidden_tests")) b.tests_program = build_dir / "hidden_tests";
    b.render_program = build_dir / "render";
    return b;
}

}  // namespace vl::grader
