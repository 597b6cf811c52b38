// Hidden tests of stage 01's pixel sample patterns (grader only; students never see this
// file). Each TEST_CASE is one graded item; its tags name the rubric category. Random
// patterns are checked for the properties the contract states (ranges, cells, repeatability,
// uniformity, independence) over fixed seeds, with limits a sound generator never reaches:
// never for particular random values.
#include "vl/catch.hh"

#include <cmath>
#include <cstdint>
#include <exception>
#include <set>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "hidden_support.hh"

using namespace vl;
using namespace vl::stage01;
using namespace vl::stage01::hidden;

namespace {

const char* const patterns[] = {"center", "grid", "jittered", "random"};

/// A seed like the render driver's: a well-mixed 64-bit number (SplitMix64's finaliser).
std::uint64_t mixed_seed(std::uint64_t i) {
    std::uint64_t z = i + 0x9e3779b97f4a7c15ull;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

/// Seeds of both kinds: small numbers from 1 up and well-mixed ones. (The statistics use
/// well-mixed seeds only, as the render driver does: some sound generators, such as
/// minstd, start similar sequences from neighbouring small seeds.)
std::uint64_t seed_number(int i) {
    const auto k = static_cast<std::uint64_t>(i);
    return i % 2 ? k / 2 + 1 : mixed_seed(k);
}

/// `n` offsets of `pattern` for `seed`, each first set to -1 (not filled).
std::vector<sample_offset> draw(const sampler& pattern, std::size_t n, std::uint64_t seed) {
    std::vector<sample_offset> out(n, sample_offset{-1, -1});
    pattern.offsets(out, seed);
    return out;
}

/// draw() for each of `seeds`, asked all at once (vl::grading::offsets_for_seeds).
std::vector<std::vector<sample_offset>> draws(const sampler& pattern, std::size_t n, const std::vector<std::uint64_t>& seeds) {
    const std::vector<sample_offset> fill(n, sample_offset{-1, -1});
    return vl::grading::offsets_for_seeds(pattern, fill, seeds);
}

/// mixed_seed(0), ..., mixed_seed(count - 1).
std::vector<std::uint64_t> mixed_seeds(int count) {
    std::vector<std::uint64_t> seeds;
    for (int j = 0; j < count; ++j) seeds.push_back(mixed_seed(static_cast<std::uint64_t>(j)));
    return seeds;
}

std::unique_ptr<sampler> require_sampler(const char* name) {
    auto s = make_sampler(name);
    VL_REQUIRE(s != nullptr, "make_sampler(\"" << name << "\") should return a sampler; yours returned nullptr");
    return s;
}

std::size_t side_of(std::size_t n) {
    std::size_t k = 0;
    while (k * k < n) ++k;
    return k;
}

bool in_pixel(const sample_offset& o) { return o.dx >= 0 && o.dx < 1 && o.dy >= 0 && o.dy < 1; }

std::string show(const sample_offset& o) { return "(" + num(o.dx) + ", " + num(o.dy) + ")"; }

bool same(const std::vector<sample_offset>& a, const std::vector<sample_offset>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (a[i].dx != b[i].dx || a[i].dy != b[i].dy) return false;
    return true;
}

std::string first_difference(const std::vector<sample_offset>& a, const std::vector<sample_offset>& b) {
    for (std::size_t i = 0; i < a.size() && i < b.size(); ++i)
        if (a[i].dx != b[i].dx || a[i].dy != b[i].dy)
            return "sample " + std::to_string(i) + " is " + show(a[i]) + " once and " + show(b[i]) + " the other time";
    return "the sizes differ";
}

/// Where sample i sits inside its cell (i % k, i / k), from 0 to 1 across the cell.
std::pair<double, double> in_cell(const sample_offset& o, std::size_t i, std::size_t k) {
    const double s = static_cast<double>(k);
    return {o.dx * s - static_cast<double>(i % k), o.dy * s - static_cast<double>(i / k)};
}

/// The Pearson correlation of two samples of the same size.
double correlation(const std::vector<double>& a, const std::vector<double>& b) {
    const double n = static_cast<double>(a.size());
    double ma = 0, mb = 0;
    for (std::size_t i = 0; i < a.size(); ++i) ma += a[i], mb += b[i];
    ma /= n, mb /= n;
    double sab = 0, saa = 0, sbb = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        sab += (a[i] - ma) * (b[i] - mb);
        saa += (a[i] - ma) * (a[i] - ma);
        sbb += (b[i] - mb) * (b[i] - mb);
    }
    return saa > 0 && sbb > 0 ? sab / std::sqrt(saa * sbb) : 1;
}

/// Pearson's chi-square of counts against equal expected counts.
double chi_square(const std::vector<int>& counts) {
    double total = 0;
    for (int c : counts) total += c;
    const double expected = total / static_cast<double>(counts.size());
    double chi = 0;
    for (int c : counts) chi += (c - expected) * (c - expected) / expected;
    return chi;
}

}  // namespace

