#pragma once
/// \file
/// \brief Sweeps and charts: what a [sweep] or [chart] hidden test measured (read from the
/// Catch2 warnings of its report), whether a sweep stayed stable where the rubric says a
/// correct method must, and the charts that show the submission's points over the
/// reference's.
#include <string>
#include <vector>

#include "rubric.hh"
#include "vl/chart.hh"

namespace vl::grader {

/// \brief One value of a sweep: `failures` of `trials` went wrong at parameter `x`.
struct sweep_point {
    double x = 0;
    long long trials = 0, failures = 0;
    std::string example;  ///< what one failure looked like, or ""
    double rate() const { return trials > 0 ? static_cast<double>(failures) / static_cast<double>(trials) : 0; }
};

/// \brief One measured point of a chart's curve.
struct chart_point {
    std::string series;
    double x = 0, y = 0;
};

/// \brief The points of one run of a sweep or chart test.
struct measured_points {
    std::vector<sweep_point> sweep;
    std::vector<chart_point> chart;
    std::string problem;  ///< a point that could not be read, or ""
};

/// Reads the points from a test's Catch2 warnings (grader/hidden/common/grading.hh writes
/// them); other warnings are ignored.
measured_points read_points(const std::vector<std::string>& warnings);

/// \brief A sweep's verdict.
struct sweep_verdict {
    bool passed = false;
    std::string message;  ///< the first value where it failed, or the summary of a pass
};

/// Judges the submission's points against the rubric's stable range. They must be the
/// reference's values in the reference's order, with the same trial counts.
sweep_verdict judge_sweep(const rubric_sweep& s, const std::vector<sweep_point>& mine,
                          const std::vector<sweep_point>& reference);

/// The failure rate against the swept value: the reference as a line, the submission as
/// marks over it, the stable range shaded.
vl::chart sweep_chart(const rubric_sweep& s, const std::vector<sweep_point>& mine,
                      const std::vector<sweep_point>& reference, const std::string& whose);

/// A chart test's curves: each reference series as a line, the submission's as marks.
vl::chart measured_chart(const rubric_chart& c, const std::vector<chart_point>& mine,
                         const std::vector<chart_point>& reference, const std::string& whose);

}  // namespace vl::grader
