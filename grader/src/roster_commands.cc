// The subcommands that grade many submissions as a roster (roster.hh): roster,
// roster-collect, and demo, which grades the bundled sample submissions as one roster per stage.
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <iostream>
#include <map>

#include "calibration.hh"
#include "commands.hh"
#include "roster.hh"
#include "roster_results.hh"
#include "terminal_summary.hh"

namespace vl::grader {

namespace fs = std::filesystem;

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

}  // namespace vl::grader