TEST_CASE("samplers: every pattern fills all n offsets - each at least 0 and below 1 - for n = 1 to 64", "[01][samplers][essential]") {
    tally t;
    for (const char* name : patterns) {
        const auto pattern = require_sampler(name);
        for (std::size_t n = 1; n <= 64; ++n)
            for (int s = 0; s < 6; ++s) {
                const std::uint64_t seed = seed_number(s);
                const auto out = draw(*pattern, n, seed);
                for (std::size_t i = 0; i < n; ++i)
                    VL_CHECK_EACH(t, in_pixel(out[i]),
                                  "\"" << name << "\" with n = " << n << " and seed " << seed << ": sample " << i
                                       << " should be in [0, 1) x [0, 1) (and filled); yours is " << show(out[i])
                                       << (out[i].dx == -1 && out[i].dy == -1 ? " (not filled)" : ""));
            }
    }
    t.finish("offsets");
}

TEST_CASE("samplers: center puts every sample at 0.5 0.5 - the pixel's centre - for any n and seed", "[01][samplers][essential]") {
    const auto pattern = require_sampler("center");
    tally t;
    for (std::size_t n = 1; n <= 64; n += 3)
        for (int s = 0; s < 4; ++s) {
            const auto out = draw(*pattern, n, seed_number(s));
            for (std::size_t i = 0; i < n; ++i)
                VL_CHECK_EACH(t, out[i].dx == 0.5 && out[i].dy == 0.5,
                              "\"center\" with n = " << n << ": sample " << i << " should be (0.5, 0.5); yours is "
                                                     << show(out[i]));
        }
    t.finish("offsets");
}

TEST_CASE("samplers: grid sample i is the centre of cell i % k across and i / k up - k = ceil(sqrt(n)) - for n = 1 to 64",
          "[01][samplers][essential]") {
    const auto pattern = require_sampler("grid");
    tally t;
    for (std::size_t n = 1; n <= 64; ++n) {
        const std::size_t k = side_of(n);
        const auto out = draw(*pattern, n, 12345);
        for (std::size_t i = 0; i < n; ++i) {
            const double s = static_cast<double>(k);
            const double wx = (static_cast<double>(i % k) + 0.5) / s, wy = (static_cast<double>(i / k) + 0.5) / s;
            VL_CHECK_EACH(t, std::fabs(out[i].dx - wx) <= 4 * u && std::fabs(out[i].dy - wy) <= 4 * u,
                          "\"grid\" with n = " << n << " (a " << k << " x " << k << " grid): sample " << i
                                               << " should be the centre of cell (" << i % k << ", " << i / k << "), ("
                                               << num(wx) << ", " << num(wy) << "); yours is " << show(out[i]));
        }
    }
    t.finish("offsets");
}

TEST_CASE("samplers: grid and center are the same for every seed", "[01][samplers]") {
    tally t;
    for (const char* name : {"grid", "center"}) {
        const auto pattern = require_sampler(name);
        for (std::size_t n : {1u, 4u, 7u, 16u, 30u}) {
            const auto first = draw(*pattern, n, 0);
            for (int s = 1; s < 20; ++s) {
                const auto other = draw(*pattern, n, seed_number(s));
                VL_CHECK_EACH(t, same(first, other),
                              "\"" << name << "\" with n = " << n << " has no randomness, so seed " << seed_number(s)
                                   << " should give the offsets of seed 0; " << first_difference(first, other));
            }
        }
    }
    t.finish("seeds");
}

