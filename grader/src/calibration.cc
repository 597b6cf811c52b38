// The calibration: reading a case (calibration.hh) and making its submission, then
// `grader/run calibrate CASE_DIR`: grade it and compare the grade with its expected.toml.
#include "calibration.hh"

#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <iostream>

#include <nlohmann/json.hpp>
#include <toml++/toml.h>

#include "commands.hh"
#include "results_json.hh"
#include "sandbox.hh"
#include "terminal_summary.hh"

namespace vl::grader {

namespace fs = std::filesystem;

namespace {

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

}  // namespace

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

int calibrate_command(const installation& in, arguments args) {
    std::string out = take_option(args, "--out");
    auto options = take_grade_options(args);
    options.policy = !take_flag(args, "--no-policy");
    if (const std::string scale = take_option(args, "--limits-scale"); !scale.empty()) {
        char* end = nullptr;
        options.limits_scale = std::strtod(scale.c_str(), &end);
        if (end == scale.c_str() || *end != '\0' || !(options.limits_scale > 0 && options.limits_scale <= 1))
            throw command_line_error{"--limits-scale takes a number above 0 and at most 1, not '" + scale + "'"};
    }
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

}  // namespace vl::grader
