#pragma once
/// \file
/// \brief Helpers for stage 03's public tests. You need not read this file to use the
/// tests, but it helps when one fails: the children the tests put into your composites
/// are the test's own objects below (test_sphere, test_shell), which compute their hits
/// in long double and count how often they were intersected, so a test can tell exactly
/// which children your composite tested.

#include "vl/catch.hh"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <memory>
#include <numbers>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "all_pieces.hh"
#include "stage_03.hh"
#include "vl/object_list.hh"
#include "vl/scene_reader.hh"
#include "vl/stats.hh"

namespace vl::stage03::testing {

// ---------------------------------------------------------------------------------------
// Printing values in messages
// ---------------------------------------------------------------------------------------

/// `x` in the shortest form that reads back as exactly `x`.
inline std::string num(double x) {
    if (std::isnan(x)) return "NaN";
    if (std::isinf(x)) return x > 0 ? "infinity" : "-infinity";
    char buf[64];
    const auto r = std::to_chars(buf, buf + sizeof buf, x);
    return std::string(buf, r.ptr);
}
/// `(x, y, z)` of a point (homogenized) or a vector.
inline std::string show(const point& p) {
    const point h = p.w == 1 ? p : p.homogenized();
    return "(" + num(h.x) + ", " + num(h.y) + ", " + num(h.z) + ")";
}
inline std::string show(const vector& v) { return "(" + num(v.x) + ", " + num(v.y) + ", " + num(v.z) + ")"; }
/// "the ray from (..) towards (..)".
inline std::string show(const ray& r) { return "the ray from " + show(r.origin()) + " towards " + show(r.direction()); }
/// What an intersection says: "a hit at t = 4 on a SPHERE", "composite_only of the BVH", "a miss".
inline std::string show(const intersection& i) {
    if (i.is_miss()) return "a miss (intersection::none())";
    if (i.is_composite_only()) return "composite_only of a " + i.object->type_name() + " (t == 0)";
    return "a hit at t = " + num(i.t) + " on a " + i.object->type_name();
}
/// The counters of vl::counts() in words.
inline std::string show(const intersection_counts& c) {
    return std::to_string(c.bounding_volume_tests) + " bounding-volume tests, " + std::to_string(c.primitive_tests) +
           " primitive tests, " + std::to_string(c.composite_tests) + " composite tests";
}

// ---------------------------------------------------------------------------------------
// Rays, random numbers, counting
// ---------------------------------------------------------------------------------------

/// The ray from `from` through `to`.
inline ray ray_through(const point& from, const point& to) { return ray(from, to - from); }

/// Random numbers for the sweeps, with a fixed seed so that every run tests the same rays.
class random_numbers {
public:
    explicit random_numbers(unsigned seed = 3) : engine_(seed) {}
    /// Uniform in [lo, hi).
    double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(engine_); }
    /// A point uniform in the box [lo, hi]^3.
    point in_box(double lo, double hi) { return {uniform(lo, hi), uniform(lo, hi), uniform(lo, hi)}; }
    /// A unit vector, uniform over the sphere of directions.
    vector direction() {
        const double z = uniform(-1, 1), phi = uniform(0, 2 * std::numbers::pi);
        const double s = std::sqrt(1 - z * z);
        return {s * std::cos(phi), s * std::sin(phi), z};
    }

private:
    std::mt19937_64 engine_;
};

/// What `work` cost in this thread's counters (vl::counts()).
template <class Work>
intersection_counts cost_of(Work&& work) {
    const intersection_counts before = counts();
    work();
    return counts() - before;
}

/// A unit vector perpendicular to `d`.
inline vector perpendicular(const vector& d) {
    const vector helper = std::fabs(d.x) < 0.6 ? vector(1, 0, 0) : vector(0, 1, 0);
    return (d % helper).unit();
}

// ---------------------------------------------------------------------------------------
// The tests' own children
// ---------------------------------------------------------------------------------------