TEST_CASE("samplers: jittered sample i lies in cell i % k across and i / k up - for n = 1 to 64 and many seeds",
          "[01][samplers][essential]") {
    const auto pattern = require_sampler("jittered");
    tally t;
    for (std::size_t n = 1; n <= 64; ++n) {
        const std::size_t k = side_of(n);
        const double s = static_cast<double>(k);
        for (int j = 0; j < 40; ++j) {
            const std::uint64_t seed = seed_number(j);
            const auto out = draw(*pattern, n, seed);
            for (std::size_t i = 0; i < n; ++i) {
                const double x0 = static_cast<double>(i % k) / s, x1 = static_cast<double>(i % k + 1) / s;
                const double y0 = static_cast<double>(i / k) / s, y1 = static_cast<double>(i / k + 1) / s;
                // Cell edges within rounding; the pixel's own edges strictly.
                const bool ok = in_pixel(out[i]) && out[i].dx >= x0 - 4 * u && out[i].dx <= x1 + 4 * u &&
                                out[i].dy >= y0 - 4 * u && out[i].dy <= y1 + 4 * u;
                VL_CHECK_EACH(t, ok,
                              "\"jittered\" with n = " << n << " and seed " << seed << ": sample " << i
                                                       << " should be in cell (" << i % k << ", " << i / k << "), ["
                                                       << num(x0) << ", " << num(x1) << ") x [" << num(y0) << ", "
                                                       << num(y1) << "); yours is " << show(out[i]));
            }
        }
    }
    t.finish("offsets");
}

TEST_CASE("samplers: jittered samples are spread uniformly over their cells", "[01][samplers]") {
    // Where in its cell a sample falls, over many seeds: 8 x 8 bins of the cell, and the
    // means. A sample always at the centre, or at one fixed spot, or jittered in one
    // direction only, fails; a sound generator passes with a wide margin.
    const auto pattern = require_sampler("jittered");
    tally t;
    for (std::size_t n : {1u, 4u, 9u, 10u}) {
        const std::size_t k = side_of(n);
        std::vector<int> bins(64, 0);
        double sum_x = 0, sum_y = 0;
        int count = 0;
        const auto all = draws(*pattern, n, mixed_seeds(2000));
        for (int j = 0; j < 2000; ++j) {
            const auto& out = all[static_cast<std::size_t>(j)];
            for (std::size_t i = 0; i < n; ++i) {
                const auto [cx, cy] = in_cell(out[i], i, k);
                const int bx = std::clamp(static_cast<int>(cx * 8), 0, 7), by = std::clamp(static_cast<int>(cy * 8), 0, 7);
                ++bins[static_cast<std::size_t>(by * 8 + bx)];
                sum_x += cx, sum_y += cy;
                ++count;
            }
        }
        // 63 degrees of freedom: mean 63, standard deviation 11; 160 is nearly 9 of them.
        const double chi = chi_square(bins);
        VL_CHECK_EACH(t, chi < 160,
                      "\"jittered\" with n = " << n << ": over 2000 well-mixed seeds, the positions of the samples inside their "
                                               << "cells should cover the cell evenly (chi-square over 8 x 8 bins below "
                                                  "160, 63 expected); yours gives "
                                               << num(chi));
        const double mx = sum_x / count, my = sum_y / count;
        VL_CHECK_EACH(t, std::fabs(mx - 0.5) < 0.02 && std::fabs(my - 0.5) < 0.02,
                      "\"jittered\" with n = " << n << ": the mean position inside the cell should be (0.5, 0.5) ± 0.02; "
                                               << "yours is (" << num(mx) << ", " << num(my) << ")");
    }
    t.finish("sample counts");
}

TEST_CASE("samplers: jittered positions within the cells are independent across cells and axes", "[01][samplers]") {
    // The same position in every cell (one random pair reused), or dy tied to dx, is a
    // regular pattern, not jittering.
    const auto pattern = require_sampler("jittered");
    constexpr std::size_t n = 16, k = 4;
    constexpr int seeds = 1500;
    std::vector<std::vector<double>> xs(n), ys(n);
    int all_alike = 0;
    const auto all = draws(*pattern, n, mixed_seeds(seeds));
    for (int j = 0; j < seeds; ++j) {
        const auto& out = all[static_cast<std::size_t>(j)];
        bool alike = true;
        const auto first = in_cell(out[0], 0, k);
        for (std::size_t i = 0; i < n; ++i) {
            const auto c = in_cell(out[i], i, k);
            xs[i].push_back(c.first);
            ys[i].push_back(c.second);
            alike = alike && std::fabs(c.first - first.first) < 1e-9 && std::fabs(c.second - first.second) < 1e-9;
        }
        all_alike += alike;
    }
    VL_EXPECT(all_alike == 0, "\"jittered\" with n = 16: each sample should be placed at random in its own cell; in "
                                  << all_alike << " of " << seeds
                                  << " seeds yours puts every sample at the same position inside its cell");
    tally t;
    // 1500 seeds: a correlation of independent numbers is 0 ± 0.026; 0.15 is nearly 6 of those.
    for (std::size_t i = 0; i < n; ++i) {
        const std::size_t next = (i + 1) % n;
        const double across = correlation(xs[i], xs[next]), across_y = correlation(ys[i], ys[next]);
        const double axes = correlation(xs[i], ys[i]);
        VL_CHECK_EACH(t, std::fabs(across) < 0.15 && std::fabs(across_y) < 0.15 && std::fabs(axes) < 0.15,
                      "\"jittered\" with n = 16, over " << seeds << " seeds: the positions inside cells " << i
                                                        << " and " << next
                                                        << " should be uncorrelated (|r| < 0.15), and so should a "
                                                           "sample's x and y; yours have r = "
                                                        << num(across) << " in x, " << num(across_y) << " in y, and "
                                                        << num(axes) << " between x and y of sample " << i);
    }
    t.finish("cells");
}

