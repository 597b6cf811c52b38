#pragma once
/// \file
/// \brief Intersection counters: how much work a ray cost, independent of the machine.
///
/// Every call of rtab_component::intersect() and of the bounding-volume helpers counts
/// here. The counters are per thread (no locks, no shared cache lines on the hot path);
/// whoever owns the threads (the render driver) reads each thread's counts and sums them.
/// They replace the thesis's `_INTRSCT_PRFM` counters, which had to be compiled in and
/// cleared by hand; these are always on and never overflow in practice (64 bits), and a
/// count never goes down (see count_bounding_volume_tests()).

#include <cstdint>
#include <iosfwd>

namespace vl {

/// \brief What one thread has counted since it started (or since the last snapshot).
struct intersection_counts {
    std::uint64_t primitive_tests = 0;       ///< intersect() calls on leaves
    std::uint64_t composite_tests = 0;       ///< intersect() calls on composites
    std::uint64_t bounding_volume_tests = 0; ///< box and sphere bound tests (vl/bounds.hh)
    std::uint64_t misses = 0;                ///< intersect() calls that hit nothing at all
    std::uint64_t composite_only = 0;        ///< composite hit, but none of its primitives

    /// All intersect() calls: the thesis's `count()`.
    std::uint64_t count() const { return primitive_tests + composite_tests; }
    /// Calls that returned no object: the thesis's `NULL_count()`.
    std::uint64_t null_count() const { return misses; }
    /// Calls that returned t == 0 (no primitive hit): the thesis's `t0_count()`.
    std::uint64_t t0_count() const { return misses + composite_only; }
    /// Everything a ray cost: intersect() calls plus bounding-volume tests.
    std::uint64_t total_tests() const { return count() + bounding_volume_tests; }

    /// \name Arithmetic
    ///@{

    /// Counter by counter: add up threads with `+`, get the cost of a piece of work
    /// as the difference of two snapshots with `-`.
    intersection_counts& operator+=(const intersection_counts& o);
    intersection_counts& operator-=(const intersection_counts& o);
    friend intersection_counts operator+(intersection_counts a, const intersection_counts& b) { return a += b; }
    friend intersection_counts operator-(intersection_counts a, const intersection_counts& b) { return a -= b; }
    ///@}
    /// Equal in every counter (`!=` is generated from it).
    friend bool operator==(const intersection_counts&, const intersection_counts&) = default;
};

namespace detail {
/// \brief The raw per-thread tallies behind vl::counts(): one increment per call.
///
/// intersect() adds 1 to a single cell chosen by what was called (leaf or composite) and
/// what it returned (hit, miss, composite-only), so the hot path pays one memory
/// increment; counts() turns the table into named totals.
struct tallies {
    std::uint64_t calls[2][3] = {};       ///< [is composite][outcome]
    std::uint64_t bounding_volume = 0;    ///< bounding-volume tests
};
enum outcome { hit_outcome = 0, miss_outcome = 1, composite_only_outcome = 2 };
// constinit: no dynamic initialiser, so every access is a plain TLS load (no wrapper call).
inline constinit thread_local tallies thread_tallies;
}  // namespace detail

/// This thread's counters. Snapshot before and after a piece of work and subtract to
/// get what that work cost: `auto before = counts(); ...; auto cost = counts() - before;`
inline intersection_counts counts() {
    const detail::tallies& t = detail::thread_tallies;
    intersection_counts c;
    c.primitive_tests = t.calls[0][0] + t.calls[0][1] + t.calls[0][2];
    c.composite_tests = t.calls[1][0] + t.calls[1][1] + t.calls[1][2];
    c.misses = t.calls[0][1] + t.calls[1][1];
    c.composite_only = t.calls[0][2] + t.calls[1][2];
    c.bounding_volume_tests = t.bounding_volume;
    return c;
}
namespace detail {
/// The most tests one call of count_bounding_volume_tests() may count: more than any ray,
/// or any render, makes (2^40).
inline constexpr std::uint64_t most_tests_per_count = std::uint64_t{1} << 40;
/// Throws vl::usage_error for count_bounding_volume_tests(n) (out of line, off the hot path).
[[noreturn]] void refuse_count(std::uint64_t n, std::uint64_t counted);
}  // namespace detail

/// Counts `n` bounding-volume tests in this thread's counters, for a composite that tests
/// its bounds with its own code instead of vl::hits_box or vl::hits_sphere (the reference
/// BVH's float boxes): each test must still be counted once. A count only grows: throws
/// vl::usage_error, counting nothing, when `n` is above 2^40 (a negative number passed as
/// unsigned, say) or when the thread's count would pass 2^64 and start again from 0.
inline void count_bounding_volume_tests(std::uint64_t n) {
    std::uint64_t& counted = detail::thread_tallies.bounding_volume;
    if (n > detail::most_tests_per_count || counted + n < counted) detail::refuse_count(n, counted);
    counted += n;
}

/// Sets this thread's counters to zero (the thesis's `clear_count()`).
inline void clear_counts() { detail::thread_tallies = {}; }

/// Writes the five counters, each after its name: `primitive tests 3, composite tests 1, ...`.
std::ostream& operator<<(std::ostream& s, const intersection_counts& c);

}  // namespace vl
