#pragma once
/// \file
/// \brief Grading one submission of one assignment: the pipeline of grader/README.md,
/// from a submission to a graded_submission that results.json, report.html and the
/// terminal summary are written from.
#include <filesystem>
#include <string>
#include <vector>

#include "catch_runner.hh"
#include "install.hh"
#include "item_result.hh"
#include "rubric.hh"
#include "sweeps.hh"

namespace vl::grader {

/// \brief One line of the grade: the build, a hidden test, a hidden scene or a sweep.
struct graded_item {
    enum class kind { build, test, scene, sweep } what = kind::test;
    std::string name, category, visibility;
    /// A hidden test's: when its message is shown (rubric_category::details).
    std::string details_visibility;
    std::vector<std::string> tags;
    long long max_units = 0;         ///< the item's share of the points, in thousandths of a point
    double score = 0, max_score = 0; ///< points (max_units / 1000, or 0)
    item_result result = item_result::not_run;
    std::string message;
    double seconds = 0;
    /// Scenes only: the submission's render, the reference's, the FLIP error map and the
    /// highlighted difference.
    std::filesystem::path image, reference_image, flip_image, highlight_image;
    double flip_mean = -1;  ///< scenes only: the FLIP mean measured (-1: not measured)
    test_case_info test;  ///< tests and sweeps: as the trusted program lists it
    std::vector<sweep_point> sweep, reference_sweep;  ///< sweeps only: the submission's and the reference's points
    std::filesystem::path chart_svg, chart_png;       ///< sweeps only: the chart of both (when gnuplot drew it)
    bool kit_passes = false;  ///< tests only: the untouched stubs pass it, so it is worth 0
    bool passed() const { return result == item_result::passed; }
};

/// \brief A chart of the report ([[chart]] in the rubric): worth no points.
struct graded_chart {
    std::string title, test;
    std::string message;                          ///< why the submission's curve is missing, or ""
    std::vector<chart_point> mine, reference;
    std::filesystem::path svg, png, tsv;
};

/// \brief A category's total.
struct category_total {
    std::string name, title;
    double score = 0, max_score = 0;
    int passed = 0, items = 0;
};

/// \brief Everything known about one graded submission.
struct graded_submission {
    std::string assignment, title, submission, origin, sandbox, started_at;
    std::vector<std::string> notes;
    bool built = false;
    std::vector<graded_item> items;  ///< the build first, then by category
    std::vector<category_total> categories;
    std::vector<graded_chart> charts;
    std::vector<leaderboard_value> leaderboard;  ///< the rubric's [[leaderboard]] values this submission earned
    double score = 0, max_score = 0, seconds = 0;
};

/// \brief Options of `grade`.
struct grade_options {
    std::filesystem::path out;    ///< results.json, report.html, renders/ and (while grading) work/ go here
    bool weaker_sandbox = false;  ///< grade even where bubblewrap cannot run (the report says so)
    bool policy = true;           ///< false only to test the sandbox alone (calibration)
    bool keep_work = false;       ///< keep out/work/ (sources, objects, programs) for a look
    double budget_seconds = 0;    ///< the whole grade's time; 0: the rubric's grade_budget_seconds
    double limits_scale = 1;      ///< the rubric's test and render time limits, times this (calibrate --limits-scale)
    int item_jobs = 1;            ///< how many items (tests, scenes) run at once (--jobs; commands: default_item_jobs())
};

/// Grades `submission` for `stage`. Problems of the submission become failed items;
/// problems of the grader throw grader_error, and then nothing scores the student.
graded_submission grade(const installation& in, const stage_info& stage, const std::filesystem::path& submission,
                        const grade_options& options);

}  // namespace vl::grader
