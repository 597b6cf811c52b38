#pragma once
// Helpers shared by stage 02's hidden tests of the flat objects (grader only).

#include <cmath>
#include <memory>
#include <numbers>
#include <random>
#include <sstream>
#include <string>

#include "stage_02.hh"
#include "vl/registry.hh"
#include "vl/scene_reader.hh"

namespace vl::stage02::hidden {

/// The ray from `from` through `to`.
inline ray through(const point& from, const point& to) { return ray(from, to - from); }

/// A primitive's answer is a hit at a finite distance > 0, on `object`.
inline bool clean_hit(const intersection& i, const rtab_component* object) {
    return i.object == object && std::isfinite(i.t) && i.t > 0;
}

/// A primitive's answer is intersection::none(): no object, no distance.
inline bool clean_miss(const intersection& i) { return i.object == nullptr && i.t == 0; }

/// Reads one object from `text` with stage 02's types and the framework's.
inline std::unique_ptr<rtab_component> read_one(const std::string& text) {
    static const registry types = [] {
        registry r;
        register_framework(r);
        register_stage_02(r);
        return r;
    }();
    scene_reader in(types);
    in.open_text(text, "hidden.ray_trace");
    return in.read_object();
}

/// What write() writes.
inline std::string text_of(const rtab_component& o) {
    std::ostringstream s;
    o.write(s);
    return s.str();
}

/// Seeded random numbers (a different seed from the public tests' helper).
class sampler {
public:
    explicit sampler(unsigned seed) : engine_(seed) {}
    double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(engine_); }
    point in_box(double s) { return {uniform(-s, s), uniform(-s, s), uniform(-s, s)}; }
    vector jitter(double s) { return {uniform(-s, s), uniform(-s, s), uniform(-s, s)}; }
    vector direction() {
        const double z = uniform(-1, 1), phi = uniform(0, 2 * std::numbers::pi);
        const double s = std::sqrt(1 - z * z);
        return {s * std::cos(phi), s * std::sin(phi), z};
    }

private:
    std::mt19937_64 engine_;
};

/// Two unit vectors spanning the plane perpendicular to `n`.
inline void plane_axes(const vector& n, vector& u, vector& v) {
    const vector helper = std::fabs(n.unit().x) < 0.6 ? vector(1, 0, 0) : vector(0, 1, 0);
    u = (n % helper).unit();
    v = (n.unit() % u).unit();
}

}  // namespace vl::stage02::hidden
