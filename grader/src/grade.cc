#include "grade.hh"

#include <algorithm>
#include <chrono>
#include <ctime>
#include <map>

#include "build_submission.hh"
#include "catch_runner.hh"
#include "rubric.hh"
#include "sandbox.hh"
#include "scenes.hh"
#include "submission.hh"

namespace vl::grader {

namespace fs = std::filesystem;

namespace {

std::string now_utc() {
    const std::time_t t = std::time(nullptr);
    char buf[32];
    std::strftime(buf, sizeof buf, "%Y-%m-%d %H:%M UTC", std::gmtime(&t));
    return buf;
}

/// A folder name for test number k: short, and the same on every run.
std::string work_name(const char* prefix, std::size_t k) { return prefix + std::to_string(k + 1); }

void add_up(graded_submission& g, const rubric& r) {
    std::map<std::string, category_total> totals;
    for (const rubric_category& c : r.categories) totals[c.name] = {c.name, c.title, 0, 0, 0, 0};
    for (const graded_item& i : g.items) {
        if (i.what == graded_item::kind::build) continue;
        category_total& t = totals[i.category];
        t.score += i.score;
        t.max_score += i.max_score;
        t.items += 1;
        t.passed += i.passed();
        g.score += i.score;
        g.max_score += i.max_score;
    }
    for (const rubric_category& c : r.categories) g.categories.push_back(totals[c.name]);
}

}  // namespace

graded_submission grade(const installation& in, const stage_info& stage, const fs::path& submission,
                        const grade_options& options) {
    const auto start = std::chrono::steady_clock::now();
    graded_submission g;
    g.assignment = stage.name;
    g.submission = submission.string();
    g.started_at = now_utc();
    const sandbox_capabilities caps = probe_sandbox(in.sanitized);
    g.sandbox = caps.summary();

    const rubric r = load_rubric(in.hidden_dir(stage) / "rubric.toml", in.sanitized);
    g.title = r.title;
    const fs::path work = options.out / "work";
    fs::remove_all(work);
    fs::create_directories(work);

    // The expected tests come from the trusted build, never from the submission's.
    std::vector<test_case_info> tests;
    if (!stage.trusted_tests.empty()) tests = list_trusted_tests(stage.trusted_tests, work / "trusted", caps);
    check_rubric(r, tests);

    // The items, in rubric order, all "not run" until they run.
    graded_item build;
    build.what = graded_item::kind::build;
    build.name = "builds";
    build.category = "build";
    build.visibility = "visible";
    build.result = "failed";
    g.items.push_back(build);
    for (const rubric_category& c : r.categories) {
        std::vector<const test_case_info*> mine;
        for (const test_case_info& t : tests)
            if (r.category_of(t) == &c) mine.push_back(&t);
        for (const test_case_info* t : mine) {
            graded_item i;
            i.name = t->name;
            i.category = c.name;
            i.visibility = c.visibility;
            i.tags = t->tags;
            i.max_score = c.points / static_cast<double>(mine.size());
            g.items.push_back(i);
        }
        for (const rubric_scene& s : r.scenes) {
            if (s.category != c.name) continue;
            graded_item i;
            i.what = graded_item::kind::scene;
            i.name = "scene: " + s.title;
            i.category = c.name;
            i.visibility = s.visibility;
            i.tags = {"scene", s.file.filename().string()};
            i.max_score = s.points;
            i.reference_image = in.reference_renders / stage.name / (s.file.stem().string() + ".png");
            if (!fs::exists(i.reference_image))
                throw grader_error(i.reference_image.string() + " is missing: rebuild with tools/setup");
            g.items.push_back(i);
        }
    }

    try {
        const prepared_submission sub = prepare_submission(submission, stage, in, work / "scratch", caps);
        g.origin = sub.origin;
        g.notes = sub.notes;
        if (!sub.kit_stages.empty()) {
            std::string list;
            for (const auto& s : sub.kit_stages) list += " " + s;
            g.notes.push_back("the kit also holds your code for" + list +
                              "; graded here with the reference for every other stage");
        }
        const build_outcome b = build_submission(sub, stage, in, work / "build", caps);
        g.built = b.ok;
        g.items[0].seconds = b.seconds;
        g.items[0].result = b.ok ? "passed" : "failed";
        g.items[0].message = b.ok ? "" : b.errors;
        if (b.ok) {
            for (std::size_t k = 1; k < g.items.size(); ++k) {
                graded_item& i = g.items[k];
                if (i.what == graded_item::kind::test) {
                    const test_outcome o = b.tests_program.empty()
                                               ? test_outcome{test_outcome::status::failed, "no test program", 0}
                                               : run_test_case(b.tests_program, i.name, work / work_name("test", k),
                                                               r.test_limits, caps);
                    i.result = to_string(o.result);
                    i.message = o.message;
                    i.seconds = o.seconds;
                } else {
                    const rubric_scene& s = *std::find_if(r.scenes.begin(), r.scenes.end(), [&](const rubric_scene& x) {
                        return x.file.filename().string() == i.tags[1];
                    });
                    const scene_outcome o = render_and_compare(b.render_program, s, i.reference_image,
                                                               work / "renders", r.render_limits, caps);
                    i.result = o.matches ? "passed" : o.rendered ? "failed" : "crashed";
                    i.message = o.message;
                    i.seconds = o.seconds;
                    i.image = o.image;
                    i.difference_image = o.difference;
                }
                if (i.passed()) i.score = i.max_score;
            }
        }
    } catch (const submission_error& e) {
        g.items[0].message = e.what();
    }
    if (!g.built)
        for (std::size_t k = 1; k < g.items.size(); ++k)
            g.items[k].message = "the submission did not build (see \"builds\")";
    add_up(g, r);
    g.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return g;
}

}  // namespace vl::grader
