// What the grader's subcommands share (commands.hh), and the subcommands that grade one
// submission or write what an instructor hands out: grade, export-kit, gradescope, list.
#include "commands.hh"

#include <sched.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>

#include "export_kit.hh"
#include "gradescope.hh"
#include "report_html.hh"
#include "results_json.hh"
#include "terminal_summary.hh"

namespace vl::grader {

namespace fs = std::filesystem;

std::string take_option(arguments& args, const std::string& flag) {
    for (std::size_t k = 0; k < args.size(); ++k) {
        if (args[k] == flag) {
            if (k + 1 >= args.size()) throw command_line_error{flag + " needs a value"};
            std::string v = args[k + 1];
            args.erase(args.begin() + static_cast<long>(k), args.begin() + static_cast<long>(k) + 2);
            return v;
        }
        if (args[k].starts_with(flag + "=")) {
            std::string v = args[k].substr(flag.size() + 1);
            args.erase(args.begin() + static_cast<long>(k));
            return v;
        }
    }
    return {};
}

bool take_flag(arguments& args, const std::string& flag) {
    const auto at = std::find(args.begin(), args.end(), flag);
    if (at == args.end()) return false;
    args.erase(at);
    return true;
}

grade_options take_grade_options(arguments& args) {
    vl::grader::grade_options o;
    o.weaker_sandbox = take_flag(args, "--weaker-sandbox");
    o.keep_work = take_flag(args, "--keep-work");
    const std::string jobs = take_option(args, "--jobs");
    o.item_jobs = jobs.empty() ? default_item_jobs(1) : positive_number(jobs, "--jobs");
    return o;
}

int default_item_jobs(int grades_at_once) {
    // A test is two processes that take turns (the judge and the subject, each waiting
    // briefly awake for the other's answer): one item per two CPUs of the grade's share.
    return std::clamp(usable_cpus() / (2 * std::max(grades_at_once, 1)), 1, 4);
}

void expect_count(const arguments& args, std::size_t n) {
    for (const std::string& a : args)
        if (a.starts_with("--")) throw command_line_error{"unknown option '" + a + "'"};
    if (args.size() != n) throw command_line_error{"expected " + std::to_string(n) + " argument(s), got " + std::to_string(args.size())};
}

graded_submission grade_into(const installation& in, const std::string& assignment, const fs::path& submission,
                             const fs::path& out, grade_options options) {
    const vl::grader::stage_info& stage = in.find_stage(assignment);
    if (!fs::exists(submission)) throw grader_error(submission.string() + ": no such file or folder");
    std::error_code ec;
    fs::create_directories(out, ec);
    if (ec || access(out.c_str(), W_OK | X_OK) != 0)
        throw grader_error("cannot write results to " + out.string() + ": " +
                           (ec ? ec.message() : std::string(std::strerror(errno))) + " (choose another --out)");
    options.out = fs::absolute(out);
    const vl::grader::graded_submission g = vl::grader::grade(in, stage, submission, options);
    vl::grader::write_results_json(g, out / "results.json");
    vl::grader::write_report_html(g, out / "report.html");
    return g;
}

fs::path default_out(const installation& in, const std::string& assignment, const std::string& submission) {
    const std::string where = fs::absolute(submission).lexically_normal().string();
    std::uint32_t h = 2166136261u;
    for (const unsigned char c : where) h = (h ^ c) * 16777619u;
    char hex[9];
    std::snprintf(hex, sizeof hex, "%08x", h);
    std::string name = fs::path(submission).lexically_normal().filename().string();
    if (name.empty() || name == "." || name == "..") name = "submission";
    return in.build_dir / "grader-out" / (in.find_stage(assignment).name + "-" + name + "-" + hex);
}

int usable_cpus() {
    cpu_set_t set;
    CPU_ZERO(&set);
    if (sched_getaffinity(0, sizeof set, &set) == 0) return std::max(1, CPU_COUNT(&set));
    return 1;
}

fs::path own_program() {
    std::error_code ec;
    const fs::path self = fs::read_symlink("/proc/self/exe", ec);
    if (ec) throw grader_error("cannot find the grader's own program (/proc/self/exe): " + ec.message());
    return self;
}

int positive_number(const std::string& text, const std::string& what) {
    char* end = nullptr;
    const long n = std::strtol(text.c_str(), &end, 10);
    if (text.empty() || *end != '\0' || n < 1 || n > 1024) throw command_line_error{what + " needs a whole number from 1, not '" + text + "'"};
    return static_cast<int>(n);
}

int grade_command(const installation& in, arguments args) {
    std::string out = take_option(args, "--out");
    const auto options = take_grade_options(args);
    expect_count(args, 2);
    if (out.empty()) out = default_out(in, args[0], args[1]).string();
    const auto g = grade_into(in, args[0], args[1], out, options);
    vl::grader::print_summary(std::cout, g, out, vl::grader::stdout_wants_colour());
    return 0;
}

int export_kit_command(const installation& in, const arguments& args) {
    expect_count(args, 1);
    fs::path dir = fs::absolute(args[0]).lexically_normal();
    if (dir.filename().empty()) dir = dir.parent_path();
    vl::grader::export_kit(in, dir);
    std::cout << "student kit: " << dir.string() << "\n             " << dir.string()
              << ".tar.gz\nchecked: no line of reference/ and no hidden test name is in it\n"
                 "a student builds it with: tools/setup --preset student (its README.md says more)\n";
    return 0;
}

/// `gradescope ASSIGNMENT OUT.zip`: the Gradescope bundle (gradescope.hh).
int gradescope_command(const installation& in, const arguments& args) {
    expect_count(args, 2);
    std::cout << vl::grader::write_gradescope_bundle(in, in.find_stage(args[0]), args[1]).summary();
    return 0;
}

int list_command(const installation& in, const arguments& args) {
    expect_count(args, 0);
    for (const auto& [name, stage] : in.stages)
        std::cout << name << (stage.trusted_tests.empty() ? "  (no hidden tests yet)" : "") << "\n";
    return 0;
}

}  // namespace vl::grader
