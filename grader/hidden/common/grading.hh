#pragma once
/// \file
/// \brief What every hidden test uses to say what went wrong, in the student's terms.
///
/// A failed hidden check is read by a student who has neither this file nor the test's
/// source. So a check never reports an expression (`CHECK_FALSE( !(...).hit() )  with
/// values: !true` means nothing to them); it reports what was asked, what was expected and
/// what came back, with every number at full precision:
///
///     the ray from (0, 0, 5) towards (0, 0, -1) should hit the sphere at t = 4 ± 1e-12;
///     yours returned t = 6
///
/// Use VL_EXPECT(condition, message) and VL_EXPECT_NEAR(what, got, want, tolerance); the
/// message is streamed (`"the ray " << show(r) << " should miss"`), and is evaluated only
/// when the check fails, so it may be expensive. In a loop, put the iteration's input in
/// the message itself, never in INFO, so a failure names the one input that failed.
/// Every check counts as an assertion (SUCCEED on success), so a test that checks nothing
/// cannot pass by accident; VL_REQUIRE stops the test, for a check the rest depends on.
///
/// The grader prints each failed check under the test's name; it removes this file's and
/// the hidden tests' file names and line numbers, which the student does not have.

#include "vl/catch.hh"

#include <charconv>
#include <cmath>
#include <string>

#include "vl/ray.hh"
#include "vl/tuples_based.hh"

namespace vl::grading {

/// `x` in the shortest form that reads back as exactly `x` (so tolerances such as 1e-12
/// are never printed as 0.0, and two different numbers never print alike).
inline std::string num(double x) {
    if (std::isnan(x)) return "NaN";
    if (std::isinf(x)) return x > 0 ? "infinity" : "-infinity";
    char buf[64];
    const auto r = std::to_chars(buf, buf + sizeof buf, x);
    return std::string(buf, r.ptr);
}

/// `(x, y, z)` of a point (homogenized) or a vector, each at full precision.
inline std::string show(const point& p) {
    const point h = p.w == 1 ? p : p.homogenized();
    return "(" + num(h.x) + ", " + num(h.y) + ", " + num(h.z) + ")";
}
inline std::string show(const vector& v) { return "(" + num(v.x) + ", " + num(v.y) + ", " + num(v.z) + ")"; }

/// The ray in words: "the ray from (..) towards (..)".
inline std::string show(const ray& r) { return "the ray from " + show(r.origin()) + " towards " + show(r.direction()); }

/// A matrix row by row: "[a b c d; e f g h; ...]".
inline std::string show(const matrix& m) {
    std::string s = "[";
    for (int r = 0; r < 4; ++r) {
        for (int c = 0; c < 4; ++c) s += num(m(r, c)) + (c < 3 ? " " : "");
        s += r < 3 ? "; " : "]";
    }
    return s;
}

/// True when `got` is within `tolerance` of `want` (never for NaN).
inline bool near(double got, double want, double tolerance) { return std::abs(got - want) <= tolerance; }


/// \name Sweeps and charts
/// A sweep test ([sweep] tag) moves one parameter to where naive methods break (a
/// sphere's distance over its radius, a matrix's condition number, ...) and reports, for
/// each value, how many of its trials went wrong; the rubric's [[sweep]] says over which
/// values a correct method must not fail, and is the graded item. A chart test ([chart])
/// reports measured points (tests per ray against N) that the report only draws.
/// Both report through Catch2 warnings, which the grader reads from the XML report; the
/// submission's points must be the same values, in the same order, as the reference's.
/// A sweep test checks nothing itself (it passes whatever it measures) and must be
/// deterministic: fixed seeds, fixed trial counts.
///@{
/// At parameter value `x`, `failures` of `trials` went wrong. `example` (optional) says
/// what one failure looked like, in the student's terms, for the report.
inline void sweep_point(double x, long trials, long failures, const std::string& example = "") {
    WARN("vl-sweep x=" << num(x) << " trials=" << trials << " failures=" << failures
                       << (example.empty() ? "" : " example=") << example);
    SUCCEED();
}
/// One measured point of the curve `series` (a word: letters, digits, '-', '_').
inline void chart_point(const std::string& series, double x, double y) {
    WARN("vl-chart series=" << series << " x=" << num(x) << " y=" << num(y));
    SUCCEED();
}
///@}

}  // namespace vl::grading

/// Checks `condition`; when it is false, the test fails with `message` (streamed) and goes on.
#define VL_EXPECT(condition, message)   \
    do {                                \
        if (condition) {                \
            SUCCEED();                  \
        } else {                        \
            FAIL_CHECK(message);        \
        }                               \
    } while (false)

/// As VL_EXPECT, but the test stops here when `condition` is false.
#define VL_REQUIRE(condition, message)  \
    do {                                \
        if (condition) {                \
            SUCCEED();                  \
        } else {                        \
            FAIL(message);              \
        }                               \
    } while (false)

/// Checks |got - want| <= tolerance; the message reads
/// "WHAT should be WANT ± TOLERANCE; yours is GOT". `what` is streamed.
#define VL_EXPECT_NEAR(what, got, want, tolerance)                                                     \
    do {                                                                                               \
        const double vl_got_ = (got), vl_want_ = (want), vl_tolerance_ = (tolerance);                  \
        VL_EXPECT(::vl::grading::near(vl_got_, vl_want_, vl_tolerance_),                               \
                  what << " should be " << ::vl::grading::num(vl_want_) << " ± "                       \
                       << ::vl::grading::num(vl_tolerance_) << "; yours is " << ::vl::grading::num(vl_got_)); \
    } while (false)