TEST_CASE("samplers: jittered and random offsets repeat for a seed - from any sampler object",
          "[01][samplers][essential]") {
    tally t;
    for (const char* name : {"jittered", "random"}) {
        const auto a = require_sampler(name);
        for (int j = 0; j < 40; ++j) {
            const std::uint64_t seed = seed_number(j);
            const std::size_t n = static_cast<std::size_t>(j % 20 + 1);
            const auto first = draw(*a, n, seed);
            const auto again = draw(*a, n, seed);
            const auto b = make_sampler(name);
            const auto other = b ? draw(*b, n, seed) : std::vector<sample_offset>{};
            VL_CHECK_EACH(t, same(first, again) && same(first, other),
                          "\"" << name << "\" with n = " << n << " and seed " << seed
                               << " should give the same offsets every time, also from a new sampler object; "
                               << (same(first, again) ? first_difference(first, other) : first_difference(first, again)));
        }
    }
    t.finish("seeds");
}

TEST_CASE("samplers: different seeds give different jittered and random offsets", "[01][samplers][essential]") {
    tally t;
    for (const char* name : {"jittered", "random"}) {
        const auto pattern = require_sampler(name);
        for (std::size_t n : {1u, 2u, 9u}) {
            std::set<std::pair<double, double>> seen;
            int repeats = 0;
            std::string example;
            std::vector<std::uint64_t> numbered;
            for (int j = 0; j < 1000; ++j) numbered.push_back(seed_number(j));
            const auto all = draws(*pattern, n, numbered);
            for (int j = 0; j < 1000; ++j) {
                const std::uint64_t seed = numbered[static_cast<std::size_t>(j)];
                const auto& out = all[static_cast<std::size_t>(j)];
                if (!seen.insert({out[0].dx, out[0].dy}).second) {
                    ++repeats;
                    if (example.empty())
                        example = "seed " + std::to_string(seed) + " repeats sample 0 = " + show(out[0]) +
                                  " of an earlier seed";
                }
            }
            // A 53-bit generator repeats a pair of numbers among 1000 seeds with probability about 1e-25.
            VL_CHECK_EACH(t, repeats == 0,
                          "\"" << name << "\" with n = " << n
                               << ": 1000 different seeds (1 to 500 and 500 well-mixed 64-bit ones) should give "
                                  "1000 different first samples; yours repeats "
                               << repeats << " (" << example << ")");
        }
    }
    t.finish("patterns");
}

TEST_CASE("samplers: seeds that differ only in their upper 32 bits give different offsets",
          "[01][samplers][detail]") {
    // The seed is a 64-bit number, and the render driver's per-pixel seeds use all of it.
    const std::uint64_t high = 0xffffffff00000000ull;
    const std::pair<std::uint64_t, std::uint64_t> pairs[] = {
        {5, 5 + (1ull << 32)}, {0, 1ull << 63}, {1, 1 | high}, {0x12345678, 0x9abcdef012345678ull},
        {mixed_seed(3), mixed_seed(3) ^ (1ull << 40)}};
    tally t;
    for (const char* name : {"jittered", "random"}) {
        const auto pattern = require_sampler(name);
        for (const auto& [a, b] : pairs) {
            const auto oa = draw(*pattern, 4, a), ob = draw(*pattern, 4, b);
            VL_CHECK_EACH(t, !same(oa, ob),
                          "\"" << name << "\" with n = 4: seeds " << a << " and " << b
                               << " differ (in their upper 32 bits), so their offsets should differ; yours are the "
                                  "same, sample 0 = "
                               << show(oa[0]) << " (seed the generator with all 64 bits of the seed)");
        }
    }
    t.finish("seed pairs");
}

