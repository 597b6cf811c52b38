#pragma once
/// \file
/// \brief An assignment's rubric (grader/hidden/NN-name/rubric.toml): categories with
/// points, which hidden tests and scenes earn them, limits, Gradescope visibility.
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "catch_runner.hh"
#include "sandbox.hh"

namespace vl::grader {

/// \brief A part of the grade, such as "Rays from inside".
struct rubric_category {
    std::string name, title;
    double points = 0;                ///< shared by its tests in proportion to their weights
    std::vector<std::string> tags;    ///< Catch2 tags (no brackets) that put a test here
    std::vector<std::string> tests;   ///< test names that put a test here
    std::map<std::string, double> weights;  ///< by tag (no brackets) or test name; others weigh 1
    std::string visibility;
    /// When a hidden test's message (what it asked, expected and got) is shown on
    /// Gradescope; until then the student sees its name, pass or fail and points.
    std::string details = "after_published";

    /// The weight of `t`: its name's, else the largest of its tags', else 1.
    double weight_of(const test_case_info& t) const;
};

/// \brief A hidden scene, rendered with the submission and compared with the reference.
struct rubric_scene {
    std::filesystem::path file;       ///< in grader/hidden/NN-name/scenes, or (public) assignments/NN-name/scenes
    bool is_public = false;           ///< one of the stage's public scenes
    std::string id;                   ///< the file's stem, "public-" first for a public scene: names its images
    /// The pieces rendered with the submission's code (`camera`, `sampler:NAME`,
    /// `tracer:NAME`, object type names); every other piece is the reference's. Empty:
    /// all of them are the submission's.
    std::vector<std::string> student_pieces;
    std::string title, category, visibility;
    double points = 0;
    /// The comparison that decides: "flip" (LDR-FLIP, vl/flip.hh: the mean error and the
    /// share of pixels whose error is over flip_pixel_level) or "mean_abs" (8-bit levels:
    /// the mean difference and the share of pixels with a channel over threshold_levels).
    /// Both are measured and shown either way.
    std::string metric = "mean_abs";
    int threshold_levels = 8;          ///< mean_abs: a pixel differs when a channel is more than this apart
    double max_mean_difference = 0.5;  ///< mean_abs: levels, over all samples
    double max_flip_mean = 0;          ///< flip: the largest mean FLIP error that passes (from calibration)
    /// flip: a pixel differs when its FLIP error is above this. 0.1 is about 6 levels of
    /// a mid gray; a difference of one level, as rounding makes, is 0.03.
    double flip_pixel_level = 0.1;
    double max_fraction_over = 0.005;  ///< both: of the pixels that differ
};

/// \brief A stability sweep: a hidden test tagged [sweep] moves one parameter to where
/// naive methods fail and reports how many trials failed at each value; the sweep passes
/// when no value in [stable_from, stable_through] fails more than max_failure_rate of its
/// trials. It adds its points to its category.
struct rubric_sweep {
    std::string test;                 ///< the hidden test's exact name
    std::string title, category, visibility, x_label;
    double points = 0;
    bool log_x = false;
    double stable_from = 0, stable_through = 0;  ///< where a correct method must not fail
    double max_failure_rate = 0;                 ///< of the trials at each value there
};

/// \brief A chart: a hidden test tagged [chart] measures curves (tests per ray against N)
/// that the report draws, the submission's over the reference's. Worth no points.
struct rubric_chart {
    std::string test, title, x_label, y_label;
    bool log_x = false, log_y = false;
};

/// \brief A value of the leaderboard (results.json's `leaderboard`, the roster's
/// leaderboard.csv): the submission's point of a [[chart]] at one series and x, such as
/// the BVH's tests per ray at N = 4096. It counts only when the submission has full marks
/// in `category`, so a fast wrong answer never leads.
struct rubric_leaderboard {
    std::string name;    ///< the column's name
    std::string chart;   ///< the [[chart]]'s test
    std::string series;  ///< one of the chart's series
    double x = 0;
    std::string order = "asc";  ///< "asc": smaller is better; "desc": larger is better
    std::string category;       ///< the [[category]] that must have full marks
};

/// \brief One value of a submission's leaderboard, as results.json's `leaderboard` has it.
struct leaderboard_value {
    std::string name, order;  ///< order: "asc" (smaller is better) or "desc"
    double value = 0;
};

/// \brief A whole rubric.
struct rubric {
    std::filesystem::path file;
    std::string assignment, title, visibility = "after_published";
    run_limits test_limits, render_limits;
    double total_points = 0;            ///< when > 0, what the categories and scenes must add up to
    double grade_budget_seconds = 600;  ///< the whole grade; items left when it is spent are not run
    std::vector<rubric_category> categories;
    std::vector<rubric_scene> scenes;
    std::vector<rubric_sweep> sweeps;
    std::vector<rubric_chart> charts;
    std::vector<rubric_leaderboard> leaderboard;

    /// The category of test `t`: the first whose tests or tags claim it, or nullptr. A
    /// sweep or chart test ([sweep], [chart]) is in no category: its [[sweep]] or
    /// [[chart]] says what it is worth.
    const rubric_category* category_of(const test_case_info& t) const;
};

/// Reads `file` (public scenes are in `public_scenes`); throws grader_error naming the
/// file, line and problem.
rubric load_rubric(const std::filesystem::path& file, const std::filesystem::path& public_scenes, bool sanitized);

/// True for a test tagged [sweep] or [chart], which a [[sweep]] or [[chart]] grades.
bool is_measurement(const test_case_info& t);

/// Checks the rubric against the hidden tests: every test has a category (or, for a sweep
/// or chart test, exactly one [[sweep]] or [[chart]]), every named test exists, every
/// category earns its points somewhere. Throws grader_error.
void check_rubric(const rubric& r, const std::vector<test_case_info>& tests);

}  // namespace vl::grader
