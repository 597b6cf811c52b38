#pragma once
// Helpers shared by stage 02's hidden tests (grader only): independent answer keys in
// long double, a tally that reports the first few failing inputs of a sweep, and readers
// for scene text.

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <numbers>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "grading.hh"
#include "stage_02.hh"
#include "vl/error.hh"
#include "vl/registry.hh"
#include "vl/scene_reader.hh"

namespace vl::stage02::hidden {

using grading::num;
using grading::show;

using real = long double;

// --- words -------------------------------------------------------------------------------

/// What an intersect() returned, in words.
inline std::string show(const intersection& i, const rtab_component* object) {
    if (i.object == nullptr && i.t == 0) return "a miss";
    if (i.object == nullptr) return "no object with t = " + num(i.t) + " (a miss must be intersection::none())";
    if (i.object != object) return "a hit at t = " + num(i.t) + " naming another object";
    if (!(i.t > 0)) return "t = " + num(i.t) + " (not a hit: t must be > 0)";
    return "a hit at t = " + num(i.t);
}

/// A primitive's answer is a hit at a finite distance > 0, on `object`.
inline bool clean_hit(const intersection& i, const rtab_component* object) {
    return i.object == object && std::isfinite(i.t) && i.t > 0;
}

/// A primitive's answer is intersection::none(): no object, no distance.
inline bool clean_miss(const intersection& i) { return i.object == nullptr && i.t == 0; }

/// A hit on `object` at t within `tolerance` of `want`.
inline bool hit_near(const intersection& i, const rtab_component* object, double want, double tolerance) {
    return clean_hit(i, object) && std::fabs(i.t - want) <= tolerance;
}

/// Counts the inputs of a sweep and keeps the first three failures in words; report()
/// fails the test once, with the count and those three.
class tally {
public:
    explicit tally(std::string what) : what_(std::move(what)) {}

    /// Records one input; when `ok` is false, `describe()` says what went wrong.
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
    void report_sweep_point(double x) const { vl::grading::sweep_point(x, tried_, failed_, first_failure()); }