TEST_CASE("samplers: offsets depend on the seed alone - not on earlier calls", "[01][samplers]") {
    tally t;
    for (const char* name : {"jittered", "random"}) {
        const auto fresh = require_sampler(name);
        // The answers of a fresh object, each seed asked once.
        std::vector<std::vector<sample_offset>> want;
        for (int j = 0; j < 12; ++j) want.push_back(draw(*require_sampler(name), 9, seed_number(j)));
        // One object asked in reverse order, with other counts and seeds in between.
        for (int j = 11; j >= 0; --j) {
            (void)draw(*fresh, static_cast<std::size_t>(j * 5 + 1), mixed_seed(static_cast<std::uint64_t>(1000 + j)));
            const auto got = draw(*fresh, 9, seed_number(j));
            VL_CHECK_EACH(t, same(got, want[static_cast<std::size_t>(j)]),
                          "\"" << name << "\" with n = 9 and seed " << seed_number(j)
                               << " should give the same offsets whatever was asked before; "
                               << first_difference(got, want[static_cast<std::size_t>(j)]));
        }
    }
    t.finish("calls");
}

TEST_CASE("samplers: one sampler object used from several threads at once gives each the same offsets",
          "[01][samplers]") {
    tally t;
    for (const char* name : {"jittered", "random", "grid"}) {
        const auto pattern = require_sampler(name);
        constexpr int seeds = 300;
        constexpr std::size_t n = 16;
        std::vector<std::vector<sample_offset>> want;
        for (int j = 0; j < seeds; ++j) want.push_back(draw(*require_sampler(name), n, seed_number(j)));
        constexpr int threads = 4;
        std::vector<int> mismatches(threads, 0);
        std::vector<std::exception_ptr> errors(threads);
        {
            std::vector<std::thread> pool;
            for (int th = 0; th < threads; ++th)
                pool.emplace_back([&, th] {
                    try {
                        for (int j = 0; j < seeds; ++j) {
                            // Each thread walks the seeds in its own order.
                            const int s = (j * (2 * th + 1) + th * 37) % seeds;
                            std::vector<sample_offset> out(n);
                            pattern->offsets(out, seed_number(s));
                            if (!same(out, want[static_cast<std::size_t>(s)])) ++mismatches[static_cast<std::size_t>(th)];
                        }
                    } catch (...) {
                        errors[static_cast<std::size_t>(th)] = std::current_exception();
                    }
                });
            for (auto& th : pool) th.join();
        }
        for (const auto& e : errors)
            if (e) std::rethrow_exception(e);
        int total = 0;
        for (int m : mismatches) total += m;
        VL_CHECK_EACH(t, total == 0,
                      "\"" << name << "\": four threads asking one sampler object for " << seeds
                           << " seeds at once should each get the offsets a single thread gets; " << total << " of "
                           << threads * seeds << " answers differed (keep no state that offsets() changes)");
    }
    t.finish("patterns");
}

TEST_CASE("samplers: random offsets cover the pixel uniformly", "[01][samplers][essential]") {
    const auto pattern = require_sampler("random");
    tally t;
    for (std::size_t n : {1u, 16u}) {
        std::vector<int> bins(64, 0), columns(16, 0), rows(16, 0);
        const int seeds = n == 1 ? 20000 : 2000;
        const auto all = draws(*pattern, n, mixed_seeds(seeds));
        for (int j = 0; j < seeds; ++j) {
            const auto& out = all[static_cast<std::size_t>(j)];
            for (const sample_offset& o : out) {
                const int bx = std::clamp(static_cast<int>(o.dx * 8), 0, 7), by = std::clamp(static_cast<int>(o.dy * 8), 0, 7);
                ++bins[static_cast<std::size_t>(by * 8 + bx)];
                ++columns[static_cast<std::size_t>(std::clamp(static_cast<int>(o.dx * 16), 0, 15))];
                ++rows[static_cast<std::size_t>(std::clamp(static_cast<int>(o.dy * 16), 0, 15))];
            }
        }
        // Chi-square: 63 degrees of freedom (mean 63, sd 11), 15 (mean 15, sd 5.5).
        const double chi = chi_square(bins), cx = chi_square(columns), cy = chi_square(rows);
        VL_CHECK_EACH(t, chi < 160 && cx < 60 && cy < 60,
                      "\"random\" with n = " << n << " over " << seeds << " well-mixed"
                                             << " seeds should cover the pixel evenly: chi-square below 160 over 8 x 8 "
                                                "bins (63 expected) and below 60 over 16 columns and 16 rows (15 "
                                                "expected); yours gives "
                                             << num(chi) << ", " << num(cx) << " and " << num(cy));
    }
    t.finish("sample counts");
}

