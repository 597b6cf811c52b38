// The grader's command line: `grader/run COMMAND ...` (see grader/README.md). Each
// command is one entry of the table below, so new ones (roster, gradescope) slot in
// beside the others, like imgdiff.
#include <sched.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <toml++/toml.h>

#include "command_line.hh"
#include "export_kit.hh"
#include "grade.hh"
#include "gradescope.hh"
#include "image_compare.hh"
#include "install.hh"
#include "report_html.hh"
#include "results_json.hh"
#include "roster.hh"
#include "roster_results.hh"
#include "sandbox.hh"
#include "terminal_summary.hh"
#include "thresholds.hh"
#include "vl/flip.hh"
#include "vl/image_io.hh"
#include "vl/ssim.hh"

namespace {

namespace fs = std::filesystem;
using vl::grader::grader_error;
using vl::grader::installation;

/// A mistake on the command line (the framework's programs' kind): printed with the
/// command's usage.
using vl::apps::command_line_error;

using arguments = std::vector<std::string>;

/// \brief One subcommand: `run` needs the built grader's installation (grader.toml);
/// `run_alone`, when set instead, needs nothing but its arguments.
struct command {
    std::string name, synopsis, summary;
    std::function<int(const installation&, const arguments&)> run;
    std::function<int(const arguments&)> run_alone = nullptr;
};

/// Takes `--flag VALUE` out of `args`; empty when absent.
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

/// Takes `--flag` out of `args`; whether it was there.
bool take_flag(arguments& args, const std::string& flag) {
    const auto at = std::find(args.begin(), args.end(), flag);
    if (at == args.end()) return false;
    args.erase(at);
    return true;
}

/// The options every grading command takes.
vl::grader::grade_options take_grade_options(arguments& args) {
    vl::grader::grade_options o;
    o.weaker_sandbox = take_flag(args, "--weaker-sandbox");
    o.keep_work = take_flag(args, "--keep-work");
    return o;
}

void expect_count(const arguments& args, std::size_t n) {
    for (const std::string& a : args)
        if (a.starts_with("--")) throw command_line_error{"unknown option '" + a + "'"};
    if (args.size() != n) throw command_line_error{"expected " + std::to_string(n) + " argument(s), got " + std::to_string(args.size())};
}

/// Grades and writes results.json and report.html into `out`.
vl::grader::graded_submission grade_into(const installation& in, const std::string& assignment,
                                         const fs::path& submission, const fs::path& out,
                                         vl::grader::grade_options options) {
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

/// Where a grade goes without --out: build/grader-out/NN-name-NAME-HASH, NAME the
/// submission's file name and HASH (FNV-1a) of its absolute path, so two students'
/// folders of the same name never share one, and the build folder (ignored by git) holds it.
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

int grade_command(const installation& in, arguments args) {
    std::string out = take_option(args, "--out");
    const auto options = take_grade_options(args);
    expect_count(args, 2);
    if (out.empty()) out = default_out(in, args[0], args[1]).string();
    const auto g = grade_into(in, args[0], args[1], out, options);
    vl::grader::print_summary(std::cout, g, out, vl::grader::stdout_wants_colour());
    return 0;
}

/// The CPUs this process may use (a cluster's allocation, taskset), at least 1.
int usable_cpus() {
    cpu_set_t set;
    CPU_ZERO(&set);
    if (sched_getaffinity(0, sizeof set, &set) == 0) return std::max(1, CPU_COUNT(&set));
    return 1;
}

/// This program, for the roster to run once per submission.
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

/// `roster ASSIGNMENT DIR [-j N] [--out DIR] [--regrade NAME...] [--shard K/N] [--weaker-sandbox]`.
int roster_command(const installation& in, arguments args) {
    vl::grader::roster_options o;
    // --regrade takes the names after it, up to the next option.
    if (const auto at = std::find(args.begin(), args.end(), "--regrade"); at != args.end()) {
        auto end = at + 1;
        while (end != args.end() && !end->starts_with("-")) o.regrade.push_back(*end++);
        if (o.regrade.empty()) throw command_line_error{"--regrade needs the names of the students to grade again"};
        args.erase(at, end);
    }
    std::string jobs = take_option(args, "-j");
    for (auto it = args.begin(); it != args.end(); ++it)
        if (jobs.empty() && it->size() > 2 && it->starts_with("-j") && std::isdigit(static_cast<unsigned char>((*it)[2]))) {
            jobs = it->substr(2);
            args.erase(it);
            break;
        }
    if (jobs.empty()) jobs = take_option(args, "--jobs");
    std::string out = take_option(args, "--out");
    const std::string shard = take_option(args, "--shard");
    o.weaker_sandbox = take_flag(args, "--weaker-sandbox");
    if (args.size() != 2 && !o.regrade.empty() && args.size() < 2)
        throw command_line_error{"give ASSIGNMENT and DIR before --regrade NAME..."};
    expect_count(args, 2);
    const vl::grader::stage_info& stage = in.find_stage(args[0]);
    o.jobs = jobs.empty() ? usable_cpus() : positive_number(jobs, "-j");
    if (!shard.empty()) {
        const auto slash = shard.find('/');
        if (slash == std::string::npos) throw command_line_error{"--shard needs K/N (task K of N, K from 0), not '" + shard + "'"};
        o.shards = positive_number(shard.substr(slash + 1), "--shard's N");
        const std::string k = shard.substr(0, slash);
        o.shard = k == "0" ? 0 : positive_number(k, "--shard's K");
        if (o.shard >= o.shards) throw command_line_error{"--shard " + shard + ": K must be below N (K counts from 0)"};
    }
    const fs::path dir = fs::absolute(args[1]).lexically_normal();
    if (out.empty()) {
        const fs::path one = default_out(in, stage.name, dir.string());
        out = (one.parent_path() / ("roster-" + one.filename().string())).string();
    }
    o.out = fs::absolute(out).lexically_normal();
    o.progress_bar = isatty(2) != 0;
    o.grader_program = own_program();
    return vl::grader::run_roster(in, stage, dir, o);
}

/// `roster-collect OUT`: the CSV and the leaderboard from the records in OUT.
int roster_collect_command(const installation&, const arguments& args) {
    expect_count(args, 1);
    return vl::grader::collect_roster(fs::absolute(args[0]).lexically_normal());
}

/// \brief A calibration case: grader/tests/submissions/NN-name/CASE/expected.toml.
struct calibration_case {
    std::string stage, name, description;
    fs::path submission, expected;
    double budget_seconds = 0;  ///< expected.toml's budget_seconds: a shorter grade budget than the rubric's
    std::string variant;        ///< "-sandbox" when graded with the policy off (its own patched copy)
};

/// Where the calibration's patched copies go: one folder per case and variant.
fs::path patched_copy_dir(const installation& in, const calibration_case& c) {
    return in.grader_build_dir / "calibration-sources" / c.stage / (c.name + c.variant);
}

// A planted bug is stored as a patch against the current reference (expected.toml:
// `patch = "bug.patch"`), so it follows every change of the reference and can never go
// stale silently: when the code it changes is rewritten, the patch stops applying and the
// calibration says so.
// `name` found on PATH (the sandbox runs programs by full path).
fs::path find_on_path(const std::string& name) {
    const char* path = std::getenv("PATH");
    std::string dirs = path ? path : "/usr/bin:/bin";
    for (std::size_t start = 0; start <= dirs.size();) {
        const std::size_t end = std::min(dirs.find(':', start), dirs.size());
        const fs::path candidate = fs::path(dirs.substr(start, end - start)) / name;
        if (access(candidate.c_str(), X_OK) == 0) return candidate;
        start = end + 1;
    }
    throw grader_error("cannot find '" + name + "' on PATH (tools/setup installs it)");
}

fs::path apply_bug_patch(const installation& in, const calibration_case& c, const fs::path& patch_file,
                         const fs::path& base) {
    const fs::path dir = patched_copy_dir(in, c);
    fs::remove_all(dir);
    fs::create_directories(dir);
    for (const auto& e : fs::directory_iterator(base))
        if (e.is_regular_file()) fs::copy_file(e.path(), dir / e.path().filename());
    vl::grader::run_request rq;
    rq.argv = {find_on_path("patch").string(), "--batch", "--forward", "--silent", "-p1", "-d", dir.string(), "-i",
               fs::absolute(patch_file).string()};
    rq.cwd = dir.string();
    rq.environment = vl::grader::child_environment(dir.string());
    rq.sandboxed = false;
    rq.limits.wall_seconds = 30;
    const auto r = vl::grader::run(rq, vl::grader::sandbox_capabilities{});
    if (!r.succeeded())
        throw grader_error(patch_file.string() + ": the patch no longer applies to " + base.string() + " (" +
                           r.output_head(1000) +
                           "); plant the bug again in a copy of the current reference and remake the patch with "
                           "diff -u --label a/FILE --label b/FILE reference/" + c.stage + "/FILE COPY/FILE");
    return dir;
}

/// A case whose submission a script makes (an archive, a folder with links): expected.toml's
/// `kind` (folder, tar.gz, tar or zip) names it; `bash make.sh REPOSITORY OUT` writes it at OUT.
calibration_case made_case(const installation& in, calibration_case c, const fs::path& script, const std::string& kind) {
    const fs::path dir = patched_copy_dir(in, c);
    fs::remove_all(dir);
    fs::create_directories(dir);
    const std::string ext = kind == "folder" ? "" : "." + kind;
    if (kind != "folder" && kind != "tar.gz" && kind != "tar" && kind != "zip")
        throw grader_error(c.expected.string() + ": kind must be folder, tar.gz, tar or zip, not \"" + kind + "\"");
    c.submission = dir / ("submission" + ext);
    vl::grader::run_request rq;
    rq.argv = {"/bin/bash", fs::absolute(script).string(), in.source_dir.string(), c.submission.string()};
    rq.cwd = dir.string();
    rq.environment = vl::grader::child_environment(dir.string());
    rq.sandboxed = false;
    rq.limits.wall_seconds = 300;
    const auto r = vl::grader::run(rq, vl::grader::sandbox_capabilities{});
    std::error_code ec;
    if (!r.succeeded() || !fs::exists(fs::symlink_status(c.submission, ec)))
        throw grader_error(script.string() + " did not make " + c.submission.string() + " (" + r.describe(300) +
                           "): " + r.output_head(1000));
    return c;
}

calibration_case read_case(const installation& in, const fs::path& dir, const std::string& variant = "") {
    calibration_case c;
    c.variant = variant;
    c.expected = dir / "expected.toml";
    c.stage = fs::absolute(dir).lexically_normal().parent_path().filename().string();
    c.name = fs::absolute(dir).lexically_normal().filename().string();
    if (c.stage.empty() || c.name.empty()) {
        const fs::path clean = fs::absolute(dir).lexically_normal().parent_path();
        c.stage = clean.parent_path().filename().string();
        c.name = clean.filename().string();
    }
    toml::table t;
    try {
        t = toml::parse_file(c.expected.string());
    } catch (const toml::parse_error& e) {
        throw grader_error(c.expected.string() + ": " + std::string(e.description()));
    }
    c.description = t["description"].value_or(std::string());
    c.stage = t["stage"].value_or(c.stage);  // cases outside a stage's folder name their stage
    c.budget_seconds = t["budget_seconds"].value_or(0.0);
    // A make.sh beside expected.toml (or the script `make` names) makes the submission.
    const std::string make = t["make"].value_or(std::string(fs::exists(dir / "make.sh") ? "make.sh" : ""));
    if (!make.empty()) return made_case(in, c, dir / make, t["kind"].value_or(std::string("folder")));
    const std::string from = t["submission"].value_or(std::string());
    const std::string patch = t["patch"].value_or(std::string());
    const std::string base = t["base"].value_or(std::string("reference"));
    if (base != "reference" && base != "stubs")
        throw grader_error(c.expected.string() + ": base must be \"reference\" or \"stubs\", not \"" + base + "\"");
    const fs::path base_dir = in.source_dir / (base == "stubs" ? "assignments" : "reference") / c.stage;
    c.submission = !patch.empty() ? apply_bug_patch(in, c, dir / patch, base_dir) : from.empty() ? dir : in.source_dir / from;
    return c;
}

std::vector<calibration_case> all_cases(const installation& in) {
    std::vector<calibration_case> cases;
    for (const auto& [name, stage] : in.stages) {
        const fs::path dir = in.source_dir / "grader" / "tests" / "submissions" / name;
        if (!fs::exists(dir)) continue;
        std::vector<fs::path> dirs;
        for (const auto& e : fs::directory_iterator(dir))
            if (fs::exists(e.path() / "expected.toml")) dirs.push_back(e.path());
        std::sort(dirs.begin(), dirs.end());
        for (const fs::path& d : dirs) cases.push_back(read_case(in, d));
    }
    return cases;
}

/// What in `r` breaks Gradescope's documented results.json format (the autograder
/// specification: top-level score, execution_time, output, stdout_visibility, tests; each
/// test's score, max_score, status, name, number, output, tags, visibility).
std::vector<std::string> gradescope_format_problems(const nlohmann::json& r) {
    std::vector<std::string> problems;
    auto need = [&](const nlohmann::json& j, const char* key, auto is_type, const char* type, const std::string& where) {
        if (!j.contains(key) || !is_type(j[key])) problems.push_back(where + "\"" + key + "\" must be " + type);
    };
    const auto number = [](const nlohmann::json& j) { return j.is_number(); };
    const auto string = [](const nlohmann::json& j) { return j.is_string(); };
    const auto visibility = [](const nlohmann::json& j) {
        return j.is_string() && (j == "hidden" || j == "after_due_date" || j == "after_published" || j == "visible");
    };
    need(r, "score", number, "a number", "");
    need(r, "execution_time", number, "a number", "");
    need(r, "output", string, "a string", "");
    need(r, "stdout_visibility", visibility, "a visibility", "");
    if (r.contains("leaderboard")) {
        if (!r["leaderboard"].is_array()) problems.push_back("\"leaderboard\" must be an array");
        else
            for (const auto& v : r["leaderboard"])
                if (!v.is_object() || !v.contains("name") || !v["name"].is_string() || !v.contains("value") ||
                    !(v["value"].is_number() || v["value"].is_string()) ||
                    (v.contains("order") && v["order"] != "asc" && v["order"] != "desc"))
                    problems.push_back("a leaderboard entry needs a name, a value (number or text) and order asc or desc");
    }
    if (!r.contains("tests") || !r["tests"].is_array()) {
        problems.push_back("\"tests\" must be an array");
        return problems;
    }
    for (const auto& t : r["tests"]) {
        const std::string where = "test " + (t.contains("name") ? t["name"].dump() : std::string("?")) + ": ";
        need(t, "name", string, "a string", where);
        need(t, "number", string, "a string", where);
        need(t, "score", number, "a number", where);
        need(t, "max_score", number, "a number", where);
        need(t, "output", string, "a string", where);
        need(t, "visibility", visibility, "a visibility", where);
        need(t, "status", [](const nlohmann::json& j) { return j == "passed" || j == "failed"; }, "passed or failed",
             where);
        need(t, "tags", [](const nlohmann::json& j) { return j.is_array(); }, "an array", where);
        if (t.contains("score") && t.contains("max_score") && t["score"].is_number() && t["max_score"].is_number() &&
            (t["score"].get<double>() < 0 || t["score"].get<double>() > t["max_score"].get<double>() + 1e-9))
            problems.push_back(where + "score outside 0..max_score");
    }
    return problems;
}

/// Compares a grade with expected.toml: the score's range in percent, which categories
/// must lose points (every other one must keep full marks), whether it built; and checks
/// that results.json keeps to Gradescope's format.
std::vector<std::string> check_expectations(const fs::path& results, const fs::path& expected, bool sandbox_alone) {
    std::ifstream in(results);
    const nlohmann::json r = nlohmann::json::parse(in);
    const toml::table whole = toml::parse_file(expected.string());
    // With the policy off, the [sandbox] table holds what must happen instead.
    const toml::table empty;
    const toml::table& t = sandbox_alone ? (whole["sandbox"].as_table() ? *whole["sandbox"].as_table() : empty) : whole;
    std::vector<std::string> problems = gradescope_format_problems(r);
    if (const auto verdict = t["verdict"].value<std::string>()) {
        bool found = false;
        for (const auto& test : r["tests"])
            if (test["output"].get<std::string>().find(*verdict) != std::string::npos) found = true;
        if (!found) problems.push_back("no item's output says \"" + *verdict + "\"");
    }
    const double score = r["score"], max = r["extra_data"]["max_score"];
    const double percent = max > 0 ? 100 * score / max : 0;
    if (const toml::array* range = t["score_percent"].as_array()) {
        const double lo = range->get(0)->value<double>().value_or(0), hi = range->get(1)->value<double>().value_or(100);
        if (percent < lo - 1e-9 || percent > hi + 1e-9)
            problems.push_back("score " + std::to_string(percent) + "% is outside [" + std::to_string(lo) + ", " +
                               std::to_string(hi) + "]");
    }
    if (const auto built = t["built"].value<bool>(); built && r["extra_data"]["built"].get<bool>() != *built)
        problems.push_back(*built ? "it did not build" : "it built, but should not have");
    if (const toml::array* lose = t["lose_only"].as_array()) {
        std::vector<std::string> losing;
        for (const toml::node& n : *lose) losing.push_back(*n.value<std::string>());
        for (const auto& c : r["extra_data"]["categories"]) {
            const std::string name = c["name"];
            const bool lost = c["score"].get<double>() < c["max_score"].get<double>() - 1e-9;
            const bool should = std::find(losing.begin(), losing.end(), name) != losing.end();
            if (lost && !should) problems.push_back("lost points in category '" + name + "', where it should not");
            if (!lost && should) problems.push_back("kept full marks in category '" + name + "', where it should lose");
        }
    }
    // lose_sweeps: exactly these sweeps (by their tests' names) fail; every other passes.
    // A case that says where it loses (lose_only) and names no sweep must pass them all.
    if (t["lose_only"].as_array() || t["lose_sweeps"].as_array()) {
        std::vector<std::string> losing;
        if (const toml::array* sweeps = t["lose_sweeps"].as_array())
            for (const toml::node& n : *sweeps) losing.push_back(n.value<std::string>().value_or(""));
        std::vector<std::string> seen;
        for (const auto& test : r["tests"]) {
            if (!test["extra_data"].contains("sweep")) continue;
            const std::string name = test["extra_data"]["sweep"]["test"];
            seen.push_back(name);
            const bool lost = test["status"] != "passed";
            const bool should = std::find(losing.begin(), losing.end(), name) != losing.end();
            if (lost && !should) problems.push_back("failed the sweep '" + name + "', which it should pass");
            if (!lost && should) problems.push_back("passed the sweep '" + name + "', which it should fail");
        }
        for (const std::string& name : losing)
            if (std::find(seen.begin(), seen.end(), name) == seen.end())
                problems.push_back("lose_sweeps names '" + name + "', which is no sweep of this grade");
    }
    return problems;
}

int calibrate_command(const installation& in, arguments args) {
    std::string out = take_option(args, "--out");
    auto options = take_grade_options(args);
    options.policy = !take_flag(args, "--no-policy");
    expect_count(args, 1);
    const calibration_case c = read_case(in, args[0], options.policy ? "" : "-sandbox");
    options.budget_seconds = c.budget_seconds;
    if (out.empty()) out = (in.grader_build_dir / "calibration" / c.stage / c.name).string();
    const auto g = grade_into(in, c.stage, c.submission, out, options);
    vl::grader::print_summary(std::cout, g, out, false);
    const auto problems = check_expectations(fs::path(out) / "results.json", c.expected, !options.policy);
    for (const std::string& p : problems) std::cout << "CALIBRATION: " << c.stage << "/" << c.name << ": " << p << "\n";
    if (problems.empty()) std::cout << "calibration: " << c.stage << "/" << c.name << " as expected\n";
    return problems.empty() ? 0 : 1;
}

/// `demo`: the bundled sample submissions of every stage (the calibration cases), each
/// stage as a roster of them (build/default/grader/demo/NN-name), so they are graded side
/// by side and a second demo grades only what changed since.
int demo_command(const installation& in, arguments args) {
    const auto options = take_grade_options(args);
    expect_count(args, 0);
    const fs::path root = in.grader_build_dir / "demo";
    const bool colour = vl::grader::stdout_wants_colour();
    std::map<std::string, std::vector<calibration_case>> by_stage;
    for (const calibration_case& c : all_cases(in)) by_stage[c.stage].push_back(c);
    struct line {
        std::string what, description;
        double score, max;
        fs::path report;
    };
    std::vector<line> lines;
    int status = 0;
    for (const auto& [stage_name, cases] : by_stage) {
        // The roster's folder: one link per case, named for it, to the submission.
        const fs::path dir = root / "submissions" / stage_name;
        std::error_code ec;
        fs::remove_all(dir, ec);
        fs::create_directories(dir);
        for (const calibration_case& c : cases) {
            const std::string file = c.submission.filename().string();
            const auto dot = file.find('.');
            fs::create_directory_symlink(fs::absolute(c.submission),
                                         dir / (c.name + (fs::is_directory(c.submission) || dot == std::string::npos
                                                              ? std::string()
                                                              : file.substr(dot))));
        }
        vl::grader::roster_options o;
        o.out = root / stage_name;
        o.jobs = usable_cpus();
        o.weaker_sandbox = options.weaker_sandbox;
        o.progress_bar = isatty(2) != 0;
        o.grader_program = own_program();
        std::cout << "\n";
        status |= vl::grader::run_roster(in, in.find_stage(stage_name), dir, o);
        for (const calibration_case& c : cases) {
            vl::grader::roster_record r;
            if (!vl::grader::read_record(o.out, c.name, r) || r.status != "graded") continue;
            lines.push_back({stage_name + " " + c.name, c.description, r.score, r.max_score, o.out / r.grade / "report.html"});
        }
    }
    std::cout << "\n";
    for (const line& l : lines)
        std::printf("%s%-34s %6.1f / %5.1f%s  %s\n", colour ? "\033[1m" : "", l.what.c_str(), l.score, l.max,
                    colour ? "\033[0m" : "", l.report.c_str());
    std::cout << "\nOpen a report in a browser; each folder also holds its results.json. What each sample is: "
                 "grader/tests/submissions/NN-name/README.md.\n";
    return status;
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

/// Reads the image `file` for imgdiff; `role` ("reference" or "test") names it in errors.
vl::image read_for_imgdiff(const std::string& file, const char* role) {
    try {
        return vl::read_image(file);
    } catch (const vl::image_error& e) {
        throw grader_error(std::string("cannot read the ") + role + " image: " + e.what() +
                           " (give the path of a PNG, PPM, PGM, PBM or PFM file)");
    }
}

/// `calibrate-thresholds ASSIGNMENT [--calibration DIR] [--renderer PATH]... [--out DIR]`: the FLIP spread of
/// each hidden scene over its legitimate renders and the thresholds it suggests
/// (thresholds.hh); prints one line per render and one per scene, and writes them to
/// OUT/thresholds.tsv.
int calibrate_thresholds_command(const installation& in, arguments args) {
    std::string calibration = take_option(args, "--calibration");
    std::string out = take_option(args, "--out");
    std::vector<fs::path> renderers;
    for (std::string r = take_option(args, "--renderer"); !r.empty(); r = take_option(args, "--renderer")) {
        if (!fs::is_regular_file(r)) throw command_line_error{"--renderer " + r + ": no such program"};
        renderers.push_back(fs::absolute(r));
    }
    expect_count(args, 1);
    const vl::grader::stage_info& stage = in.find_stage(args[0]);
    if (calibration.empty()) calibration = (in.grader_build_dir / "calibration" / stage.name).string();
    if (out.empty()) out = (in.grader_build_dir / "thresholds" / stage.name).string();
    const auto spreads = vl::grader::measure_spread(in, stage, calibration, out, renderers);
    std::ofstream tsv(fs::path(out) / "thresholds.tsv");
    tsv << "scene\tvariation\tflip_mean\tfraction_over\n";
    for (const auto& sp : spreads) {
        for (const auto& v : sp.variations) {
            if (!v.problem.empty()) {
                std::printf("scene=%s variation=\"%s\" not measured: %s\n", sp.id.c_str(), v.name.c_str(), v.problem.c_str());
                continue;
            }
            std::printf("scene=%s variation=\"%s\" flip_mean=%.5f fraction_over=%.5f\n", sp.id.c_str(), v.name.c_str(),
                        v.flip_mean, v.fraction_over);
            tsv << sp.id << '\t' << v.name << '\t' << v.flip_mean << '\t' << v.fraction_over << '\n';
        }
        std::printf("scene=%s spread: flip_mean<=%.5f fraction_over<=%.5f -> max_flip_mean = %g, max_fraction_over = %g"
                    " (the rubric has metric=%s, max_flip_mean=%g, max_fraction_over=%g)\n",
                    sp.id.c_str(), sp.max_flip_mean, sp.max_fraction_over, sp.suggested_flip_mean, sp.suggested_fraction,
                    sp.metric.c_str(), sp.current_max_flip_mean, sp.current_max_fraction_over);
    }
    std::printf("written: %s\n", (fs::path(out) / "thresholds.tsv").string().c_str());
    return 0;
}

/// `imgdiff REF TEST [--map OUT.png] [--ppd N]`: LDR-FLIP, SSIM and the largest 8-bit
/// difference of TEST against REF, on one line (docs/image-metrics.md explains them).
int imgdiff_command(arguments args) {
    const std::string map = take_option(args, "--map");
    const std::string ppd_text = take_option(args, "--ppd");
    expect_count(args, 2);
    vl::flip_options options;
    if (!ppd_text.empty()) {
        char* end = nullptr;
        options.pixels_per_degree = std::strtod(ppd_text.c_str(), &end);
        if (end == ppd_text.c_str() || *end != '\0' || !(options.pixels_per_degree > 0) ||
            !std::isfinite(options.pixels_per_degree))
            throw command_line_error{"--ppd needs a positive number of pixels per degree, not '" + ppd_text + "'"};
    }
    const vl::image reference = read_for_imgdiff(args[0], "reference");
    const vl::image test = read_for_imgdiff(args[1], "test");
    if (reference.width() != test.width() || reference.height() != test.height())
        throw grader_error("the images differ in size: the reference " + args[0] + " is " +
                           std::to_string(reference.width()) + " x " + std::to_string(reference.height()) +
                           " pixels and the test " + args[1] + " is " + std::to_string(test.width()) + " x " +
                           std::to_string(test.height()) +
                           " pixels; imgdiff compares images pixel by pixel: render the test at the reference's size");
    const vl::flip_result f = vl::flip(reference, test, options);
    const vl::ssim_result s = vl::ssim(reference, test);
    const vl::image_difference d = vl::compare_images(reference, test);
    if (!map.empty()) {
        try {
            vl::write_image(map, vl::flip_error_map(f));
        } catch (const vl::image_error& e) {
            throw grader_error(std::string("cannot write the error map: ") + e.what());
        }
    }
    std::printf("flip_mean=%.6f ssim=%.6f max_abs=%d flip_weighted_median=%.6f flip_weighted_q1=%.6f "
                "flip_weighted_q3=%.6f flip_max=%.6f mean_abs=%.4f\n",
                f.mean, s.mean, d.max_abs, f.weighted_median, f.weighted_quartile_1, f.weighted_quartile_3, f.max,
                d.mean_abs);
    return 0;
}

/// `tradeoff ...`: runs the tradeoff program this build made (framework/apps/tradeoff,
/// beside the grader's build folder), which knows its own options (`tradeoff --help`).
int tradeoff_command(arguments args) {
    char self[4096];
    const ssize_t n = readlink("/proc/self/exe", self, sizeof self - 1);
    if (n <= 0) throw grader_error("cannot find the grader's own program (/proc/self/exe) to find tradeoff beside it");
    self[n] = '\0';
    const fs::path program = fs::path(self).parent_path().parent_path() / "framework" / "apps" / "tradeoff";
    if (access(program.c_str(), X_OK) != 0)
        throw grader_error(program.string() + " is missing: build it with tools/setup (or cmake --build build/default "
                           "--target tradeoff)");
    std::vector<char*> argv{const_cast<char*>(program.c_str())};
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    std::fflush(stdout);
    execv(program.c_str(), argv.data());
    throw grader_error("cannot run " + program.string() + ": " + std::strerror(errno));
}

const std::vector<command>& commands() {
    static const std::vector<command> table = {
        {"demo", "demo", "grade the bundled sample submissions and print where their reports are", demo_command},
        {"grade", "grade ASSIGNMENT SUBMISSION [--out DIR] [--weaker-sandbox] [--keep-work]",
         "grade one submission (a folder, a student kit, or a .zip/.tar.gz of one); writes DIR/results.json "
         "and DIR/report.html",
         grade_command},
        {"roster", "roster ASSIGNMENT DIR [-j N] [--out DIR] [--regrade NAME...] [--shard K/N] [--weaker-sandbox]",
         "grade every submission in DIR (one folder or archive per student), N at once (default: one per CPU), "
         "each in its own sandboxes; a rerun grades only what is new or changed; writes roster.csv, "
         "grades/NAME-HASH/ and, where the rubric has one, leaderboard.csv into --out DIR",
         roster_command},
        {"roster-collect", "roster-collect OUT",
         "write OUT/roster.csv and OUT/leaderboard.csv from the grades in OUT (after a cluster's array tasks, "
         "grader/slurm/)",
         roster_collect_command},
        {"export-kit", "export-kit DIR", "write the student kit to DIR and DIR.tar.gz (no reference, no hidden tests)",
         export_kit_command},
        {"gradescope", "gradescope ASSIGNMENT OUT.zip",
         "write a Gradescope autograder bundle that grades ASSIGNMENT (setup.sh builds it, run_autograder grades)",
         gradescope_command},
        {"list", "list", "the assignments this build can grade", list_command},
        {"calibrate", "calibrate CASE_DIR [--out DIR] [--no-policy]",
         "grade one calibration or attack case (grader/tests/submissions/NN-name/CASE, grader/tests/adversarial/...) "
         "and check it against its expected.toml; --no-policy tests the sandbox alone ([sandbox] in expected.toml)",
         calibrate_command},
        {"calibrate-thresholds", "calibrate-thresholds ASSIGNMENT [--calibration DIR] [--renderer PATH]... [--out DIR]",
         "the FLIP spread of each hidden scene over legitimate renders (two threads, other seeds, other builds' "
         "reference renderers, the correct alternative cases' renders from DIR, by default the calibrate "
         "command's) and the max_flip_mean and max_fraction_over that follow",
         calibrate_thresholds_command},
        {"imgdiff", "imgdiff REF TEST [--map OUT.png] [--ppd N]",
         "how different TEST looks from REF: prints flip_mean (LDR-FLIP, 0 same), ssim (1 same), max_abs (8-bit "
         "levels) and FLIP's weighted percentiles on one line; --map writes the FLIP error map (magma colours)",
         nullptr, imgdiff_command},
        {"tradeoff", "tradeoff SCENE [options] | --structures [options]",
         "speed against accuracy as charts (TSV, gnuplot script, SVG, PNG in --out DIR), one line per point: SCENE's "
         "LDR-FLIP against a converged render at 1 to 64 samples per pixel, per sample pattern, against time, rays "
         "and tests; --structures: composites' tests per ray against N and build time (tradeoff --help)",
         nullptr, tradeoff_command},
    };
    return table;
}

void print_usage(std::FILE* to) {
    std::fprintf(to, "usage: grader/run COMMAND [ARGUMENTS]\n\ncommands:\n");
    for (const command& c : commands()) std::fprintf(to, "  %-40s %s\n", c.synopsis.c_str(), c.summary.c_str());
    std::fprintf(to, "\nASSIGNMENT is a number (02), a full name (02-sphere) or a name (sphere).\n"
                     "grade exits 0 whenever it wrote results, whatever the score.\n");
}

}  // namespace

int main(int argc, char** argv) {
    const arguments all(argv + 1, argv + argc);
    if (all.empty() || all[0] == "-h" || all[0] == "--help" || all[0] == "help") {
        print_usage(all.empty() ? stderr : stdout);
        return all.empty() ? 2 : 0;
    }
    const auto c = std::find_if(commands().begin(), commands().end(), [&](const command& x) { return x.name == all[0]; });
    if (c == commands().end()) {
        std::fprintf(stderr, "grader: unknown command '%s'\n\n", all[0].c_str());
        print_usage(stderr);
        return 2;
    }
    try {
        if (c->run_alone) return c->run_alone(arguments(all.begin() + 1, all.end()));
        const installation in = vl::grader::load_installation();
        return c->run(in, arguments(all.begin() + 1, all.end()));
    } catch (const command_line_error& e) {
        std::fprintf(stderr, "grader %s: %s\nusage: grader/run %s\n", c->name.c_str(), e.message.c_str(),
                     c->synopsis.c_str());
        return 2;
    } catch (const grader_error& e) {
        std::fprintf(stderr, "grader %s: %s\n", c->name.c_str(), e.what());
    } catch (const std::exception& e) {
        std::fprintf(stderr, "grader %s: %s\n", c->name.c_str(), e.what());
    }
    return 1;
}