    /// Passes when nothing failed; otherwise one failure per example kept (each read on
    /// its own), then the count.
    void report() const {
        if (failed_ == 0) {
            SUCCEED();
            return;
        }
        for (const std::string& e : examples_) FAIL_CHECK(e);
        FAIL_CHECK(what_ << ": " << failed_ << " of " << tried_ << " went wrong"
                         << (failed_ > 3 ? " (the first 3 are above)" : " (above)"));
    }

private:
    std::string what_;
    std::vector<std::string> examples_;
    int failed_ = 0, tried_ = 0;
};

// --- random inputs -----------------------------------------------------------------------

/// The ray from `from` through `to`.
inline ray through(const point& from, const point& to) { return ray(from, to - from); }

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

/// A surface with every key set to a value that needs all 17 digits.
inline surface full_precision_surface(double zero_t) {
    surface s;
    s.clr = color(0.1 + 1e-13, 1.0 / 3, 2.0 / 3 + 1e-12, 1.0 / 7);
    s.kdr = 0.7 + 1e-14;
    s.ksr = 1.0 / 3;
    s.kdt = 1e-7 / 3;
    s.kst = 0.2 + 3e-15;
    s.n = 123456.789012345;
    s.ior = 1.5 + 1e-13;
    s.zero_t = zero_t;
    return s;
}

// --- independent answer keys (long double) -----------------------------------------------

struct rvec {
    real x = 0, y = 0, z = 0;
};
inline rvec to_r(const point& p) {
    const point h = p.homogenized();
    return {h.x, h.y, h.z};
}
inline rvec to_r(const vector& v) { return {v.x, v.y, v.z}; }
inline rvec operator-(const rvec& a, const rvec& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline rvec operator+(const rvec& a, const rvec& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline rvec operator*(real s, const rvec& a) { return {s * a.x, s * a.y, s * a.z}; }
inline real dot(const rvec& a, const rvec& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline rvec cross(const rvec& a, const rvec& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline real len(const rvec& a) { return std::sqrt(dot(a, a)); }
inline rvec unit(const rvec& a) { return (1 / len(a)) * a; }

/// Where the line of `r` meets the sphere: both roots t0 <= t1 (stable formulas), or none.
struct sphere_roots {
    bool meets = false;
    real t0 = 0, t1 = 0;
    real scale = 0;  ///< |origin - center| + radius: what a double computation's error scales with
};
inline sphere_roots sphere_oracle(const point& center, double radius, const ray& r) {
    const rvec f = to_r(r.origin()) - to_r(center), d = unit(to_r(r.direction()));
    const real rr = radius;
    const real b = dot(f, d);
    const rvec l = f - b * d;
    const real disc = rr * rr - dot(l, l);
    sphere_roots out;
    out.scale = len(f) + rr;
    if (disc < 0) return out;
    const real q = -(b + std::copysign(std::sqrt(disc), b));
    const real c = (len(f) - rr) * (len(f) + rr);
    real t0 = q == 0 ? 0 : c / q, t1 = q;
    if (t0 > t1) std::swap(t0, t1);
    out.meets = true;
    out.t0 = t0;
    out.t1 = t1;
    return out;
}

/// The distance along `r` to the plane through `p0` with normal `n`; NaN when parallel.
inline real plane_oracle(const point& p0, const vector& n, const ray& r) {
    const rvec nn = to_r(n), d = unit(to_r(r.direction()));
    const real den = dot(d, nn);
    if (den == 0) return std::numeric_limits<real>::quiet_NaN();
    return dot(to_r(p0) - to_r(r.origin()), nn) / den;
}

/// The line of `r` against the plane of triangle a b c: the distance t and the
/// barycentric coordinates (wa, wb, wc) of the point where it meets that plane.
struct triangle_answer {
    bool meets = false;  ///< false when the ray is parallel to the plane
    real t = 0, wa = 0, wb = 0, wc = 0;
    real min_weight() const { return std::min({wa, wb, wc}); }
};
inline triangle_answer triangle_oracle(const point& a, const point& b, const point& c, const ray& r) {
    const rvec A = to_r(a), e1 = to_r(b) - A, e2 = to_r(c) - A, o = to_r(r.origin()), d = unit(to_r(r.direction()));
    const rvec p = cross(d, e2);
    const real det = dot(e1, p);
    triangle_answer out;
    if (det == 0) return out;
    const rvec s = o - A;
    const real u = dot(s, p) / det;
    const rvec q = cross(s, e1);
    const real v = dot(d, q) / det;
    out.meets = true;
    out.t = dot(e2, q) / det;
    out.wb = u;
    out.wc = v;
    out.wa = 1 - u - v;
    return out;
}

/// The line of `r` against a convex planar polygon: t, and how far inside the hit point
/// is, as the smallest signed distance to an edge's line divided by the polygon's box
/// diagonal (> 0 inside, < 0 outside).
struct polygon_answer {
    bool meets = false;
    real t = 0, inside = 0;
};
inline rvec newell(const std::vector<point>& v) {
    rvec n;
    rvec c;
    for (const point& p : v) c = c + to_r(p);
    c = (1 / static_cast<real>(v.size())) * c;
    for (std::size_t i = 0; i < v.size(); ++i) n = n + cross(to_r(v[i]) - c, to_r(v[(i + 1) % v.size()]) - c);
    return n;
}
inline polygon_answer polygon_oracle(const std::vector<point>& v, const ray& r) {
    const rvec n = unit(newell(v)), o = to_r(r.origin()), d = unit(to_r(r.direction()));
    polygon_answer out;
    const real den = dot(d, n);
    if (den == 0) return out;
    out.meets = true;
    out.t = dot(to_r(v[0]) - o, n) / den;
    const rvec hit = o + out.t * d;
    rvec lo = to_r(v[0]), hi = lo;
    for (const point& p : v) {
        const rvec q = to_r(p);
        lo = {std::min(lo.x, q.x), std::min(lo.y, q.y), std::min(lo.z, q.z)};
        hi = {std::max(hi.x, q.x), std::max(hi.y, q.y), std::max(hi.z, q.z)};
    }
    const real diagonal = len(hi - lo);
    real inside = std::numeric_limits<real>::infinity();
    for (std::size_t i = 0; i < v.size(); ++i) {
        const rvec a = to_r(v[i]), b = to_r(v[(i + 1) % v.size()]);
        const rvec edge = b - a;
        inside = std::min(inside, dot(cross(edge, hit - a), n) / len(edge));
    }
    out.inside = inside / diagonal;
    return out;
}

/// |got - want| within `ulps` units in the last place of `want` (at least of the smallest
/// normal double, so 0 compares with tiny numbers).
inline bool within_ulps(double got, double want, double ulps) {
    const double unit_in_last_place =
        std::max(std::fabs(want) * std::numeric_limits<double>::epsilon(), std::numeric_limits<double>::min());
    return std::fabs(got - want) <= ulps * unit_in_last_place;
}

/// How far `got` is from the unit vector of `want`, component by component.
inline double unit_gap(const vector& got, const vector& want) {
    const rvec w = unit(to_r(want));
    return static_cast<double>(std::max({std::fabs(got.x - w.x), std::fabs(got.y - w.y), std::fabs(got.z - w.z)}));
}

// --- scene text --------------------------------------------------------------------------

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

/// The message of the vl::file_error that reading `text` throws, or what happened instead.
inline std::string read_error(const std::string& text) {
    try {
        read_one(text);
    } catch (const file_error& e) {
        return e.what();
    } catch (const std::exception& e) {
        return std::string("(not a vl::file_error: ") + e.what() + ")";
    }
    return "(no error: the object was read)";
}

/// What a write() wrote, read by the tests' own reader (not yours): the type, each
/// geometric key's numbers, the surface, and whether the text held one object only.
struct written_object {
    std::string type;
    std::map<std::string, std::vector<double>> keys;  ///< a point's x y z, a vector's x y z, a number
    std::vector<point> vertices;
    surface surf;
    bool one_object = false;
    std::string problem;  ///< why the text could not be read, or ""
};

namespace detail {

/// Reads a stage 02 object's keys into a written_object.
class probe final : public primitive {
public:
    probe(std::string type, written_object* out, std::map<std::string, std::vector<double>> defaults,
          std::vector<point> vertices)
        : type_(std::move(type)), out_(out), defaults_(std::move(defaults)), vertices_(std::move(vertices)) {}
    std::string type_name() const override { return type_; }
    void read(scene_reader& in) override {
        out_->keys = defaults_;
        out_->vertices = vertices_;
        std::vector<scene_reader::property> props;
        for (const auto& [key, value] : defaults_) {
            const std::string k = key;
            props.push_back({std::string_view(key), [this, &in, k] {
                                 std::vector<double>& slot = out_->keys[k];
                                 if (slot.size() == 1) {
                                     slot[0] = in.read_number(k);
                                 } else if (k == "normal") {
                                     const vector v = in.read_vector(k);
                                     slot = {v.x, v.y, v.z};
                                 } else {
                                     const point p = in.read_point(k).homogenized();
                                     slot = {p.x, p.y, p.z};
                                 }
                             }});
        }
        if (type_ == "POLYGON")
            props.push_back({"vertices", [this, &in] {
                                 out_->vertices.clear();
                                 while (in.peek().type == token::kind::punct && in.peek().text == "(")
                                     out_->vertices.push_back(in.read_point("vertex").homogenized());
                             }});
        read_with_surface(in, props);
        out_->surf = surf();
    }
    void write(std::ostream&) const override {}

private:
    intersection find_intersection(const ray&) const override { return intersection::none(); }
    std::string type_;
    written_object* out_;
    std::map<std::string, std::vector<double>> defaults_;
    std::vector<point> vertices_;
};

}  // namespace detail

/// Reads `text` (what a write() wrote) with the tests' own reader, which knows each
/// type's keys and defaults as the contract gives them.
inline written_object parse_written(const std::string& text) {
    written_object out;
    registry types;
    types.add("SPHERE", [&out] {
        return std::make_unique<detail::probe>("SPHERE", &out,
                                               std::map<std::string, std::vector<double>>{{"center", {0, 0, 0}}, {"radius", {1}}},
                                               std::vector<point>{});
    });
    types.add("PLANE", [&out] {
        return std::make_unique<detail::probe>(
            "PLANE", &out, std::map<std::string, std::vector<double>>{{"point", {0, 0, 0}}, {"normal", {0, 1, 0}}},
            std::vector<point>{});
    });
    types.add("TRIANGLE", [&out] {
        return std::make_unique<detail::probe>(
            "TRIANGLE", &out,
            std::map<std::string, std::vector<double>>{{"a", {0, 0, 0}}, {"b", {1, 0, 0}}, {"c", {0, 1, 0}}},
            std::vector<point>{});
    });
    types.add("POLYGON", [&out] {
        return std::make_unique<detail::probe>(
            "POLYGON", &out, std::map<std::string, std::vector<double>>{},
            std::vector<point>{point(0, 0, 0), point(1, 0, 0), point(1, 1, 0), point(0, 1, 0)});
    });
    try {
        scene_reader in(types);
        in.open_text(text, "written.ray_trace");
        const auto object = in.read_object();
        out.type = object->type_name();
        out.one_object = in.at_end();
    } catch (const std::exception& e) {
        out.problem = e.what();
    }
    return out;
}

/// Compares each surface key of `got` with `want` to 4 ulps; appends a line per difference.
inline void compare_surface(const surface& got, const surface& want, const std::string& who, tally& t) {
    const std::pair<const char*, std::pair<double, double>> keys[] = {
        {"color red", {got.clr.r, want.clr.r}},   {"color green", {got.clr.g, want.clr.g}},
        {"color blue", {got.clr.b, want.clr.b}},  {"color alpha", {got.clr.a, want.clr.a}},
        {"kdr", {got.kdr, want.kdr}},             {"ksr", {got.ksr, want.ksr}},
        {"kdt", {got.kdt, want.kdt}},             {"kst", {got.kst, want.kst}},
        {"n", {got.n, want.n}},                   {"ior", {got.ior, want.ior}},
        {"zero_t", {got.zero_t, want.zero_t}},
    };
    for (const auto& [name, values] : keys)
        t.check(within_ulps(values.first, values.second, 4), [&, name = name, values = values] {
            return who + " has " + name + " " + num(values.first) + " where the object had " + num(values.second) +
                   " (allowed: 4 units in the last place)";
        });
}

/// The surface getters of an object, as a vl::surface.
inline surface surface_of(const rtab_component& o) {
    surface s;
    s.clr = o.clr();
    s.kdr = o.kdr();
    s.ksr = o.ksr();
    s.kdt = o.kdt();
    s.kst = o.kst();
    s.n = o.n();
    s.ior = o.ior();
    s.zero_t = o.zero_t();
    return s;
}

/// Checks that `make` throws vl::usage_error; says what happened otherwise.
template <class Make>
void expect_usage_error(tally& t, const std::string& call, Make&& make) {
    std::string happened;
    try {
        const auto object = make();
        happened = "it returned an object";
    } catch (const usage_error&) {
        happened = "";
    } catch (const std::exception& e) {
        happened = std::string("it threw another exception: ") + e.what();
    }
    t.check(happened.empty(), [&] { return call + " should throw vl::usage_error; " + happened; });
}

}  // namespace vl::stage02::hidden