/// \brief A sphere the tests put into your composites. Its hits are computed in long
/// double, it knows its box, normal and inside, and it counts its own intersect() calls.
/// `id` tells the spheres of a test apart (and a copy of a sphere from the original).
class test_sphere final : public rtab_component {
public:
    test_sphere(const point& center, double radius, int id = 0) : center_(center), radius_(radius), id_(id) {}

    std::string type_name() const override { return "TEST_SPHERE"; }
    int id() const { return id_; }
    const point& center() const { return center_; }
    double radius() const { return radius_; }
    /// How many times a ray was intersected with this sphere.
    std::uint64_t calls() const { return calls_; }

    vector normal(const point& p) const override { return (p.homogenized() - center_).unit(); }
    point min_point() const override { return center_ - vector(radius_, radius_, radius_); }
    point max_point() const override { return center_ + vector(radius_, radius_, radius_); }
    bool contains(const point& p) const override { return (p.homogenized() - center_).length() < radius_; }

private:
    intersection find_intersection(const ray& r) const override {
        ++calls_;
        using ld = long double;
        const point o = r.origin().homogenized();
        const vector d = r.direction();
        const ld ox = ld(o.x) - center_.x, oy = ld(o.y) - center_.y, oz = ld(o.z) - center_.z;
        const ld dd = ld(d.x) * d.x + ld(d.y) * d.y + ld(d.z) * d.z;
        const ld b = ox * d.x + oy * d.y + oz * d.z;
        const ld c = ox * ox + oy * oy + oz * oz - ld(radius_) * radius_;
        const ld disc = b * b - dd * c;
        if (disc < 0) return intersection::none();
        const ld root = std::sqrt(disc);
        // The near root without cancellation, the far one from the product of the roots.
        const ld q = b > 0 ? -(b + root) : -(b - root);
        ld t1 = q / dd, t2 = q != 0 ? c / q : t1;
        if (t1 > t2) std::swap(t1, t2);
        const ld limit = std::fabs(zero_t());
        if (t1 > limit) return intersection::at(static_cast<double>(t1), this);
        if (t2 > limit) return intersection::at(static_cast<double>(t2), this);
        return intersection::none();
    }

    point center_;
    double radius_;
    int id_;
    mutable std::uint64_t calls_ = 0;
};

/// \brief A composite with no children and a spherical bound: a ray that passes within
/// `radius` of `center` (ahead of its origin) gets composite_only(this), any other ray a
/// miss. The tests use it to see what your composite does with a child's rule 2.
class test_shell final : public rtab_composite {
public:
    test_shell(const point& center, double radius) : center_(center), radius_(radius) {}
    std::string type_name() const override { return "TEST_SHELL"; }
    point min_point() const override { return center_ - vector(radius_, radius_, radius_); }
    point max_point() const override { return center_ + vector(radius_, radius_, radius_); }

private:
    intersection find_intersection(const ray& r) const override {
        const vector oc = center_ - r.origin().homogenized();
        const double along = oc * r.direction();
        const double miss_distance = (oc - along * r.direction()).length();
        if (miss_distance < radius_ && (along > 0 || oc.length() < radius_)) return intersection::composite_only(this);
        return intersection::none();
    }
    point center_;
    double radius_;
};

/// The test sphere a hit landed on, or nullptr (a miss, composite_only, another type).
inline const test_sphere* hit_sphere(const intersection& i) {
    return i.hit() ? dynamic_cast<const test_sphere*>(i.object) : nullptr;
}

/// A LIST (the framework's, no bound) of copies of `spheres`: the answer key.
inline std::unique_ptr<object_list> list_of(const std::vector<test_sphere*>& spheres) {
    auto list = std::make_unique<object_list>();
    for (const test_sphere* s : spheres) list->insert(std::make_unique<test_sphere>(s->center(), s->radius(), s->id()));
    return list;
}

/// Inserts a test sphere into `c` and returns it (still owned by `c`).
inline test_sphere* add_sphere(rtab_composite& c, const point& center, double radius, int id = 0) {
    auto s = std::make_unique<test_sphere>(center, radius, id);
    test_sphere* raw = s.get();
    c.insert(std::move(s));
    return raw;
}

