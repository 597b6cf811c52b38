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

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <initializer_list>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "01-tuples/tests/test_support.hh"
#include "vl/error.hh"
#include "vl/camera.hh"
#include "vl/ray.hh"
#include "vl/rt_base_objects.hh"
#include "vl/tuples_based.hh"

namespace vl::grading {

// Numbers, tuples, rays and matrices print as in the public tests' messages: `x` in the
// shortest form that reads back as exactly `x` (so tolerances such as 1e-12 are never
// printed as 0.0, and two different numbers never print alike), "(x, y, z)", "the ray
// from (..) towards (..)", "[a b c d; ...]".
using test01::num;
using test01::show;

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

/// What a budget test measured against its limit, in the student's words ("12.3 of the 30
/// primitive tests per ray allowed"): the report shows it beside a test that passed, so a
/// student sees the margin as well as the verdict (a failure says it in its message).
inline void margin(const std::string& text) {
    WARN("vl-margin " << text);
    SUCCEED();
}
/// `x` to three significant digits, for a margin (a measure, not a value to compare).
inline std::string about(double x) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3g", x);
    return buf;
}

/// \name Asking many objects at once
/// In the grader the student's objects live in another process (grader/README.md, "Who
/// holds what"), and each call crosses to it. A test that asks every object of a mesh for
/// each of thousands of rays asks them all at once with intersect_all, which the judge
/// serves with a few crossings; in one process it is the plain loop.
///@{
/// Fills `out[k * objects.size() + j]` with `objects[j]->intersect(rays[k])`, as one
/// batch; false when it cannot (an object that is no stand-in), and then the caller asks
/// them one by one.
using intersect_batch = bool (*)(std::span<const rtab_component* const> objects, std::span<const ray> rays,
                                 std::span<intersection> out);
/// The judge's way of asking a batch (set when the judge starts); none in one process.
inline intersect_batch& batch_of_intersections() {
    static intersect_batch batch = nullptr;
    return batch;
}
/// Every object's intersection with every ray: element `k * objects.size() + j` is what
/// `objects[j]->intersect(rays[k])` returns, counted as those calls are counted.
inline std::vector<intersection> intersect_all(std::span<const rtab_component* const> objects,
                                               std::span<const ray> rays) {
    std::vector<intersection> out(objects.size() * rays.size());
    if (const intersect_batch batch = batch_of_intersections(); batch != nullptr && batch(objects, rays, out))
        return out;
    for (std::size_t k = 0; k < rays.size(); ++k)
        for (std::size_t j = 0; j < objects.size(); ++j) out[k * objects.size() + j] = objects[j]->intersect(rays[k]);
    return out;
}
///@}

/// \name Many seeds of one sample pattern at once
/// As intersect_all, for a test that asks a pattern for thousands of seeds.
///@{
/// Fills `out[k * fill.size() + i]` with offset i of `pattern` for `seeds[k]`, each run
/// starting from the values of `fill`; false when it cannot (the pattern is no stand-in).
using offsets_batch = bool (*)(const sampler& pattern, std::span<const sample_offset> fill,
                               std::span<const std::uint64_t> seeds, std::span<sample_offset> out);
/// The judge's way of asking a batch (set when the judge starts); none in one process.
inline offsets_batch& batch_of_offsets() {
    static offsets_batch batch = nullptr;
    return batch;
}
/// What `pattern.offsets(span, seed)` leaves in a span of `fill.size()` offsets that held
/// `fill`, for each seed of `seeds`, in order.
inline std::vector<std::vector<sample_offset>> offsets_for_seeds(const sampler& pattern,
                                                                 std::span<const sample_offset> fill,
                                                                 std::span<const std::uint64_t> seeds) {
    const std::size_t n = fill.size();
    std::vector<sample_offset> flat(n * seeds.size());
    if (const offsets_batch batch = batch_of_offsets(); batch == nullptr || !batch(pattern, fill, seeds, flat))
        for (std::size_t k = 0; k < seeds.size(); ++k) {
            const std::span<sample_offset> one(flat.data() + k * n, n);
            std::copy(fill.begin(), fill.end(), one.begin());
            pattern.offsets(one, seeds[k]);
        }
    std::vector<std::vector<sample_offset>> out;
    out.reserve(seeds.size());
    for (std::size_t k = 0; k < seeds.size(); ++k) out.emplace_back(flat.begin() + k * n, flat.begin() + (k + 1) * n);
    return out;
}
///@}

/// \brief Counts the inputs of a loop and keeps the first three failures in words;
/// report() fails the test once, with those three and the count, so a sweep of a thousand
/// rays that all go wrong reads as four lines, not a thousand.
class tally {
public:
    explicit tally(std::string what) : what_(std::move(what)) {}

    /// Records one input; when `ok` is false, `describe()` says what went wrong (called
    /// only for the first three failures).
    template <class Describe>
    bool check(bool ok, Describe&& describe) {
        ++tried_;
        if (!ok) {
            if (failed_ < 3) examples_.push_back(describe());
            ++failed_;
        }
        return ok;
    }
    int failed() const { return failed_; }
    int tried() const { return tried_; }
    /// The first failure in words, or "".
    std::string first_failure() const { return examples_.empty() ? std::string() : examples_.front(); }
    /// Reports the count as one point of a sweep (the test passes whatever it is).
    void report_sweep_point(double x) const { sweep_point(x, tried_, failed_, first_failure()); }

    /// Passes when at most `allowed` inputs went wrong; otherwise one failure per example
    /// kept (each read on its own), then the count.
    void report(int allowed = 0) const {
        if (failed_ <= allowed) {
            SUCCEED();
            return;
        }
        for (const std::string& e : examples_) FAIL_CHECK(e);
        FAIL_CHECK(what_ << ": " << failed_ << " of " << tried_ << " went wrong"
                         << (allowed > 0 ? " (at most " + std::to_string(allowed) + " may)" : std::string())
                         << (failed_ > 3 ? " (the first 3 are above)" : " (above)"));
    }
    /// What the loop checks, as the report names it.
    const std::string& what() const { return what_; }

private:
    std::string what_;
    std::vector<std::string> examples_;
    int failed_ = 0, tried_ = 0;
};

/// The message of the vl::file_error that `read()` throws, or what happened instead (in
/// words, for the report: another exception, or no error at all).
template <class Read>
std::string file_error_of(Read&& read) {
    try {
        read();
    } catch (const file_error& e) {
        return e.what();
    } catch (const std::exception& e) {
        return std::string("(not a vl::file_error: ") + e.what() + ")";
    }
    return "(no error: the object was read)";
}

/// A scene-file block a reader must refuse, and the place its vl::file_error must name
/// ("hidden.ray_trace:3:10").
struct refused_block {
    const char* text;
    const char* where;
};

/// Checks, for each of `blocks`, that `read_error(text)` (the message of what reading
/// the text threw) names the block's place.
template <class ReadError>
void check_refused(tally& t, ReadError&& read_error, std::initializer_list<refused_block> blocks) {
    for (const refused_block& c : blocks) {
        const std::string message = read_error(c.text);
        t.check(message.find(c.where) != std::string::npos, [&] {
            return std::string("reading \"") + c.text + "\" should fail with a vl::file_error at " + c.where + "; it gave: " +
                   message;
        });
    }
}

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
