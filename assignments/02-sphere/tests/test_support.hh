#pragma once
/// \file
/// \brief Helpers for stage 02's public tests. You need not read this file: the tests
/// themselves say what they check.

#include <cmath>
#include <memory>
#include <numbers>
#include <random>
#include <sstream>
#include <string>

#include "all_pieces.hh"
#include "stage_02.hh"
#include "vl/scene_reader.hh"

namespace vl::stage02::testing {

/// The ray from `from` through `to`.
inline ray ray_through(const point& from, const point& to) { return ray(from, to - from); }

/// The distance between two points.
inline double distance(const point& p, const point& q) { return (p - q).length(); }

/// Reads one object (`SPHERE { ... }`) from `text` as if it were the file `test.ray_trace`,
/// with every piece this build links.
inline std::unique_ptr<rtab_component> read_object(const std::string& text) {
    static const registry types = [] {
        registry r;
        register_all_pieces(r);
        return r;
    }();
    scene_reader in(types);
    in.open_text(text, "test.ray_trace");
    return in.read_object();
}

/// What write() writes for `o`.
inline std::string written(const rtab_component& o) {
    std::ostringstream s;
    o.write(s);
    return s.str();
}

/// A surface that differs from the default only in zero_t.
inline surface with_zero_t(double zero_t) {
    surface s;
    s.zero_t = zero_t;
    return s;
}

/// Random numbers for the sweeps, with a fixed seed so that every run tests the same rays.
class random_numbers {
public:
    explicit random_numbers(unsigned seed = 2) : engine_(seed) {}
    /// Uniform in [lo, hi).
    double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(engine_); }
    /// A point uniform in the cube [-s, s]^3.
    point in_cube(double s) { return {uniform(-s, s), uniform(-s, s), uniform(-s, s)}; }
    /// A vector uniform in the cube [-s, s]^3.
    vector offset(double s) { return {uniform(-s, s), uniform(-s, s), uniform(-s, s)}; }
    /// A unit vector, uniform over the sphere of directions.
    vector direction() {
        const double z = uniform(-1, 1), phi = uniform(0, 2 * std::numbers::pi);
        const double s = std::sqrt(1 - z * z);
        return {s * std::cos(phi), s * std::sin(phi), z};
    }

private:
    std::mt19937_64 engine_;
};

}  // namespace vl::stage02::testing