/// \brief Compares `composite` with `list` (the same spheres in a LIST) on `rays`: both
/// must hit or both miss, at the same t, on the sphere with the same id. Returns "" when
/// they agree on every ray, else how many rays differ and what the first one got.
inline std::string differences_from_list(const rtab_component& composite, const rtab_component& list,
                                         const std::vector<ray>& rays) {
    int wrong = 0;
    std::string first;
    for (const ray& r : rays) {
        const intersection got = composite.intersect(r), want = list.intersect(r);
        bool same = got.hit() == want.hit();
        if (same && want.hit()) {
            const test_sphere* g = hit_sphere(got);
            same =
                g != nullptr && g->id() == hit_sphere(want)->id() && std::fabs(got.t - want.t) <= 1e-12 * (1 + want.t);
        }
        if (!same && wrong++ == 0) {
            first = show(r) + " should give " +
                    (want.hit()
                         ? "the hit at t = " + num(want.t) + " on test sphere " + std::to_string(hit_sphere(want)->id())
                         : std::string("no hit"));
            const test_sphere* g = hit_sphere(got);
            first += "; yours gave " + show(got) + (g ? " (test sphere " + std::to_string(g->id()) + ")" : "");
        }
    }
    if (wrong == 0) return "";
    return std::to_string(wrong) + " of " + std::to_string(rays.size()) + " rays differ from a LIST of the same " +
           "children; the first: " + first;
}

/// `n` random rays that start anywhere in [lo, hi]^3 and point anywhere.
inline std::vector<ray> random_rays(random_numbers& random, int n, double lo, double hi) {
    std::vector<ray> rays;
    for (int k = 0; k < n; ++k) rays.emplace_back(random.in_box(lo, hi), random.direction());
    return rays;
}

/// `n` random rays from outside [lo, hi]^3 (a margin of `hi - lo` around it) aimed at
/// random points inside it.
inline std::vector<ray> rays_into(random_numbers& random, int n, double lo, double hi) {
    std::vector<ray> rays;
    const double size = hi - lo;
    while (static_cast<int>(rays.size()) < n) {
        const point from = random.in_box(lo - size, hi + size);
        if (from.x > lo && from.x < hi && from.y > lo && from.y < hi && from.z > lo && from.z < hi) continue;
        rays.push_back(ray_through(from, random.in_box(lo, hi)));
    }
    return rays;
}

// ---------------------------------------------------------------------------------------
// Scene files
// ---------------------------------------------------------------------------------------

/// Reads one object (`BOX { ... }`) from `text` as if it were the file `test.ray_trace`,
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

/// The message of the vl::file_error that reading `text` throws, or "(no error)".
inline std::string read_error(const std::string& text) {
    try {
        read_object(text);
    } catch (const file_error& e) {
        return e.what();
    }
    return "(no error)";
}

/// What write() writes for `o`.
inline std::string written(const rtab_component& o) {
    std::ostringstream s;
    o.write(s);
    return s.str();
}

/// The message of the vl::usage_error that `work` throws, or "(no error)". Any other
/// exception (a stub's "not yet implemented") goes on to fail the test.
template <class Work>
std::string usage_error_of(Work&& work) {
    try {
        work();
    } catch (const usage_error& e) {
        return e.what();
    }
    return "(no error)";
}

/// \brief Compares two objects (one read from what the other wrote) on `n` random rays
/// from [lo, hi]^3: the same hit or miss at the same t. Returns "" or the first difference.
inline std::string different_hits(const rtab_component& a, const rtab_component& b, int n, double lo, double hi) {
    random_numbers random(11);
    for (int k = 0; k < n; ++k) {
        const ray r(random.in_box(lo, hi), random.direction());
        const intersection i = a.intersect(r), j = b.intersect(r);
        if (i.hit() != j.hit() || (i.hit() && std::fabs(i.t - j.t) > 1e-9 * (1 + i.t)))
            return show(r) + ": the first object gives " + show(i) + ", the one read back " + show(j);
    }
    return "";
}

}  // namespace vl::stage03::testing
