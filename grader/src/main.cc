// The grader's command line: `grader/run COMMAND ...` (see grader/README.md). Each
// command is one entry of the table below, so new ones (roster, gradescope) slot in
// beside the others, like imgdiff; the commands themselves are in commands.hh.
#include <algorithm>
#include <cstdio>
#include <exception>
#include <functional>
#include <string>
#include <vector>

#include "commands.hh"
#include "install.hh"

namespace {

using namespace vl::grader;

/// \brief One subcommand: `run` needs the built grader's installation (grader.toml);
/// `run_alone`, when set instead, needs nothing but its arguments.
struct command {
    std::string name, synopsis, summary;
    std::function<int(const installation&, const arguments&)> run;
    std::function<int(const arguments&)> run_alone = nullptr;
};

const std::vector<command>& commands() {
    static const std::vector<command> table = {
        {"demo", "demo", "grade the bundled sample submissions and print where their reports are", demo_command},
        {"grade", "grade ASSIGNMENT SUBMISSION [--out DIR] [--jobs N] [--weaker-sandbox] [--keep-work]",
         "grade one submission (a folder, a student kit, or a .zip/.tar.gz of one); writes DIR/results.json "
         "and DIR/report.html; --jobs N runs N tests and scenes at once (default: one per two CPUs, at most 4)",
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
        {"calibrate", "calibrate CASE_DIR [--out DIR] [--jobs N] [--no-policy] [--limits-scale F]",
         "grade one calibration or attack case (grader/tests/submissions/NN-name/CASE, grader/tests/adversarial/...) "
         "and check it against its expected.toml; --no-policy tests the sandbox alone ([sandbox] in expected.toml); "
         "--limits-scale F (0 < F <= 1) grades with the rubric's test and render time limits times F, so an endless "
         "loop ends sooner",
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
