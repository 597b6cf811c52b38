#pragma once
// Helpers shared by stage 03's hidden tests (grader only): probe children that compute
// their own hits in long double and count their own tests, brute-force answer keys, random
// scenes, and readers for scene text. What the public tests have (ray_through(), random
// numbers, reading scene text) comes from their helpers (assignments/02-sphere/tests/
// test_support.hh), what every hidden suite has (the tally, long-double vectors,
// surfaces) from grader/hidden/common.
//
// Every child a test puts into your composites is, wherever possible, a probe: a type
// your code has never seen, reachable only through its counted intersect(). Each probe
// counts its own tests (in its own storage and in a per-thread total), so the tests can
// check that your composite's work as the framework's counters see it (vl::counts()) is
// the work the children really did.

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <numbers>
#include <optional>
#include <ostream>
#include <random>
#include <sstream>
#include <type_traits>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "02-sphere/tests/test_support.hh"
#include "grading.hh"
#include "long_double.hh"
#include "stage_02.hh"
#include "stage_03.hh"
#include "surfaces.hh"
#include "vl/bounds.hh"
#include "vl/error.hh"
#include "vl/object_list.hh"
#include "vl/primitive.hh"
#include "vl/registry.hh"
#include "vl/scene_reader.hh"
#include "vl/stats.hh"

