#include "roster.hh"

#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/prctl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <thread>

#include <nlohmann/json.hpp>

#include "commands.hh"
#include "roster_results.hh"
#include "rubric.hh"
#include "safe_files.hh"

namespace vl::grader {

namespace fs = std::filesystem;
using nlohmann::json;
using clock_type = std::chrono::steady_clock;

namespace {

// --- The scheduler's state and its screen -------------------------------------------

volatile std::sig_atomic_t stop_signal = 0;
extern "C" void on_stop_signal(int s) { stop_signal = s; }

/// One grade under way: a `grader grade` child process.
struct running_grade {
    roster_entry entry;
    std::string hash;
    pid_t pid = -1;
    fs::path work, log;
    clock_type::time_point started;
    bool overran = false;  ///< killed by the roster's guard (a grade that hangs)
};

std::string clock_text(double seconds) {
    if (!(seconds >= 0) || !std::isfinite(seconds)) return "--:--";
    const long s = std::lround(seconds);
    char text[32];
    if (s >= 3600) std::snprintf(text, sizeof text, "%ld:%02ld:%02ld", s / 3600, s / 60 % 60, s % 60);
    else std::snprintf(text, sizeof text, "%ld:%02ld", s / 60, s % 60);
    return text;
}

/// The progress: a bar redrawn on a terminal, and one line per finished grade.
struct progress {
    std::size_t total = 0, done = 0, errors = 0;
    std::size_t name_width = 0;  ///< the longest name, up to 32 characters: the lines' columns
    int jobs = 1;
    bool bar = false;
    double finished_seconds = 0;      ///< the durations of the grades finished so far, added up
    std::vector<double> running_ages;  ///< how long each running grade has run
    clock_type::time_point started = clock_type::now();
    mutable std::string drawn;

