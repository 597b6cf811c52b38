#pragma once
// Helpers shared by stage 02's hidden tests (grader only): independent answer keys in
// long double, and the tests' own reader of what a write() wrote. What the public tests
// have (ray_through(), random numbers, reading scene text) comes from their helpers
// (assignments/02-sphere/tests/test_support.hh), what every hidden suite has (the tally,
// long-double vectors, surfaces) from grader/hidden/common.

#include <algorithm>
#include <cmath>
#include <functional>
#include <initializer_list>
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

#include "02-sphere/tests/test_support.hh"
#include "grading.hh"
#include "long_double.hh"
#include "stage_02.hh"
#include "surfaces.hh"
#include "vl/error.hh"
#include "vl/registry.hh"
#include "vl/scene_reader.hh"

namespace vl::stage02::hidden {

using grading::full_precision_surface;
using grading::num;
using grading::real;
using grading::rvec;
using grading::show;
using grading::surface_of;
using grading::surface_text;
using grading::tally;
using grading::to_r;
using testing::box_of_polygons;
using testing::ray_through;
/// Seeded random numbers (the public tests' generator, with seeds of the hidden tests' own).
using sampler = testing::random_numbers;

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

/// For each of `rays`, whether it hits at least one of `objects` cleanly; all the rays are
/// asked at once (vl::grading::intersect_all), so a watertightness test of thousands of
/// rays crosses to the student's process a few times, not once per ray and face.
template <class Owned>
std::vector<bool> hits_any(const std::vector<Owned>& objects, const std::vector<ray>& rays) {
    std::vector<const rtab_component*> asked;
    for (const auto& o : objects) asked.push_back(o.get());
    const std::vector<intersection> hits = vl::grading::intersect_all(asked, rays);
    std::vector<bool> hit(rays.size(), false);
    for (std::size_t k = 0; k < rays.size(); ++k)
        for (std::size_t j = 0; j < asked.size(); ++j) hit[k] = clean_hit(hits[k * asked.size() + j], asked[j]) || hit[k];
    return hit;
}

/// A primitive's answer is intersection::none(): no object, no distance.
inline bool clean_miss(const intersection& i) { return i.object == nullptr && i.t == 0; }

/// A hit on `object` at t within `tolerance` of `want`.
inline bool hit_near(const intersection& i, const rtab_component* object, double want, double tolerance) {
    return clean_hit(i, object) && std::fabs(i.t - want) <= tolerance;
}

/// Checks that `got` (`who`, in words) answered `r` with `i` as `want` (a `type` made by its
/// factory) did with `w`: both hits, at t within `tol` and on `got`, or both clean misses.
inline void check_same_answer(tally& t, const ray& r, const rtab_component& got, const intersection& i,
                              const rtab_component& want, const intersection& w, double tol, const std::string& who,
                              const std::string& type) {
    const bool same = (i.hit() && w.hit() && std::fabs(i.t - w.t) <= tol && i.object == &got) ||
                      (clean_miss(i) && clean_miss(w));
    t.check(same, [&] {
        return show(r) + ": " + who + " returned " + show(i, &got) + " where the " + type + " returned " + show(w, &want) +
               " (± " + num(tol) + ")";
    });
}

/// Checks that `i`, what `o` answered to `r` (which comes `side`, in words, or ""), is a
/// hit at t = `want` ± `tol`. `described()` names the object in the message (called only
/// for one).
template <class Described>
void check_hit_at(tally& t, const intersection& i, const rtab_component& o, const ray& r, double want, double tol,
                  const Described& described, const std::string& side = "") {
    t.check(hit_near(i, &o, want, tol), [&] {
        return show(r) + side + " should hit " + described() + " at t = " + num(want) + " ± " + num(tol) +
               "; yours returned " + show(i, &o);
    });
}

// --- random inputs -----------------------------------------------------------------------

/// Two unit vectors spanning the plane perpendicular to `n`.
inline void plane_axes(const vector& n, vector& u, vector& v) {
    const vector helper = std::fabs(n.unit().x) < 0.6 ? vector(1, 0, 0) : vector(0, 1, 0);
    u = (n % helper).unit();
    v = (n.unit() % u).unit();
}

/// Checks that rays along each of `directions` (parallel to the flat object `o`, described
/// as `described`) miss it cleanly: through `on + offset n` for each of `offsets` (0: in
/// its plane), each ray once from 10 units back and once from that point.
inline void check_parallel_rays_miss(tally& t, const rtab_component& o, const std::string& described, const point& on,
                                     const vector& n, std::initializer_list<vector> directions,
                                     std::initializer_list<double> offsets) {
    for (const vector d : directions) {
        for (const double offset : offsets) {
            const point through = on + offset * n;
            // Starting outside and crossing the object's outline, and starting inside it.
            for (const ray& r : {ray(through - 10 * d.unit(), d), ray(through, d)}) {
                const intersection i = o.intersect(r);
                t.check(clean_miss(i), [&] {
                    return show(r) + " runs parallel to " + described + (offset == 0 ? " in its plane" : "") +
                           ": it should miss; yours returned " + show(i, &o);
                });
            }
        }
    }
}

/// Checks that `r`, which leaves a point of `o` (`described()`, called only for a message)
/// whose zero_t is `zero_t`, does not hit it again: a clean miss.
template <class Described>
void check_leaving_misses(tally& t, const rtab_component& o, const ray& r, double zero_t, const Described& described) {
    const intersection i = o.intersect(r);
    t.check(clean_miss(i), [&] {
        return show(r) + " starts on " + described() + " (zero_t = " + num(zero_t) +
               "): it should not hit it again; yours returned " + show(i, &o);
    });
}

/// A direction for a ray leaving a point of a flat object whose unit normal is `n` (`u` and
/// `v` span its plane): for an even `k` a grazing one, 10^lowest to 0.1 radians off the
/// plane (on the side of `n` when k % 4 == 0, else on the other), for an odd `k` any.
inline vector leaving_direction(sampler& random, int k, const vector& n, const vector& u, const vector& v,
                                double lowest) {
    vector d = random.direction();
    if (k % 2 == 0) {
        const double angle = std::pow(10.0, random.uniform(lowest, -1)) * (k % 4 == 0 ? 1 : -1);
        const double turn = random.uniform(0, 2 * std::numbers::pi);
        d = std::cos(angle) * (std::cos(turn) * u + std::sin(turn) * v) + std::sin(angle) * n;
    }
    return d;
}

// --- independent answer keys (long double) -----------------------------------------------

/// Where the line of `r` meets the sphere: both roots t0 <= t1 (stable formulas), or none.
struct sphere_key : grading::roots {
    real scale = 0;  ///< |origin - center| + radius: what a double computation's error scales with
};
inline sphere_key sphere_oracle(const point& center, double radius, const ray& r) {
    const rvec o = to_r(r.origin()), c = to_r(center);
    sphere_key out;
    static_cast<grading::roots&>(out) = grading::sphere_roots(o, unit(to_r(r.direction())), c, radius);
    out.scale = len(o - c) + radius;
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

/// \brief zero_t, positive or negative, hides a hit up to its absolute value: each of `rays`
/// meets `o` (`described`, as the messages say) at t = 0.3, so with each of a list of
/// zero_t it must hit there (± 1e-12) when |zero_t| < 0.3 and miss otherwise.
inline void check_zero_t_hides_hit_at_0_3(tally& t, primitive& o, const std::string& described,
                                          std::initializer_list<ray> rays) {
    for (const double zero_t : {0.0, 1e-6, -1e-6, 0.2, -0.2, 0.29, -0.29, 0.31, -0.31, 0.5, -0.5}) {
        o.set_surface(testing::with_zero_t(zero_t));
        for (const ray& r : rays) {
            const bool want = 0.3 > std::fabs(zero_t);
            const intersection i = o.intersect(r);
            t.check(want ? hit_near(i, &o, 0.3, 1e-12) : clean_miss(i), [&] {
                return show(r) + " meets " + described + " at t = 0.3; with zero_t = " + num(zero_t) + " it should " +
                       (want ? "hit there (± 1e-12)" : "miss") + "; yours returned " + show(i, &o);
            });
        }
    }
}

/// Checks that the box of `o` (`described` in words) runs exactly from `want_lo` to `want_hi`.
inline void check_exact_box(tally& t, const rtab_component& o, const std::string& described, const point& want_lo,
                            const point& want_hi) {
    const point lo = o.min_point(), hi = o.max_point();
    t.check(lo == want_lo && hi == want_hi, [&] {
        return "the box of " + described + " should run from " + show(want_lo) + " to " + show(want_hi) +
               "; yours runs from " + show(lo) + " to " + show(hi);
    });
}

/// Checks that the box of `got` (`who`) is the box of `want` within `slack`.
inline void check_same_box(tally& t, const rtab_component& got, const rtab_component& want, const std::string& who,
                           double slack) {
    const point lo = got.min_point(), hi = got.max_point(), wlo = want.min_point(), whi = want.max_point();
    t.check((lo - wlo).length() <= slack && (hi - whi).length() <= slack, [&] {
        return who + "'s box runs from " + show(lo) + " to " + show(hi) + "; it should run from " + show(wlo) + " to " +
               show(whi) + " (± " + num(slack) + ")";
    });
}

// --- scene text --------------------------------------------------------------------------

/// The types the tests read: stage 02's and the framework's.
inline const registry& test_types() {
    static const registry types = [] {
        registry r;
        register_framework(r);
        register_stage_02(r);
        return r;
    }();
    return types;
}

/// Reads one object from `text` (as the file "hidden.ray_trace").
inline std::unique_ptr<rtab_component> read_one(const std::string& text) {
    return testing::read_object(text, "hidden.ray_trace", test_types());
}

/// What write() writes.
inline std::string text_of(const rtab_component& o) { return testing::written(o); }

/// The message of the vl::file_error that reading `text` throws, or what happened instead.
inline std::string read_error(const std::string& text) {
    return grading::file_error_of([&] { read_one(text); });
}

/// Checks that each of `blocks` is refused with a vl::file_error at its place.
inline void check_refused(tally& t, std::initializer_list<grading::refused_block> blocks) {
    grading::check_refused(t, [](const std::string& text) { return read_error(text); }, blocks);
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
    for (const auto& [name, values] : grading::surface_keys(got, want))
        t.check(within_ulps(values.first, values.second, 4), [&, name = name, values = values] {
            return who + " has " + name + " " + num(values.first) + " where the object had " + num(values.second) +
                   " (allowed: 4 units in the last place)";
        });
}

/// Reads `text`, which describes `want` (a `type`) with the surface `surf`: what your read()
/// makes of it must have that surface and be the same object, as `same_object(got, what)`
/// checks.
template <class Object, class SameObject>
void check_read_as(tally& t, const std::string& text, const std::string& type, Object& want, const surface& surf,
                   SameObject&& same_object) {
    const auto got = read_one(text);
    want.set_surface(surf);
    const std::string what = "the " + type + " read from " + text;
    compare_surface(surface_of(*got), surf, what, t);
    same_object(*got, what);
}

/// \brief The round trip of a scene-file test: write() of `original` (an object of type
/// `type`, `described` in words) must be one `type` { ... } as the tests' own reader reads
/// it, with the keys `same_keys(w, who)` checks and the surface of `original` (to 4 ulps);
/// and what your read() makes of that text must be the same object, as
/// `same_object(back, what)` checks, with the same surface.
template <class Object, class SameKeys, class SameObject>
void check_write_reads_back(tally& t, const Object& original, const std::string& type, const std::string& described,
                            SameKeys&& same_keys, SameObject&& same_object) {
    const std::string text = text_of(original);
    const std::string who = "write() of " + described + " gave \"" + text + "\", which";
    // What the text says, read by the tests' own reader.
    const written_object w = parse_written(text);
    t.check(w.problem.empty() && w.type == type && w.one_object, [&] {
        return who + " should be one " + type + " { ... }; " + (w.problem.empty() ? "it is not" : w.problem);
    });
    if (w.problem.empty()) {
        same_keys(w, who);
        compare_surface(w.surf, original.surf(), who, t);
    }
    // What your read() makes of it: the same object.
    const auto back = read_one(text);
    const std::string what = "the " + type + " read back from \"" + text + "\"";
    compare_surface(surface_of(*back), original.surf(), what, t);
    same_object(*back, what);
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