namespace vl::stage03::hidden {

using grading::full_precision_surface;
using grading::num;
using grading::real;
using grading::roots;
using grading::rvec;
using grading::sphere_roots;
using grading::show;
using grading::surface_of;
using grading::surface_text;
using grading::tally;
using grading::to_point;
using grading::to_r;
using grading::to_vector;
using stage02::testing::ray_through;

// --- long-double vectors -----------------------------------------------------------------

inline real axis_of(const rvec& a, int k) { return k == 0 ? a.x : k == 1 ? a.y : a.z; }
inline double axis_of(const point& a, int k) { return k == 0 ? a.x : k == 1 ? a.y : a.z; }
inline std::string show(const rvec& a) {
    return "(" + num(static_cast<double>(a.x)) + ", " + num(static_cast<double>(a.y)) + ", " +
           num(static_cast<double>(a.z)) + ")";
}

/// `x` rounded to a double no greater (down) or no smaller (up) than it.
inline double round_down(real x) {
    double d = static_cast<double>(x);
    if (static_cast<real>(d) > x) d = std::nextafter(d, -std::numeric_limits<double>::infinity());
    return d;
}
inline double round_up(real x) {
    double d = static_cast<double>(x);
    if (static_cast<real>(d) < x) d = std::nextafter(d, std::numeric_limits<double>::infinity());
    return d;
}

/// The first root beyond `eps` (0 when none).
inline real first_beyond(const roots& r, real eps) {
    if (!r.meets) return 0;
    if (r.t0 > eps) return r.t0;
    if (r.t1 > eps) return r.t1;
    return 0;
}

// --- what an intersect() returned, in words ------------------------------------------------

/// A name for each object a test knows (probes, your composites); unknown ones by type.
class namer {
public:
    void name(const rtab_component* o, std::string what) { names_[o] = std::move(what); }
    std::string operator()(const rtab_component* o) const {
        if (o == nullptr) return "no object";
        const auto found = names_.find(o);
        if (found != names_.end()) return found->second;
        return "an object of type " + o->type_name() + " that is not one of the children";
    }

private:
    std::unordered_map<const rtab_component*, std::string> names_;
};

inline std::string show(const intersection& i, const namer& names) {
    if (i.object == nullptr && i.t == 0) return "a miss (intersection::none())";
    if (i.object == nullptr) return "t = " + num(i.t) + " with no object (a miss must be intersection::none())";
    if (i.t == 0) return "composite_only of " + names(i.object);
    if (!(i.t > 0)) return "t = " + num(i.t) + " on " + names(i.object) + " (not a hit: t must be > 0)";
    return "a hit at t = " + num(i.t) + " on " + names(i.object);
}

/// Runs `f`; "" when it returned normally, else what it threw, in words.
template <class F>
std::string what_thrown(F&& f) {
    try {
        f();
    } catch (const usage_error& e) {
        return std::string("usage_error: ") + e.what();
    } catch (const file_error& e) {
        return std::string("file_error: ") + e.what();
    } catch (const std::exception& e) {
        return std::string("exception: ") + e.what();
    } catch (...) {
        return "an exception that is not a std::exception";
    }
    return "";
}

/// True when `f` throws vl::usage_error; `message` gets its message or what happened.
template <class F>
bool throws_usage_error(F&& f, std::string& message) {
    try {
        f();
    } catch (const usage_error& e) {
        message = e.what();
        return true;
    } catch (const std::exception& e) {
        message = std::string("it threw another exception: ") + e.what();
        return false;
    } catch (...) {
        message = "it threw something that is not a std::exception";
        return false;
    }
    message = "it threw nothing";
    return false;
}

// --- random inputs -----------------------------------------------------------------------

/// Seeded random numbers: the public tests' generator, with a whole number below `n` and
/// a point in the cube [lo, hi]^3 (the unit cube unless a test says otherwise).
class dice : public stage02::testing::random_numbers {
public:
    explicit dice(unsigned seed) : random_numbers(seed) {}
    int below(int n) { return std::uniform_int_distribution<int>(0, n - 1)(engine()); }
    point in_cube(double lo = 0, double hi = 1) { return in_box(lo, hi); }
};

// --- probes ------------------------------------------------------------------------------

/// Every probe's tests on this thread, all probes together.
inline thread_local std::uint64_t probe_tests = 0;
/// Every probe's tests on every thread: more than this thread's, during a ray this thread
/// asked for, means the composite tested children on threads of its own, which the
/// counters (per thread) do not see.
inline std::atomic<std::uint64_t> probe_tests_everywhere{0};

/// \brief The probes' common part: a primitive with a surface that counts each of its
/// intersection tests, and a long-double answer key of its own (exact_t).
class probe : public primitive {
public:
    /// The tests of this probe, on all threads.
    std::uint64_t tests() const { return tests_.load(std::memory_order_relaxed); }
    /// The first hit beyond |zero_t()| in long double, or 0 for none (uncounted).
    virtual real exact_t(const ray& r) const = 0;
    /// A name for messages.
    virtual std::string describe() const = 0;
    std::string type_name() const override { return "PROBE"; }
    /// An id written by write() so tests can follow a probe through a scene file.
    int id = -1;

private:
    intersection find_intersection(const ray& r) const override {
        ++probe_tests;
        probe_tests_everywhere.fetch_add(1, std::memory_order_relaxed);
        tests_.fetch_add(1, std::memory_order_relaxed);
        const real t = exact_t(r);
        return t > 0 ? intersection::at(static_cast<double>(t), this) : intersection::none();
    }
    mutable std::atomic<std::uint64_t> tests_{0};
};

inline real eps_of(const rtab_component& o) { return std::fabs(static_cast<real>(o.zero_t())); }

/// A sphere (written and read as `PROBE { center X Y Z radius R id K }`).
class probe_sphere final : public probe {
public:
    /// `widened`: the box is a little larger than the sphere, by a part in ten million that
    /// differs from sphere to sphere. A box still holds its sphere (any box may be larger
    /// than its object), but no code can then read the sphere off its box and answer for
    /// it without calling its intersect(): such hits are off by far more than the tests'
    /// tolerance of 1e-12. The scenes a BVH is measured on use such spheres.
    probe_sphere(const point& c, double r, bool widened = false) : widened_(widened) { set(c, r); }
    void set(const point& c, double r) {
        center_ = c.homogenized();
        radius_ = r;
        const rvec cc = to_r(center_);
        const real rr = widened_ ? r * (1 + widening(cc)) : r;
        lo_ = point(round_down(cc.x - rr), round_down(cc.y - rr), round_down(cc.z - rr));
        hi_ = point(round_up(cc.x + rr), round_up(cc.y + rr), round_up(cc.z + rr));
    }
    const point& center() const { return center_; }
    double radius() const { return radius_; }
    real exact_t(const ray& r) const override {
        // A quick double test first: the line well beside the sphere is a miss.
        const vector oc = center_ - r.origin();
        const double along = oc * r.direction();
        const vector side = oc - along * r.direction();
        if (side * side > radius_ * radius_ * (1 + 1e-9) + 1e-300) return 0;
        return first_beyond(sphere_roots(to_r(r.origin()), unit(to_r(r.direction())), to_r(center_), radius_),
                            eps_of(*this));
    }
    vector normal(const point& p) const override { return to_vector(unit(to_r(p) - to_r(center_))); }
    bool contains(const point& p) const override { return len(to_r(p) - to_r(center_)) < radius_; }
    point min_point() const override { return lo_; }
    point max_point() const override { return hi_; }
    std::string describe() const override {
        return "the probe sphere" + (id >= 0 ? " #" + std::to_string(id) : std::string()) + " around " +
               show(center_) + " of radius " + num(radius_);
    }
    void read(scene_reader& in) override {
        point c = center_;
        double r = radius_;
        std::vector<scene_reader::property> props{{"center", [&] { c = in.read_point("center of PROBE"); }},
                                                  {"radius", [&] { r = in.read_positive("radius of PROBE"); }},
                                                  {"id", [&] { id = in.read_int("id of PROBE", 0, 1 << 30); }}};
        read_with_surface(in, props);
        set(c, r);
    }
    void write(std::ostream& s) const override {
        s << "PROBE { center " << num(center_.x) << ' ' << num(center_.y) << ' ' << num(center_.z) << " radius "
          << num(radius_) << " id " << id;
        write_surface(s);
        s << " }";
    }

private:
    /// From 1e-7 to 2e-7, a function of the centre.
    static real widening(const rvec& c) {
        const real h = std::fabs(std::sin(12.9898L * c.x + 78.233L * c.y + 37.719L * c.z) * 43758.5453L);
        return 1e-7L * (1 + (h - std::floor(h)));
    }
    bool widened_;
    point center_, lo_, hi_;
    double radius_ = 1;
};

/// A capsule: every point within `radius` of the segment a b (a long thin object).
class probe_capsule final : public probe {
public:
    probe_capsule(const point& a, const point& b, double r) : a_(a.homogenized()), b_(b.homogenized()), radius_(r) {
        const rvec ra = to_r(a_), rb = to_r(b_);
        const real rr = r;
        lo_ = point(round_down(std::min(ra.x, rb.x) - rr), round_down(std::min(ra.y, rb.y) - rr),
                    round_down(std::min(ra.z, rb.z) - rr));
        hi_ = point(round_up(std::max(ra.x, rb.x) + rr), round_up(std::max(ra.y, rb.y) + rr),
                    round_up(std::max(ra.z, rb.z) + rr));
    }
    real exact_t(const ray& r) const override {
        if (!hits_box_exactly(r)) return 0;
        const rvec o = to_r(r.origin()), d = unit(to_r(r.direction())), a = to_r(a_), ab = to_r(b_) - a;
        const real ab2 = dot(ab, ab), eps = eps_of(*this), rr = radius_;
        real best = 0;
        auto offer = [&](real t) {
            if (t > eps && (best == 0 || t < best)) best = t;
        };
        auto along = [&](real t) { return dot(o + t * d - a, ab) / ab2; };  // 0 at a, 1 at b
        // The cylinder around the line a b, where the foot is between a and b.
        const rvec oa = o - a;
        const rvec dp = d - (dot(d, ab) / ab2) * ab, op = oa - (dot(oa, ab) / ab2) * ab;
        const real qa = dot(dp, dp), qb = dot(dp, op), qc = dot(op, op) - rr * rr;
        if (qa > 0) {
            const real disc = qb * qb - qa * qc;
            if (disc >= 0) {
                const real s = std::sqrt(disc);
                for (const real t : {(-qb - s) / qa, (-qb + s) / qa}) {
                    const real u = along(t);
                    if (u >= 0 && u <= 1) offer(t);
                }
            }
        }
        // The two caps: the half of each end's sphere beyond the segment.
        for (const int end : {0, 1}) {
            const roots k = sphere_roots(o, d, end == 0 ? a : to_r(b_), rr);
            if (!k.meets) continue;
            for (const real t : {k.t0, k.t1}) {
                const real u = along(t);
                if (end == 0 ? u <= 0 : u >= 1) offer(t);
            }
        }
        return best;
    }
    vector normal(const point& p) const override { return to_vector(unit(to_r(p) - foot(to_r(p)))); }
    bool contains(const point& p) const override { return len(to_r(p) - foot(to_r(p))) < radius_; }
    point min_point() const override { return lo_; }
    point max_point() const override { return hi_; }
    std::string describe() const override {
        return "the probe capsule" + (id >= 0 ? " #" + std::to_string(id) : std::string()) + " from " + show(a_) +
               " to " + show(b_) + " of radius " + num(radius_);
    }

private:
    bool hits_box_exactly(const ray& r) const {
        // The box holds the capsule: a ray beside it (or behind it) cannot hit.
        const double o[3] = {r.origin().x, r.origin().y, r.origin().z}, d[3] = {r.direction().x, r.direction().y, r.direction().z};
        const double lo[3] = {lo_.x, lo_.y, lo_.z}, hi[3] = {hi_.x, hi_.y, hi_.z};
        real t0 = -std::numeric_limits<real>::infinity(), t1 = std::numeric_limits<real>::infinity();
        for (int k = 0; k < 3; ++k) {
            if (d[k] == 0) {
                if (o[k] < lo[k] || o[k] > hi[k]) return false;
                continue;
            }
            real n = (static_cast<real>(lo[k]) - o[k]) / d[k], f = (static_cast<real>(hi[k]) - o[k]) / d[k];
            if (n > f) std::swap(n, f);
            t0 = std::max(t0, n - 1e-9L);
            t1 = std::min(t1, f + 1e-9L);
        }
        return t0 <= t1 && t1 > 0;
    }
    rvec foot(const rvec& p) const {
        const rvec a = to_r(a_), ab = to_r(b_) - a;
        const real u = std::clamp(dot(p - a, ab) / dot(ab, ab), static_cast<real>(0), static_cast<real>(1));
        return a + u * ab;
    }
    point a_, b_, lo_, hi_;
    double radius_;
};

/// An axis-aligned box, solid (a leaf, not your BOX): slabs in long double.
class probe_cuboid final : public probe {
public:
    probe_cuboid(const point& lo, const point& hi) : lo_(lo.homogenized()), hi_(hi.homogenized()) {}
    real exact_t(const ray& r) const override {
        const rvec o = to_r(r.origin()), d = unit(to_r(r.direction()));
        real t0 = -std::numeric_limits<real>::infinity(), t1 = std::numeric_limits<real>::infinity();
        for (int k = 0; k < 3; ++k) {
            const real ok = axis_of(o, k), dk = axis_of(d, k), a = axis_of(lo_, k), b = axis_of(hi_, k);
            if (dk == 0) {
                if (ok < a || ok > b) return 0;
                continue;
            }
            real n = (a - ok) / dk, f = (b - ok) / dk;
            if (n > f) std::swap(n, f);
            t0 = std::max(t0, n);
            t1 = std::min(t1, f);
        }
        if (t0 > t1) return 0;
        const real eps = eps_of(*this);
        if (t0 > eps) return t0;
        if (t1 > eps) return t1;
        return 0;
    }
    vector normal(const point& p) const override {
        const point q = p.homogenized();
        const double gap[6] = {q.x - lo_.x, hi_.x - q.x, q.y - lo_.y, hi_.y - q.y, q.z - lo_.z, hi_.z - q.z};
        int k = 0;
        for (int j = 1; j < 6; ++j)
            if (std::fabs(gap[j]) < std::fabs(gap[k])) k = j;
        const double s = k % 2 == 0 ? -1 : 1;
        return k / 2 == 0 ? vector(s, 0, 0) : k / 2 == 1 ? vector(0, s, 0) : vector(0, 0, s);
    }
    bool contains(const point& p) const override {
        const point q = p.homogenized();
        return lo_.x < q.x && q.x < hi_.x && lo_.y < q.y && q.y < hi_.y && lo_.z < q.z && q.z < hi_.z;
    }
    point min_point() const override { return lo_; }
    point max_point() const override { return hi_; }
    std::string describe() const override {
        return "the probe cuboid" + (id >= 0 ? " #" + std::to_string(id) : std::string()) + " from " + show(lo_) +
               " to " + show(hi_);
    }

private:
    point lo_, hi_;
};

/// A flat rectangle in the plane `axis` = `at`, from `lo` to `hi` in the other two axes:
/// its box has no thickness.
class probe_flat final : public probe {
public:
    probe_flat(int axis, double at, double lo_u, double lo_v, double hi_u, double hi_v)
        : axis_(axis), at_(at), lo_{lo_u, lo_v}, hi_{hi_u, hi_v} {}
    real exact_t(const ray& r) const override {
        const rvec o = to_r(r.origin()), d = unit(to_r(r.direction()));
        const real dk = axis_of(d, axis_);
        if (dk == 0) return 0;
        const real t = (at_ - axis_of(o, axis_)) / dk;
        if (!(t > eps_of(*this))) return 0;
        const rvec p = o + t * d;
        const int u = (axis_ + 1) % 3, v = (axis_ + 2) % 3;
        const real pu = axis_of(p, u), pv = axis_of(p, v);
        return pu >= lo_[0] && pu <= hi_[0] && pv >= lo_[1] && pv <= hi_[1] ? t : 0;
    }
    vector normal(const point&) const override {
        return axis_ == 0 ? vector(1, 0, 0) : axis_ == 1 ? vector(0, 1, 0) : vector(0, 0, 1);
    }
    point min_point() const override { return corner(lo_); }
    point max_point() const override { return corner(hi_); }
    std::string describe() const override {
        return "the flat probe rectangle" + (id >= 0 ? " #" + std::to_string(id) : std::string()) + " from " +
               show(min_point()) + " to " + show(max_point());
    }

private:
    point corner(const double (&uv)[2]) const {
        double c[3];
        c[axis_] = at_;
        c[(axis_ + 1) % 3] = uv[0];
        c[(axis_ + 2) % 3] = uv[1];
        return point(c[0], c[1], c[2]);
    }
    int axis_;
    double at_;
    double lo_[2], hi_[2];
};

/// \brief A composite of no primitives with a box: every ray through its box gets
/// composite_only(this hollow), every other a miss. (Counted as a composite test.)
class probe_hollow final : public rtab_composite {
public:
    probe_hollow(const point& lo, const point& hi) : lo_(lo), hi_(hi) {}
    std::string type_name() const override { return "HOLLOW"; }
    point min_point() const override { return lo_; }
    point max_point() const override { return hi_; }
    std::uint64_t tests() const { return tests_.load(std::memory_order_relaxed); }

private:
    intersection find_intersection(const ray& r) const override {
        tests_.fetch_add(1, std::memory_order_relaxed);
        probe_cuboid shape(lo_, hi_);
        return shape.exact_t(r) > 0 ? intersection::composite_only(this) : intersection::none();
    }
    point lo_, hi_;
    mutable std::atomic<std::uint64_t> tests_{0};
};

/// A primitive whose box is what it is given (NaN or infinite: unknown); never hit.
class probe_boxless final : public primitive {
public:
    probe_boxless(const point& lo, const point& hi) : lo_(lo), hi_(hi) {}
    std::string type_name() const override { return "BOXLESS"; }
    point min_point() const override { return lo_; }
    point max_point() const override { return hi_; }

private:
    intersection find_intersection(const ray&) const override { return intersection::none(); }
    point lo_, hi_;
};

// --- a set of probes and the brute-force answer key ---------------------------------------

/// \brief Probes owned by the test until they are handed to a composite, with the
/// brute-force nearest hit over all of them as the answer key.
struct probe_set {
    struct quick {
        double x, y, z, r;
        const probe* p;
    };
    std::vector<quick> spheres;       // the sphere probes, packed for a quick first test
    std::vector<const probe*> others;  // every other probe
    std::vector<const probe*> all;
    std::unordered_map<const rtab_component*, std::size_t> index;

