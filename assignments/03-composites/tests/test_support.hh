#pragma once
/// \file
/// \brief Helpers for stage 03's public tests. You need not read this file to use the
/// tests, but it helps when one fails: the children the tests put into your composites
/// are the test's own objects below (test_sphere, test_shell), which compute their hits
/// in long double and count how often they were intersected, so a test can tell exactly
/// which children your composite tested.

#include "vl/catch.hh"

#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "../../02-sphere/tests/test_support.hh"
#include "stage_03.hh"
#include "vl/object_list.hh"
#include "vl/stats.hh"

namespace vl::stage03::testing {

// The ray_through(), random numbers, messages and scene-file readers of stage 02's tests.
using stage02::testing::num;
using stage02::testing::random_numbers;
using stage02::testing::ray_through;
using stage02::testing::read_error;
using stage02::testing::read_object;
using stage02::testing::show;
using stage02::testing::written;

/// The counters of vl::counts() in words.
inline std::string show(const intersection_counts& c) {
    return std::to_string(c.bounding_volume_tests) + " bounding-volume tests, " + std::to_string(c.primitive_tests) +
           " primitive tests, " + std::to_string(c.composite_tests) + " composite tests";
}

// ---------------------------------------------------------------------------------------
// Counting and geometry
// ---------------------------------------------------------------------------------------

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
class test_sphere final : public stage02::testing::test_ball<rtab_component> {
public:
    test_sphere(const point& center, double radius, int id = 0) : test_ball(center, radius), id_(id) {}

    std::string type_name() const override { return "TEST_SPHERE"; }
    int id() const { return id_; }
    const point& center() const { return center_; }
    double radius() const { return radius_; }
    /// How many times a ray was intersected with this sphere.
    std::uint64_t calls() const { return calls_; }

private:
    intersection find_intersection(const ray& r) const override {
        ++calls_;
        const stage02::testing::sphere_roots h = stage02::testing::roots_in_long_double(center_, radius_, r);
        if (!h.meets) return intersection::none();
        const long double limit = std::fabs(zero_t());
        if (h.t1 > limit) return intersection::at(static_cast<double>(h.t1), this);
        if (h.t2 > limit) return intersection::at(static_cast<double>(h.t2), this);
        return intersection::none();
    }

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
        if (stage02::testing::passes_within(r, center_, radius_)) return intersection::composite_only(this);
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