TEST_CASE("samplers: random samples are independent of each other - not a grid", "[01][samplers]") {
    // Each random sample anywhere in the pixel: sample 0 is not held to a cell, successive
    // samples are uncorrelated, and x is not tied to y.
    const auto pattern = require_sampler("random");
    constexpr std::size_t n = 9;
    constexpr int seeds = 1500;
    std::vector<std::vector<double>> xs(n), ys(n);
    for (int j = 0; j < seeds; ++j) {
        const auto out = draw(*pattern, n, mixed_seed(static_cast<std::uint64_t>(j)));
        for (std::size_t i = 0; i < n; ++i) xs[i].push_back(out[i].dx), ys[i].push_back(out[i].dy);
    }
    tally t;
    for (std::size_t i = 0; i < n; ++i) {
        std::vector<int> quarters(4, 0);
        for (int j = 0; j < seeds; ++j)
            ++quarters[static_cast<std::size_t>((xs[i][static_cast<std::size_t>(j)] < 0.5 ? 0 : 1) +
                                                (ys[i][static_cast<std::size_t>(j)] < 0.5 ? 0 : 2))];
        const double chi = chi_square(quarters);  // 3 degrees of freedom: 40 is far out
        const std::size_t next = (i + 1) % n;
        const double rx = correlation(xs[i], xs[next]), ry = correlation(ys[i], ys[next]), rxy = correlation(xs[i], ys[i]);
        VL_CHECK_EACH(t, chi < 40 && std::fabs(rx) < 0.15 && std::fabs(ry) < 0.15 && std::fabs(rxy) < 0.15,
                      "\"random\" with n = 9, over " << seeds << " seeds: sample " << i
                                                     << " should fall in each quarter of the pixel equally often "
                                                        "(chi-square below 40) and be uncorrelated with sample "
                                                     << next << " (|r| < 0.15) and its y with its x; yours gives "
                                                     << "quarters " << quarters[0] << ", " << quarters[1] << ", "
                                                     << quarters[2] << ", " << quarters[3] << " and r = " << num(rx)
                                                     << ", " << num(ry) << ", " << num(rxy));
    }
    t.finish("samples");
}

TEST_CASE("samplers: n == 0 fills nothing", "[01][samplers][detail]") {
    tally t;
    for (const char* name : patterns) {
        const auto pattern = require_sampler(name);
        std::vector<sample_offset> store(4, sample_offset{-1, -1});
        pattern->offsets(std::span<sample_offset>(store.data(), 0), 7);
        pattern->offsets(std::span<sample_offset>(store.data() + 2, 0), 7);
        bool untouched = true;
        for (const sample_offset& o : store) untouched = untouched && o.dx == -1 && o.dy == -1;
        VL_CHECK_EACH(t, untouched, "\"" << name << "\" asked for 0 offsets should write nothing; yours wrote into the "
                                                     "memory around the empty span");
        const auto one = draw(*pattern, 1, 7);
        VL_CHECK_EACH(t, in_pixel(one[0]), "\"" << name << "\" asked for 1 offset should fill it with a point of the pixel; "
                                                           "yours gives "
                                                << show(one[0]));
    }
    t.finish("patterns");
}

TEST_CASE("samplers: unknown names - and known names in the wrong case - give nullptr", "[01][samplers][detail]") {
    for (const char* name : patterns)
        VL_EXPECT(make_sampler(name) != nullptr, "make_sampler(\"" << name << "\") should return a sampler; yours returned nullptr");
    for (const char* name : {"", "Center", "GRID", "Jittered", "RANDOM", "stratified", "jitter", "grid ", " random",
                             "centre", "uniform"}) {
        const auto s = make_sampler(name);
        VL_EXPECT(s == nullptr, "make_sampler(\"" << name << "\") should return nullptr (not one of center, grid, "
                                                             "jittered, random; names are case-sensitive); yours "
                                                             "returned a sampler");
    }
    // A name that is a prefix of a longer string_view's text is still the short name.
    const std::string_view cut = std::string_view("gridded").substr(0, 4);
    VL_EXPECT(make_sampler(cut) != nullptr, "make_sampler(\"grid\") (a string_view into \"gridded\") should return a "
                                            "sampler; yours returned nullptr");
}