    /// Records `p` (which the caller then inserts into a composite) and returns it.
    template <class P>
    std::unique_ptr<P> add(std::unique_ptr<P> p) {
        p->id = static_cast<int>(all.size());
        index[p.get()] = all.size();
        all.push_back(p.get());
        if constexpr (std::is_same_v<P, probe_sphere>)
            spheres.push_back({p->center().x, p->center().y, p->center().z, p->radius() * (1 + 1e-9), p.get()});
        else
            others.push_back(p.get());
        return p;
    }

    /// The nearest hit over every probe (0 for none).
    real nearest(const ray& r) const {
        real best = 0;
        const double ox = r.origin().x, oy = r.origin().y, oz = r.origin().z;
        const double dx = r.direction().x, dy = r.direction().y, dz = r.direction().z;
        for (const quick& q : spheres) {
            // The line well beside the sphere is a miss (the probe's own test decides the rest).
            const double fx = q.x - ox, fy = q.y - oy, fz = q.z - oz;
            const double along = fx * dx + fy * dy + fz * dz;
            const double sx = fx - along * dx, sy = fy - along * dy, sz = fz - along * dz;
            if (sx * sx + sy * sy + sz * sz > q.r * q.r + 1e-300) continue;
            const real t = q.p->exact_t(r);
            if (t > 0 && (best == 0 || t < best)) best = t;
        }
        for (const probe* p : others) {
            const real t = p->exact_t(r);
            if (t > 0 && (best == 0 || t < best)) best = t;
        }
        return best;
    }

