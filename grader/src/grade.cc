#include "grade.hh"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <ctime>
#include <exception>
#include <map>
#include <mutex>
#include <set>
#include <thread>

#include "build_submission.hh"
#include "catch_runner.hh"
#include "reference_side.hh"
#include "rubric.hh"
#include "sandbox.hh"
#include "scenes.hh"
#include "submission.hh"
#include "sweeps.hh"

namespace vl::grader {

namespace fs = std::filesystem;

namespace {

/// Calls `each(items[k])` for every k from `first`, `jobs` at a time (each item on one
/// thread), and returns when all are done. The first exception one throws (a grader
/// failure) stops the others from starting more and is rethrown here.
template <class item, class work>
void run_side_by_side(std::vector<item>& items, std::size_t first, int jobs, const work& each) {
    std::atomic<std::size_t> next = first;
    std::atomic<bool> failed = false;
    std::exception_ptr failure;
    std::mutex failure_mutex;
    auto worker = [&] {
        for (std::size_t k; !failed && (k = next++) < items.size();) {
            try {
                each(items[k]);
            } catch (...) {
                const std::lock_guard<std::mutex> lock(failure_mutex);
                if (!failure) failure = std::current_exception();
                failed = true;
            }
        }
    };
    {
        std::vector<std::jthread> workers;
        for (int t = 1; t < std::max(jobs, 1); ++t) workers.emplace_back(worker);
        worker();
    }
    if (failure) std::rethrow_exception(failure);
}

/// The margins a passed test reported (grading::margin(): "vl-margin TEXT" warnings),
/// one per line.
std::string margins_of(const std::vector<std::string>& warnings) {
    std::string out;
    for (const std::string& w : warnings)
        if (w.starts_with("vl-margin ")) out += (out.empty() ? "" : "\n") + w.substr(10, 600);
    return out;
}

std::string now_utc() {
    const std::time_t t = std::time(nullptr);
    char buf[32];
    std::strftime(buf, sizeof buf, "%Y-%m-%d %H:%M UTC", std::gmtime(&t));
    return buf;
}

/// Shares `points` among items in proportion to `weights`, in thousandths of a point
/// (largest remainders first), so the shares add up to exactly the points.
std::vector<long long> shares(double points, const std::vector<double>& weights) {
    std::vector<long long> out(weights.size(), 0);
    double sum = 0;
    for (const double w : weights) sum += w;
    if (weights.empty() || sum <= 0) return out;
    const long long total = std::llround(points * 1000);
    long long given = 0;
    std::vector<std::pair<double, std::size_t>> remainders;
    for (std::size_t k = 0; k < weights.size(); ++k) {
        const double exact = static_cast<double>(total) * weights[k] / sum;
        out[k] = static_cast<long long>(std::floor(exact));
        given += out[k];
        remainders.push_back({exact - static_cast<double>(out[k]), k});
    }
    std::stable_sort(remainders.begin(), remainders.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
    for (std::size_t k = 0; given < total && k < remainders.size(); ++k, ++given) out[remainders[k].second] += 1;
    return out;
}

void add_up(graded_submission& g, const rubric& r) {
    std::map<std::string, category_total> totals;
    std::map<std::string, long long> score_units, max_units;
    long long all_score = 0, all_max = 0;
    for (const rubric_category& c : r.categories) totals[c.name] = {c.name, c.title, 0, 0, 0, 0};
    for (graded_item& i : g.items) {
        if (i.what == graded_item::kind::build) continue;
        const long long earned = i.passed() ? i.max_units : 0;
        i.max_score = static_cast<double>(i.max_units) / 1000;
        i.score = static_cast<double>(earned) / 1000;
        category_total& t = totals[i.category];
        score_units[i.category] += earned;
        max_units[i.category] += i.max_units;
        t.items += 1;
        t.passed += i.passed();
        all_score += earned;
        all_max += i.max_units;
    }
    for (const rubric_category& c : r.categories) {
        category_total t = totals[c.name];
        t.score = static_cast<double>(score_units[c.name]) / 1000;
        t.max_score = static_cast<double>(max_units[c.name]) / 1000;
        g.categories.push_back(t);
    }
    g.score = static_cast<double>(all_score) / 1000;
    g.max_score = static_cast<double>(all_max) / 1000;
}

/// A file name for a test's chart: its letters and digits, the rest as '-'.
std::string chart_stem(const std::string& test) {
    std::string out;
    for (const char c : test) {
        const bool keep = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9');
        if (keep) out += c;
        else if (!out.empty() && out.back() != '-') out += '-';
    }
    while (!out.empty() && out.back() == '-') out.pop_back();
    return out.substr(0, 80);
}

/// The rubric entry an item was made from, found by `matches`. Items are made from the
/// rubric, so it is always there; a miss is the grader's own fault, said as such.
template <class Entry, class Match>
const Entry& rubric_entry(const std::vector<Entry>& entries, Match matches, const std::string& what) {
    const auto it = std::find_if(entries.begin(), entries.end(), matches);
    if (it == entries.end()) throw grader_error("the rubric lost its " + what + " while grading");
    return *it;
}

}  // namespace

graded_submission grade(const installation& in, const stage_info& stage, const fs::path& submission,
                        const grade_options& options) {
    const auto start = std::chrono::steady_clock::now();
    graded_submission g;
    g.assignment = stage.name;
    g.submission = submission.filename().string();
    g.started_at = now_utc();
    const sandbox_capabilities caps = probe_sandbox(in.sanitized, options.weaker_sandbox);
    g.sandbox = caps.summary();
    if (!options.policy) g.sandbox += "; the source and symbol policy was OFF (a sandbox test)";

    rubric r = load_rubric(in.hidden_dir(stage) / "rubric.toml", in.assignment_dir(stage) / "scenes", in.sanitized);
    if (options.budget_seconds > 0) r.grade_budget_seconds = options.budget_seconds;
    r.test_limits.wall_seconds *= options.limits_scale;
    r.render_limits.wall_seconds *= options.limits_scale;
    g.title = r.title;
    const fs::path work = options.out / "work", renders = options.out / "renders", charts = options.out / "charts";
    std::error_code ec;
    for (const fs::path& old : {work, renders, charts}) {
        fs::remove_all(old, ec);
        if (ec) throw grader_error("cannot clear " + old.string() + ": " + ec.message());
        fs::create_directories(old, ec);
        if (ec) throw grader_error("cannot make " + old.string() + ": " + ec.message());
    }
    auto left = [&] {
        return r.grade_budget_seconds - std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };

    // The expected tests come from the trusted build, never from the submission's; they,
    // the tests the stubs pass and the reference's sweeps and charts are measured before
    // the submission is looked at (once per build: reference_side.hh).
    reference_side ref = reference_side_of(in, stage, r, work, caps);
    const std::vector<test_case_info>& tests = ref.tests;
    const std::set<std::string>& kit_passes = ref.kit_passes;
    check_rubric(r, tests);
    std::map<std::string, measured_points>& reference = ref.points;
    for (const rubric_sweep& s : r.sweeps) {
        const sweep_verdict v = judge_sweep(s, reference[s.test].sweep, reference[s.test].sweep);
        if (!v.passed)
            throw grader_error(r.file.string() + ": the reference is not stable where [[sweep]] '" + s.test +
                               "' says a correct method is: " + v.message);
    }

    // The items, in rubric order, all "not run" until they run.
    graded_item build;
    build.what = graded_item::kind::build;
    build.name = "builds";
    build.category = "build";
    build.visibility = "visible";
    build.result = item_result::failed;
    g.items.push_back(build);
    for (const rubric_category& c : r.categories) {
        std::vector<const test_case_info*> mine;
        for (const test_case_info& t : tests)
            if (r.category_of(t) == &c) mine.push_back(&t);
        std::vector<double> weights;
        // A test the untouched stubs pass checks what the kit supplies: it weighs nothing.
        for (const test_case_info* t : mine) weights.push_back(kit_passes.contains(t->name) ? 0 : c.weight_of(*t));
        if (c.points > 0 && !mine.empty() && std::all_of(weights.begin(), weights.end(), [](double w) { return w == 0; }))
            throw grader_error(r.file.string() + ": every test of category '" + c.name +
                               "' weighs 0 or passes with the untouched stubs: its points cannot be earned");
        const std::vector<long long> share = shares(c.points, weights);
        for (std::size_t k = 0; k < mine.size(); ++k) {
            graded_item i;
            i.name = mine[k]->name;
            i.category = c.name;
            i.visibility = c.visibility;
            i.tags = mine[k]->tags;
            // A public test (the student has it in tests/) says so, and shows its message;
            // a hidden one shows it when its category says (after publication by default).
            if (is_public_test_file(mine[k]->file)) i.tags.push_back("public");
            else i.details_visibility = c.details;
            i.max_units = share[k];
            i.test = *mine[k];
            i.kit_passes = kit_passes.contains(mine[k]->name);
            g.items.push_back(i);
        }
        for (const rubric_sweep& s : r.sweeps) {
            if (s.category != c.name) continue;
            graded_item i;
            i.what = graded_item::kind::sweep;
            i.name = s.title.starts_with("sweep") ? s.title : "sweep: " + s.title;
            i.category = c.name;
            i.visibility = s.visibility;
            i.test = named_test(tests, s.test);
            i.tags = i.test.tags;
            i.max_units = std::llround(s.points * 1000);
            i.reference_sweep = reference[s.test].sweep;
            g.items.push_back(i);
        }
        for (const rubric_scene& s : r.scenes) {
            if (s.category != c.name) continue;
            graded_item i;
            i.what = graded_item::kind::scene;
            i.name = (s.is_public ? "public scene: " : "scene: ") + s.title;
            i.category = c.name;
            i.visibility = s.visibility;
            i.tags = {"scene", s.id};
            i.max_units = std::llround(s.points * 1000);
            i.reference_image = in.reference_renders / stage.name / (s.id + ".png");
            if (!fs::exists(i.reference_image))
                throw grader_error(i.reference_image.string() + " is missing: rebuild with tools/setup");
            g.items.push_back(i);
        }
    }

    try {
        const prepared_submission sub = prepare_submission(submission, stage, in, work / "submission", caps, left());
        g.origin = sub.origin;
        g.notes = sub.notes;
        if (!sub.kit_stages.empty()) {
            std::string list;
            for (const auto& s : sub.kit_stages) list += " " + s;
            g.notes.push_back("the kit also holds your code for" + list +
                              "; graded here with the reference for every other stage");
        }
        seed_compile_cache(in, stage, work / "seed", caps);
        std::vector<std::vector<std::string>> scene_pieces;
        for (const rubric_scene& s : r.scenes) scene_pieces.push_back(s.student_pieces);
        const build_outcome b =
            build_submission(sub, stage, in, work / "build", caps, {options.policy, left(), scene_pieces});
        g.built = b.ok;
        g.items[0].seconds = b.seconds;
        g.items[0].result = b.ok ? item_result::passed : b.refused ? item_result::refused : item_result::failed;
        g.items[0].message = b.ok ? "" : b.errors;
        if (b.ok) {
            // Each item is one run (or a judge and a subject) of its own, so items run side
            // by side, options.item_jobs at a time; each writes only its own item.
            auto grade_item = [&](graded_item& i) {
                if (left() < 1) {
                    i.message = "not run: the time budget of this grade (" +
                                std::to_string(static_cast<int>(r.grade_budget_seconds)) + " s) was spent";
                    return;
                }
                if (i.what == graded_item::kind::test) {
                    run_limits limits = r.test_limits;
                    limits.wall_seconds = std::min(limits.wall_seconds, left());
                    const test_outcome o = run_graded_test(b.tests, i.test, limits, caps);
                    i.result = o.result;
                    i.message = o.message;
                    // A passed budget says by how much (grading::margin(), from the judge).
                    if (o.result == item_result::passed) i.message = margins_of(o.warnings);
                    if (i.kit_passes && i.message.empty())
                        i.message = "the untouched stubs pass this test too (it checks what the kit supplies), "
                                    "so it is worth no points";
                    i.seconds = o.seconds;
                } else if (i.what == graded_item::kind::sweep) {
                    const rubric_sweep& s = rubric_entry(
                        r.sweeps, [&](const rubric_sweep& x) { return x.test == i.test.name; }, "sweep " + i.test.name);
                    run_limits limits = r.test_limits;
                    limits.wall_seconds = std::min(limits.wall_seconds, left());
                    const test_outcome o = run_graded_test(b.tests, i.test, limits, caps);
                    i.seconds = o.seconds;
                    i.result = o.result;
                    i.message = o.message;
                    if (o.result == item_result::passed) {
                        const measured_points m = read_points(o.warnings);
                        i.sweep = m.sweep;
                        const sweep_verdict v = m.problem.empty() ? judge_sweep(s, m.sweep, i.reference_sweep)
                                                                  : sweep_verdict{false, "the sweep's report: " + m.problem};
                        i.result = v.passed ? item_result::passed : item_result::failed;
                        i.message = v.message;
                    }
                } else {
                    const rubric_scene& s = rubric_entry(
                        r.scenes, [&](const rubric_scene& x) { return x.id == i.tags[1]; }, "scene " + i.tags[1]);
                    run_limits limits = r.render_limits;
                    limits.wall_seconds = std::min(limits.wall_seconds, left());
                    const render_program& program = b.renders.at(b.render_of.at(static_cast<std::size_t>(&s - r.scenes.data())));
                    const scene_outcome o = render_and_compare(program, s, i.reference_image, renders, limits, caps);
                    i.result = o.matches ? item_result::passed : o.rendered ? item_result::failed : item_result::crashed;
                    i.message = o.message;
                    i.seconds = o.seconds;
                    i.image = o.image;
                    i.flip_image = o.flip_map;
                    i.highlight_image = o.highlight;
                    if (!o.flip_map.empty()) i.flip_mean = o.flip_mean;
                }
            };
            run_side_by_side(g.items, 1, options.item_jobs, grade_item);
        }
        if (b.ok)
            for (const rubric_chart& c : r.charts) {
                graded_chart gc;
                gc.title = c.title;
                gc.test = c.test;
                gc.reference = reference[c.test].chart;
                run_limits limits = r.test_limits;
                limits.wall_seconds = std::min(limits.wall_seconds, left());
                if (limits.wall_seconds < 1 || b.tests.empty()) {
                    gc.message = "not measured: the time budget of this grade was spent";
                } else {
                    const test_outcome o = run_graded_test(b.tests, named_test(tests, c.test), limits, caps);
                    const measured_points m = read_points(o.warnings);
                    if (o.result != item_result::passed)
                        gc.message = std::string("your code's curve is missing: the measurement ") + to_string(o.result) +
                                     (o.message.empty() ? "" : ": " + o.message);
                    else if (!m.problem.empty())
                        gc.message = "your code's curve is missing: " + m.problem;
                    else
                        gc.mine = m.chart;
                }
                g.charts.push_back(gc);
            }
    } catch (const submission_error& e) {
        g.items[0].message = e.what();
    }
    // Charts: the submission's points over the reference's, for every sweep and chart.
    fs::create_directories(charts, ec);
    const std::string whose = g.built ? "this submission" : "";
    for (graded_item& i : g.items) {
        if (i.what != graded_item::kind::sweep) continue;
        const rubric_sweep& s =
            rubric_entry(r.sweeps, [&](const rubric_sweep& x) { return x.test == i.test.name; }, "sweep " + i.test.name);
        const vl::chart_files f = draw_chart(sweep_chart(s, i.sweep, i.reference_sweep, i.sweep.empty() ? "" : whose),
                                             charts / chart_stem(s.test));
        i.chart_svg = f.svg;
        i.chart_png = f.png;
    }
    if (g.charts.empty())
        for (const rubric_chart& c : r.charts) g.charts.push_back({c.title, c.test, "", {}, reference[c.test].chart, {}, {}, {}});
    for (graded_chart& gc : g.charts) {
        const rubric_chart& c =
            rubric_entry(r.charts, [&](const rubric_chart& x) { return x.test == gc.test; }, "chart " + gc.test);
        const vl::chart_files f =
            draw_chart(measured_chart(c, gc.mine, gc.reference, gc.mine.empty() ? "" : whose), charts / chart_stem(c.test));
        gc.svg = f.svg;
        gc.png = f.png;
        gc.tsv = f.tsv;
        if (!f.problem.empty() && gc.message.empty()) gc.message = f.problem;
    }
    if (!g.built)
        for (std::size_t k = 1; k < g.items.size(); ++k)
            g.items[k].message = g.items[0].result == item_result::refused ? "not run: the code was refused (see \"builds\")"
                                                                : "the submission did not build (see \"builds\")";
    add_up(g, r);
    // The leaderboard: a chart's point, where the category it measures has full marks.
    for (const rubric_leaderboard& l : r.leaderboard) {
        const auto cat = std::find_if(g.categories.begin(), g.categories.end(),
                                      [&](const category_total& c) { return c.name == l.category; });
        const auto chart = std::find_if(g.charts.begin(), g.charts.end(), [&](const graded_chart& c) { return c.test == l.chart; });
        if (cat == g.categories.end() || cat->score < cat->max_score - 1e-9 || chart == g.charts.end()) continue;
        for (const chart_point& p : chart->mine)
            if (p.series == l.series && std::abs(p.x - l.x) <= 1e-9 * std::max(1.0, std::abs(l.x))) {
                g.leaderboard.push_back({l.name, l.order, p.y});
                break;
            }
    }
    if (!options.keep_work) fs::remove_all(work, ec);
    g.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return g;
}

}  // namespace vl::grader