    /// The time left: the grades not started, each the mean length so far, and what the
    /// running ones probably still need, shared among the jobs.
    std::string eta() const {
        if (done == 0) return "ETA --:--";
        const double mean = finished_seconds / static_cast<double>(done);
        double work = static_cast<double>(total - done - running_ages.size()) * mean;
        for (const double age : running_ages) work += std::max(0.0, mean - age);
        return "ETA " + clock_text(work / jobs);
    }
    void draw() const {
        if (!bar) return;
        const int width = 30;
        const int filled = total ? static_cast<int>(width * done / total) : width;
        const double elapsed = std::chrono::duration<double>(clock_type::now() - started).count();
        const std::string line = "\r[" + std::string(static_cast<std::size_t>(filled), '#') +
                                 std::string(static_cast<std::size_t>(width - filled), '.') + "] " +
                                 std::to_string(done) + "/" + std::to_string(total) + "  " +
                                 std::to_string(running_ages.size()) + " grading" +
                                 (errors ? "  " + std::to_string(errors) + " grader error(s)" : std::string()) + "  " +
                                 clock_text(elapsed) + "  " + eta() + "\033[K";
        if (line == drawn) return;  // a terminal is redrawn when something changed, at most every second
        drawn = line;
        std::fputs(line.c_str(), stderr);
        std::fflush(stderr);
    }
    /// "[ 3/20] alice    " with the counter and the name padded to their widths.
    std::string head(const std::string& name) const {
        const std::string n = std::to_string(total);
        std::string count = std::to_string(done);
        count = std::string(n.size() - std::min(n.size(), count.size()), ' ') + count;
        std::string padded = name;
        if (padded.size() < name_width) padded += std::string(name_width - padded.size(), ' ');
        return "[" + count + "/" + n + "] " + padded;
    }
    void line(const std::string& text) const {
        if (bar) std::fputs("\r\033[K", stderr);
        drawn.clear();
        std::cout << text << "\n" << std::flush;
    }
    void finish() const {
        if (bar) std::fputs("\r\033[K", stderr);
    }
};

/// Starts `grader grade` for `g` in its own work folder, its output in g.log. The child
/// dies with the roster (PR_SET_PDEATHSIG), so a roster killed with SIGKILL leaves no grade
/// running behind it; the grade's sandboxes die with the grade (bubblewrap --die-with-parent).
void start_grade(running_grade& g, const installation& in, const stage_info& stage, const roster_options& o) {
    std::vector<std::string> args = {o.grader_program.string(), "grade", stage.name, g.entry.submission.string(), "--out",
                                     g.work.string()};
    if (o.weaker_sandbox) args.push_back("--weaker-sandbox");
    // The CPUs are shared among the grades running at once.
    args.push_back("--jobs");
    args.push_back(std::to_string(default_item_jobs(o.jobs)));
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    const int log = open(g.log.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_NOFOLLOW | O_CLOEXEC, 0644);
    if (log < 0) throw grader_error("cannot write " + g.log.string() + ": " + std::strerror(errno));
    const pid_t parent = getpid();
    std::fflush(stdout);
    std::fflush(stderr);
    const pid_t pid = fork();
    if (pid < 0) {
        close(log);
        throw grader_error(std::string("cannot start a grade (fork): ") + std::strerror(errno));
    }
    if (pid == 0) {
        prctl(PR_SET_PDEATHSIG, SIGKILL);
        if (getppid() != parent) _exit(127);
        setpgid(0, 0);  // a Ctrl-C reaches the roster, which stops its grades itself
        signal(SIGINT, SIG_DFL);
        signal(SIGTERM, SIG_DFL);
        const int null = open("/dev/null", O_RDONLY);
        if (null >= 0) dup2(null, 0);
        dup2(log, 1);
        dup2(log, 2);
        if (chdir(in.source_dir.c_str()) != 0) _exit(127);
        execv(argv[0], argv.data());
        std::fprintf(stderr, "cannot run %s: %s\n", argv[0], std::strerror(errno));
        _exit(127);
    }
    close(log);
    g.pid = pid;
    g.started = clock_type::now();
}

/// The last non-empty line of a grade's log (the grader's own error message), made one line.
std::string last_line(const fs::path& log) {
    const std::string text = read_regular_file(log, std::size_t{16} << 20);
    std::string last;
    std::size_t start = 0;
    while (start < text.size()) {
        const std::size_t end = std::min(text.find('\n', start), text.size());
        if (end > start) last = text.substr(start, end - start);
        start = end + 1;
    }
    if (last.size() > 400) last = last.substr(0, 400) + "...";
    return last;
}

/// Takes `fd` as a lock (flock): shared or exclusive, without waiting.
bool lock(const fs::path& file, bool exclusive) {
    const int fd = open(file.c_str(), O_RDWR | O_CREAT | O_NOFOLLOW | O_CLOEXEC, 0644);
    return fd >= 0 && flock(fd, (exclusive ? LOCK_EX : LOCK_SH) | LOCK_NB) == 0;  // held until the process ends
}

/// OUT/roster.json: what this folder holds; a folder of another assignment is refused.
void claim_out(const fs::path& out, const stage_info& stage, const fs::path& dir) {
    const fs::path file = out / "roster.json";
    const json old = json::parse(read_regular_file(file, 1 << 20), nullptr, false);
    if (old.is_object() && old.value("assignment", stage.name) != stage.name)
        throw grader_error(out.string() + " holds a roster of " + old.value("assignment", std::string("?")) + ", not " +
                           stage.name + ": give each assignment its own --out");
    replace_file(file, json{{"assignment", stage.name}, {"submissions", dir.string()}}.dump(2) + "\n");
}

}  // namespace

int run_roster(const installation& in, const stage_info& stage, const fs::path& dir, const roster_options& o) {
    std::vector<std::string> skipped;
    const std::vector<roster_entry> all = list_submissions(dir, skipped, o.out);
    for (const std::string& s : skipped) std::cout << "skipped " << s << "\n";
    if (all.empty())
        throw grader_error(dir.string() + " holds no submission: give the folder that holds one folder or .zip, .tar.gz, "
                           ".tgz or .tar archive per student");
    for (const std::string& name : o.regrade)
        if (std::none_of(all.begin(), all.end(), [&](const roster_entry& e) { return e.name == name; }))
            throw grader_error("--regrade " + name + ": " + dir.string() + " has no submission of that name (a folder " +
                               name + "/ or an archive " + name + ".zip, .tar.gz, .tgz or .tar)");

    const fs::path out = o.out;
    std::error_code ec;
    for (const char* sub : {"results", "grades", ".work"}) {
        fs::create_directories(out / sub, ec);
        if (ec || access((out / sub).c_str(), W_OK | X_OK) != 0)
            throw grader_error("cannot write the roster's results to " + (out / sub).string() + ": " +
                               (ec ? ec.message() : std::string(std::strerror(errno))) + " (choose another --out)");
    }
    // One roster per folder, or several array tasks, each with its own shard.
    const std::string shard_name = "shard-" + std::to_string(o.shard) + "-of-" + std::to_string(o.shards);
    if (!lock(out / ".work" / "roster.lock", o.shards == 1) || !lock(out / ".work" / (shard_name + ".lock"), true))
        throw grader_error("another roster is grading into " + out.string() +
                           " right now: wait for it to end, or give this one another --out");
    claim_out(out, stage, fs::absolute(dir));
    const fs::path work = out / ".work" / shard_name;
    fs::remove_all(work, ec);  // what a killed roster of this shard left half-done
    fs::create_directories(work, ec);
    if (ec) throw grader_error("cannot make " + work.string() + ": " + ec.message());

    // Who needs a grade: every entry of this shard without a record of its present content.
    std::vector<roster_entry> mine;
    for (std::size_t k = 0; k < all.size(); ++k)
        if (static_cast<int>(k % static_cast<std::size_t>(o.shards)) == o.shard) mine.push_back(all[k]);
    const std::string setup = setup_hash(in, stage, o.grader_program);
    std::vector<std::pair<roster_entry, std::string>> todo;
    std::size_t unchanged = 0, other_setup = 0;
    for (const roster_entry& e : mine) {
        const std::string hash = content_hash(e.submission);
        roster_record r;
        const bool forced = std::find(o.regrade.begin(), o.regrade.end(), e.name) != o.regrade.end();
        const bool have = read_record(out, e.name, r) && r.status == "graded" && r.hash == hash &&
                          fs::is_regular_file(out / r.grade / "results.json", ec);
        if (!forced && have && r.setup == setup) {
            ++unchanged;
            continue;
        }
        if (have && r.setup != setup) ++other_setup;
        todo.emplace_back(e, hash);
    }
    const int jobs = std::max(1, std::min<int>(o.jobs, static_cast<int>(std::max<std::size_t>(todo.size(), 1))));
    std::cout << stage.name << ": " << mine.size() << " submission(s)" << (o.shards > 1 ? " in " + shard_name : "")
              << "; " << unchanged << " already graded and unchanged; grading " << todo.size() << " with -j " << jobs
              << "\n";
    if (other_setup)
        std::cout << "of them, " << other_setup << " had been graded by another build of the grader, its hidden tests "
                  << "or its rubric: every grade in the CSV comes from the same ones\n";
    std::cout << std::flush;

    const rubric r = load_rubric(in.hidden_dir(stage) / "rubric.toml", in.assignment_dir(stage) / "scenes", in.sanitized);
    // A grade keeps to its budget by itself; this only catches a grader that hangs.
    const double guard_seconds = 2 * r.grade_budget_seconds + 300;

    struct sigaction stop {};
    stop.sa_handler = on_stop_signal;
    sigemptyset(&stop.sa_mask);
    struct sigaction old_int {}, old_term {};
    sigaction(SIGINT, &stop, &old_int);
    sigaction(SIGTERM, &stop, &old_term);

    progress p;
    p.total = todo.size();
    p.bar = o.progress_bar;
    p.jobs = jobs;
    for (const auto& t : todo) p.name_width = std::max(p.name_width, std::min<std::size_t>(t.first.name.size(), 32));
    std::vector<running_grade> running;
    std::vector<std::string> failures;
    std::size_t next = 0;
    auto finish = [&](running_grade& g, int status) {
        std::error_code ignored;
        if (stop_signal) {  // stopped: this grade counts for nothing, and is done again next time
            fs::remove_all(g.work, ignored);
            return;
        }
        const double seconds = std::chrono::duration<double>(clock_type::now() - g.started).count();
        const std::string stem = roster_file_stem(g.entry.name);
        const bool exited = WIFEXITED(status) && WEXITSTATUS(status) == 0;
        roster_record rec;
        std::string problem;
        if (exited && fs::is_regular_file(g.work / "results.json")) {
            const std::string grade_dir = "grades/" + stem + "-" + g.hash;
            try {
                rec = record_from_results(g.work / "results.json", g.entry.name, g.entry.submission.string(), g.hash,
                                          grade_dir);
                rec.setup = setup;
                fs::rename(g.log, g.work / "grader.log");
                // The old grade of the same content (a --regrade) makes way, then the new one
                // moves in whole; only then does the record name it.
                const fs::path final_dir = out / grade_dir;
                if (fs::exists(fs::symlink_status(final_dir))) {
                    const fs::path old = work / (stem + ".replaced");
                    fs::rename(final_dir, old);
                    fs::remove_all(old);
                }
                fs::rename(g.work, final_dir);
                write_record(out, rec);
                fs::remove(out / "results" / (stem + ".log"), ignored);  // of an earlier grader error
            } catch (const std::exception& e) {
                problem = e.what();
            }
        } else {
            problem = g.overran ? "the grade did not end within " + std::to_string(static_cast<int>(guard_seconds)) +
                                      " s (twice the rubric's grade_budget_seconds, and 300): the grader hung"
                      : WIFSIGNALED(status) ? std::string("the grade was killed by signal ") + strsignal(WTERMSIG(status))
                                            : "the grader failed: " + last_line(g.log);
        }
        ++p.done;
        p.finished_seconds += seconds;
        if (!problem.empty()) {
            ++p.errors;
            roster_record err;
            err.student = g.entry.name;
            err.submission = g.entry.submission.string();
            err.hash = g.hash;
            err.assignment = stage.name;
            err.status = "grader error";
            err.message = problem;
            const fs::path kept_log = out / "results" / (stem + ".log");
            fs::rename(g.log, kept_log, ignored);
            try {
                write_record(out, err);
            } catch (const std::exception&) {
            }
            failures.push_back(g.entry.name + ": " + problem + " (its log: " + kept_log.string() + ")");
            p.line(p.head(g.entry.name) + "  GRADER ERROR, no grade: " + problem);
        } else {
            char score[96];
            std::snprintf(score, sizeof score, "%6.1f / %5.1f  %-13s %5.1f s", rec.score, rec.max_score,
                          rec.verdict.c_str(), seconds);
            p.line(p.head(g.entry.name) + "  " + score);
        }
        fs::remove_all(g.work, ignored);
    };

    while ((next < todo.size() || !running.empty()) && !stop_signal) {
        while (next < todo.size() && static_cast<int>(running.size()) < jobs && !stop_signal) {
            running_grade g;
            g.entry = todo[next].first;
            g.hash = todo[next].second;
            g.work = work / roster_file_stem(g.entry.name);
            g.log = work / (roster_file_stem(g.entry.name) + ".log");
            start_grade(g, in, stage, o);
            running.push_back(g);
            ++next;
        }
        bool reaped = false;
        for (auto it = running.begin(); it != running.end();) {
            int status = 0;
            const pid_t w = waitpid(it->pid, &status, WNOHANG);
            if (w == it->pid) {
                finish(*it, status);
                it = running.erase(it);
                reaped = true;
                continue;
            }
            if (!it->overran && std::chrono::duration<double>(clock_type::now() - it->started).count() > guard_seconds) {
                it->overran = true;
                kill(it->pid, SIGKILL);  // reaped, as killed, on the next round
            }
            ++it;
        }
        p.running_ages.clear();
        for (const running_grade& g : running)
            p.running_ages.push_back(std::chrono::duration<double>(clock_type::now() - g.started).count());
        p.draw();
        if (!reaped) std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    p.finish();
    if (stop_signal) {
        for (running_grade& g : running) kill(g.pid, SIGKILL);
        for (running_grade& g : running) waitpid(g.pid, nullptr, 0);
        fs::remove_all(work, ec);
        std::cout << "stopped (" << strsignal(stop_signal) << "): " << p.done << " of " << p.total
                  << " graded in this run; run the same command again to grade the rest\n";
        sigaction(SIGINT, &old_int, nullptr);
        sigaction(SIGTERM, &old_term, nullptr);
        return 128 + stop_signal;
    }
    sigaction(SIGINT, &old_int, nullptr);
    sigaction(SIGTERM, &old_term, nullptr);
    fs::remove_all(work, ec);
    for (const std::string& f : failures) std::cout << "GRADER ERROR " << f << "\n";
    if (!failures.empty())
        std::cout << failures.size() << " submission(s) have no grade because the grader failed, not the student; "
                  << "fix the cause and run the same command again (only they are graded then)\n";
    const int collected = o.shards == 1 ? collect_roster(out, false, true) : 0;
    return failures.empty() ? collected : 1;
}

int collect_roster(const fs::path& out, bool quiet, bool locked) {
    if (!locked && fs::exists(out / ".work") && !lock(out / ".work" / "roster.lock", true))
        throw grader_error("a roster (or an array task) is still grading into " + out.string() +
                           ": collect when it has ended");
    const json roster = json::parse(read_regular_file(out / "roster.json", 1 << 20), nullptr, false);
    if (!roster.is_object())
        throw grader_error(out.string() + " holds no roster (no roster.json): give the --out folder of a roster");
    std::vector<roster_record> records = read_records(out);
    // The folder's submissions decide who is in the CSV: a student without a record is
    // "not graded"; a record whose submission has gone is left out, and said so.
    std::vector<std::string> missing;
    const fs::path dir = roster.value("submissions", std::string());
    std::error_code ec;
    if (!dir.empty() && fs::is_directory(dir, ec)) {
        std::vector<std::string> skipped;
        std::set<std::string> names;
        for (const roster_entry& e : list_submissions(dir, skipped, out)) names.insert(e.name);
        for (const roster_record& r : records)
            if (!names.count(r.student) && !quiet)
                std::cout << "left out: " << r.student << " has a grade, but " << dir.string()
                          << " no longer holds that submission\n";
        std::erase_if(records, [&](const roster_record& r) { return !names.count(r.student); });
        for (const std::string& n : names)
            if (std::none_of(records.begin(), records.end(), [&](const roster_record& r) { return r.student == n; }))
                missing.push_back(n);
    }
    // Grades no record names (replaced by a newer one, or never finished) go.
    std::set<std::string> kept;
    for (const roster_record& r : records)
        if (!r.grade.empty()) kept.insert(fs::path(r.grade).filename().string());
    for (const auto& e : fs::directory_iterator(out / "grades", ec))
        if (!kept.count(e.path().filename().string())) fs::remove_all(e.path(), ec);

    replace_file(out / "roster.csv", roster_csv(records, missing));
    const std::string board = leaderboard_csv(records);
    if (!board.empty()) replace_file(out / "leaderboard.csv", board);
    const auto errors = std::count_if(records.begin(), records.end(), [](const auto& r) { return r.status != "graded"; });
    if (!quiet) {
        std::cout << "summary: " << (out / "roster.csv").string() << " (" << records.size() - static_cast<std::size_t>(errors)
                  << " graded";
        if (errors) std::cout << ", " << errors << " grader error(s)";
        if (!missing.empty()) std::cout << ", " << missing.size() << " not graded yet";
        std::cout << ")\n";
        if (!board.empty()) std::cout << "leaderboard: " << (out / "leaderboard.csv").string() << "\n";
    }
    return errors == 0 && missing.empty() ? 0 : 1;
}

}  // namespace vl::grader