    /// Records a probe that is already in a composite (read from a scene file, say).
    void track(const probe* p) {
        index[p] = all.size();
        all.push_back(p);
        if (const auto* s = dynamic_cast<const probe_sphere*>(p))
            spheres.push_back({s->center().x, s->center().y, s->center().z, s->radius() * (1 + 1e-9), p});
        else
            others.push_back(p);
    }

    std::uint64_t total_tests() const {
        std::uint64_t n = 0;
        for (const probe* p : all) n += p->tests();
        return n;
    }
};

/// What one ray cost: the framework's counters and the probes' own count, on this thread
/// and on all threads.
struct cost {
    intersection_counts counts;
    std::uint64_t probe = 0;
    std::uint64_t probe_everywhere = 0;
};
template <class F>
cost measure(F&& f) {
    const intersection_counts before = counts();
    const std::uint64_t probe_before = probe_tests, everywhere_before = probe_tests_everywhere.load();
    f();
    return {counts() - before, probe_tests - probe_before, probe_tests_everywhere.load() - everywhere_before};
}

/// Checks `got` against the brute-force answer over `set`: the same nearest t (up to
/// 1e-12 of it: the probe computes it once, in long double) on one of the probes with
/// that t, or, when no probe is hit, rule 2 (composite_only of `self`) or rule 3 (a miss)
/// as `enters_bound` says. `enters_bound` unset: either is accepted.
inline void check_against_list(tally& t, const std::string& who, const rtab_component* self, const probe_set& set,
                               const ray& r, const intersection& got, std::optional<bool> enters_bound) {
    const real want = set.nearest(r);
    if (want > 0) {
        const auto found = set.index.find(got.object);
        const double w = static_cast<double>(want), tol = 1e-12 * std::max(1.0, w);
        bool ok = got.hit() && found != set.index.end() && std::fabs(got.t - w) <= tol;
        if (ok) {
            const real own = set.all[found->second]->exact_t(r);
            ok = std::fabs(static_cast<double>(own) - w) <= tol;
        }
        t.check(ok, [&] {
            std::string got_words;
            if (got.hit() && found != set.index.end())
                got_words = "a hit at t = " + num(got.t) + " on " + set.all[found->second]->describe();
            else if (got.hit())
                got_words = "a hit at t = " + num(got.t) + " on " +
                            (got.object == self ? "the " + who + " itself (rule 1: the object must be the leaf hit)"
                                                : "an object that is not one of the children (" +
                                                      got.object->type_name() + ")");
            else if (got.object == nullptr)
                got_words = got.t == 0 ? "a miss" : "t = " + num(got.t) + " with no object";
            else
                got_words = "composite_only (t = 0)";
            return show(r) + ": the " + who + " should return the nearest hit of its children, at t = " + num(w) +
                   " ± " + num(tol) + " (the same as a plain LIST of them); yours returned " + got_words;
        });
        return;
    }
    const bool miss = got.object == nullptr && got.t == 0, only = got.object == self && got.t == 0;
    bool ok = enters_bound.has_value() ? (*enters_bound ? only : miss) : (miss || only);
    t.check(ok, [&] {
        std::string got_words = miss   ? "a miss (intersection::none())"
                                : only ? "composite_only(this)"
                                : got.object == nullptr
                                    ? "t = " + num(got.t) + " with no object"
                                    : (got.t == 0 ? "composite_only of another object (" + got.object->type_name() +
                                                        ": rule 2 names the composite itself)"
                                                  : "a hit at t = " + num(got.t) + " on " + got.object->type_name());
        const std::string want_words =
            !enters_bound.has_value() ? "composite_only(this) or a miss"
            : *enters_bound           ? "composite_only(this) (rule 2: it enters the bound but hits no child)"
                                      : "a miss, intersection::none() (rule 3: it misses the bound)";
        return show(r) + " hits none of the " + who + "'s children: it should return " + want_words + "; yours returned " +
               got_words;
    });
}

// --- long-double matrices -------------------------------------------------------------------

struct rmat {
    real e[4][4] = {};
    static rmat of(const matrix& m) {
        rmat out;
        for (int r = 0; r < 4; ++r)
            for (int c = 0; c < 4; ++c) out.e[r][c] = m(r, c);
        return out;
    }
    rvec apply_point(const rvec& p) const {
        return {e[0][0] * p.x + e[0][1] * p.y + e[0][2] * p.z + e[0][3],
                e[1][0] * p.x + e[1][1] * p.y + e[1][2] * p.z + e[1][3],
                e[2][0] * p.x + e[2][1] * p.y + e[2][2] * p.z + e[2][3]};
    }
    rvec apply_vector(const rvec& v) const {
        return {e[0][0] * v.x + e[0][1] * v.y + e[0][2] * v.z, e[1][0] * v.x + e[1][1] * v.y + e[1][2] * v.z,
                e[2][0] * v.x + e[2][1] * v.y + e[2][2] * v.z};
    }
    rvec apply_transposed(const rvec& v) const {
        return {e[0][0] * v.x + e[1][0] * v.y + e[2][0] * v.z, e[0][1] * v.x + e[1][1] * v.y + e[2][1] * v.z,
                e[0][2] * v.x + e[1][2] * v.y + e[2][2] * v.z};
    }
    /// The inverse by Gauss-Jordan elimination with partial pivoting.
    rmat inverse() const {
        real a[4][8];
        for (int r = 0; r < 4; ++r)
            for (int c = 0; c < 8; ++c) a[r][c] = c < 4 ? e[r][c] : (c - 4 == r ? 1 : 0);
        for (int c = 0; c < 4; ++c) {
            int p = c;
            for (int r = c + 1; r < 4; ++r)
                if (std::fabs(a[r][c]) > std::fabs(a[p][c])) p = r;
            for (int k = 0; k < 8; ++k) std::swap(a[c][k], a[p][k]);
            const real pivot = a[c][c];
            for (int k = 0; k < 8; ++k) a[c][k] /= pivot;
            for (int r = 0; r < 4; ++r) {
                if (r == c) continue;
                const real f = a[r][c];
                for (int k = 0; k < 8; ++k) a[r][k] -= f * a[c][k];
            }
        }
        rmat out;
        for (int r = 0; r < 4; ++r)
            for (int c = 0; c < 4; ++c) out.e[r][c] = a[r][c + 4];
        return out;
    }
    rmat operator*(const rmat& o) const {
        rmat out;
        for (int r = 0; r < 4; ++r)
            for (int c = 0; c < 4; ++c) {
                real s = 0;
                for (int k = 0; k < 4; ++k) s += e[r][k] * o.e[k][c];
                out.e[r][c] = s;
            }
        return out;
    }
};

/// Long-double builders of the scene file's steps (independent of stage 01's).
inline rmat r_identity() {
    rmat m;
    for (int k = 0; k < 4; ++k) m.e[k][k] = 1;
    return m;
}
inline rmat r_scale(real x, real y, real z) {
    rmat m = r_identity();
    m.e[0][0] = x;
    m.e[1][1] = y;
    m.e[2][2] = z;
    return m;
}
inline rmat r_translate(real x, real y, real z) {
    rmat m = r_identity();
    m.e[0][3] = x;
    m.e[1][3] = y;
    m.e[2][3] = z;
    return m;
}
/// Right-handed rotation by `degrees` about the axis (Rodrigues).
inline rmat r_rotate(real ax, real ay, real az, real degrees) {
    const rvec k = unit(rvec{ax, ay, az});
    const real a = degrees * std::numbers::pi_v<real> / 180, c = std::cos(a), s = std::sin(a), v = 1 - c;
    rmat m = r_identity();
    m.e[0][0] = c + k.x * k.x * v;
    m.e[0][1] = k.x * k.y * v - k.z * s;
    m.e[0][2] = k.x * k.z * v + k.y * s;
    m.e[1][0] = k.y * k.x * v + k.z * s;
    m.e[1][1] = c + k.y * k.y * v;
    m.e[1][2] = k.y * k.z * v - k.x * s;
    m.e[2][0] = k.z * k.x * v - k.y * s;
    m.e[2][1] = k.z * k.y * v + k.x * s;
    m.e[2][2] = c + k.z * k.z * v;
    return m;
}
inline matrix to_matrix(const rmat& m) {
    return matrix(static_cast<double>(m.e[0][0]), static_cast<double>(m.e[0][1]), static_cast<double>(m.e[0][2]),
                  static_cast<double>(m.e[0][3]), static_cast<double>(m.e[1][0]), static_cast<double>(m.e[1][1]),
                  static_cast<double>(m.e[1][2]), static_cast<double>(m.e[1][3]), static_cast<double>(m.e[2][0]),
                  static_cast<double>(m.e[2][1]), static_cast<double>(m.e[2][2]), static_cast<double>(m.e[2][3]),
                  static_cast<double>(m.e[3][0]), static_cast<double>(m.e[3][1]), static_cast<double>(m.e[3][2]),
                  static_cast<double>(m.e[3][3]));
}

// --- scene text --------------------------------------------------------------------------

/// The types the tests read: the framework's, stage 02's, yours, and `PROBE`
/// (a probe sphere, `PROBE { center X Y Z radius R id K }`).
inline const registry& test_types() {
    static const registry types = [] {
        registry r;
        register_framework(r);
        stage02::register_stage_02(r);
        register_stage_03(r);
        r.add("PROBE", [] { return std::make_unique<probe_sphere>(point(0, 0, 0), 1); });
        return r;
    }();
    return types;
}

/// Reads one object from `text` (as the file "hidden.ray_trace").
inline std::unique_ptr<rtab_component> read_one(const std::string& text) {
    return stage02::testing::read_object(text, "hidden.ray_trace", test_types());
}

/// Reads every object of `text` (as a scene's top level does, without the settings).
inline std::vector<std::unique_ptr<rtab_component>> read_all(const std::string& text) {
    scene_reader in(test_types());
    in.open_text(text, "hidden.ray_trace");
    std::vector<std::unique_ptr<rtab_component>> out;
    while (!in.at_end()) out.push_back(in.read_object());
    return out;
}

/// What write() writes.
inline std::string text_of(const rtab_component& o) { return stage02::testing::written(o); }

/// The message of the vl::file_error that reading `text` throws, or what happened instead.
inline std::string read_error(const std::string& text) {
    return grading::file_error_of([&] { read_one(text); });
}

/// Checks that each of `blocks` is refused with a vl::file_error at its place.
inline void check_refused(tally& t, std::initializer_list<grading::refused_block> blocks) {
    grading::check_refused(t, [](const std::string& text) { return read_error(text); }, blocks);
}

/// The numbers that follow the first `key` in `text` (up to `count` of them), read by
/// the tests' own scanner, not by your read().
inline std::vector<double> numbers_after(const std::string& text, const std::string& key, int count) {
    std::vector<double> out;
    std::size_t at = 0;
    for (;;) {
        at = text.find(key, at);
        if (at == std::string::npos) return out;
        const bool starts = at == 0 || !(std::isalnum(static_cast<unsigned char>(text[at - 1])) || text[at - 1] == '_');
        const std::size_t end = at + key.size();
        const bool ends = end >= text.size() || !(std::isalnum(static_cast<unsigned char>(text[end])) || text[end] == '_');
        if (starts && ends) break;
        at = end;
    }
    const char* p = text.c_str() + at + key.size();
    while (static_cast<int>(out.size()) < count) {
        while (*p == ' ' || *p == '\n' || *p == '\t' || *p == '(' || *p == ',' || *p == ')') ++p;
        char* end = nullptr;
        const double x = std::strtod(p, &end);
        if (end == p) break;
        out.push_back(x);
        p = end;
    }
    return out;
}

/// Compares each surface key of `got` with `want` exactly; a line per difference.
inline void compare_surface(const surface& got, const surface& want, const std::string& who, tally& t) {
    for (const auto& [name, values] : grading::surface_keys(got, want))
        t.check(values.first == values.second, [&, name = name, values = values] {
            return who + " has " + name + " " + num(values.first) + "; it should be " + num(values.second);
        });
}

/// Checks that `p` is `want` in every coordinate within `tol`.
inline void check_point(tally& t, const std::string& what, const point& p, const rvec& want, real tol) {
    const rvec g = to_r(p);
    const bool ok = !is_nan(p) && std::fabs(g.x - want.x) <= tol && std::fabs(g.y - want.y) <= tol &&
                    std::fabs(g.z - want.z) <= tol;
    t.check(ok, [&] {
        return what + " should be " + show(want) + " ± " + num(static_cast<double>(tol)) + " in every coordinate; yours is " +
               show(p);
    });
}

/// True when every coordinate of `p` is NaN or `p` is NaN_point (an unknown box corner).
inline bool unknown(const point& p) { return std::isnan(p.x) || std::isnan(p.y) || std::isnan(p.z); }

}  // namespace vl::stage03::hidden
