#pragma once
// Helpers shared by stage 04's hidden tests (grader only): probe objects of types your
// tracer has never seen, answer keys in long double, and ways to say in words what a
// trace() returned.
//
// Every object a test gives your tracer is a probe: an infinite plane with a chosen point,
// normal, interior and surface; a sphere whose hits are computed in long double; a root
// LIST that answers composite_only when nothing is hit; a watcher that is never hit but
// writes down every ray the tracer asks the scene about (so a test can read the direction
// of a reflected or transmitted ray). The tracer can reach them only through
// rtab_component, as the contract asks.
//
// "Emitters": with no lights and ambient (1, 1, 1), an object with kdr 1 and nothing else
// returns exactly its clr() (ambient * c * kdr), so a test can see which object a bounced
// ray reached by its colour. The bounce tests grade only what the bounces add: your
// trace() of a ray minus your trace() of the same ray with the mirror's or the glass's
// ksr and kst set to 0 (its own light), against the weights times what your tracer shows
// for the emitter itself. So a mistake in the local light does not cost points there.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <functional>
#include <limits>
#include <memory>
#include <mutex>
#include <numbers>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "02-sphere/tests/test_support.hh"
#include "04-shading/tests/test_support.hh"
#include "grading.hh"
#include "long_double.hh"
#include "stage_04.hh"
#include "vl/object_list.hh"
#include "vl/primitive.hh"
#include "vl/scene.hh"
#include "vl/tracer.hh"

namespace vl::stage04::hidden {

using grading::num;
using grading::real;
using grading::rvec;
using grading::show;
using grading::to_point;
using grading::to_r;
using grading::to_vector;
using stage02::testing::ray_through;

// --- long-double vectors and colours --------------------------------------------------------

/// A point or direction in words; a coordinate below 1e-15 of the largest is shown as 0.
inline std::string show(const rvec& a) {
    const real big = std::max({std::fabs(a.x), std::fabs(a.y), std::fabs(a.z)});
    const auto one = [&](real x) { return num(std::fabs(x) < 1e-15L * big ? 0.0 : static_cast<double>(x)); };
    return "(" + one(a.x) + ", " + one(a.y) + ", " + one(a.z) + ")";
}
inline real degrees(real radians) { return radians * 180 / std::numbers::pi_v<real>; }
inline real radians(real deg) { return deg * std::numbers::pi_v<real> / 180; }

/// A colour in long double (red, green, blue; alpha is not graded).
struct rgb {
    real r = 0, g = 0, b = 0;
};
inline rgb of(const color& c) { return {c.r, c.g, c.b}; }
inline rgb operator+(const rgb& x, const rgb& y) { return {x.r + y.r, x.g + y.g, x.b + y.b}; }
inline rgb operator*(const rgb& x, const rgb& y) { return {x.r * y.r, x.g * y.g, x.b * y.b}; }
inline rgb operator*(real s, const rgb& x) { return {s * x.r, s * x.g, s * x.b}; }
inline std::string show(const rgb& c) {
    return "(" + num(static_cast<double>(c.r)) + ", " + num(static_cast<double>(c.g)) + ", " +
           num(static_cast<double>(c.b)) + ")";
}
inline std::string show(const color& c) { return "(" + num(c.r) + ", " + num(c.g) + ", " + num(c.b) + ")"; }

/// True when each of red, green and blue of `got` is within `tol` of `want` (never NaN).
inline bool same(const color& got, const rgb& want, real tol) {
    return std::fabs(got.r - want.r) <= tol && std::fabs(got.g - want.g) <= tol && std::fabs(got.b - want.b) <= tol;
}
/// True when `got` and `want` differ by at most `tol` in each channel.
inline bool same(const color& got, const color& want, double tol) {
    return std::fabs(got.r - want.r) <= tol && std::fabs(got.g - want.g) <= tol && std::fabs(got.b - want.b) <= tol;
}

// --- Fresnel, both ways -----------------------------------------------------------------------

/// The reflectance where a ray in a medium of index eta1 meets one of index eta2, with
/// `cos_i` the cosine of its angle of incidence; 1 for total internal reflection: Schlick's
/// approximation with the cosine on the side of the lower index, and the exact Fresnel
/// equations for unpolarised light (the public tests' formulas, in long double).
inline real schlick(real eta1, real eta2, real cos_i) { return testing::schlick<real>(eta1, eta2, cos_i); }
inline real fresnel_exact(real eta1, real eta2, real cos_i) { return testing::fresnel_exact<real>(eta1, eta2, cos_i); }
/// What the contract accepts for F: anything between Schlick's value and the exact one,
/// widened by 0.02 on each side.
struct band {
    real lo = 0, hi = 0;
    bool holds(real x) const { return x >= lo && x <= hi; }
    /// "between LO and HI", to as many significant digits as keep each end within a
    /// thousandth of the band's width of its value (at least 4).
    std::string words() const {
        const real width = hi - lo, size = std::max(std::fabs(lo), std::fabs(hi));
        int digits = 17;  // a band of one value, or an end that is not finite: every digit
        if (width > 0 && size > 0 && std::isfinite(width) && std::isfinite(size))
            digits = static_cast<int>(std::clamp(std::ceil(std::log10(size / width)) + 3, 4.0L, 17.0L));
        return "between " + rounded(lo, digits) + " and " + rounded(hi, digits);
    }
    static std::string rounded(real x, int digits) {
        char buf[64];
        std::snprintf(buf, sizeof buf, "%.*g", digits, static_cast<double>(x));
        return buf;
    }
};
inline band fresnel_band(real eta1, real eta2, real cos_i) {
    const real s = schlick(eta1, eta2, cos_i), e = fresnel_exact(eta1, eta2, cos_i);
    return {std::min(s, e) - 0.02L, std::max(s, e) + 0.02L};
}
/// The transmitted weight kst (1 - F) for F in `f`.
inline band transmitted_weight(const band& f, real kst) { return {kst * (1 - f.hi), kst * (1 - f.lo)}; }

/// \brief A common mistake, and the weight it gives: when a failed check's value is that
/// weight, the message names the mistake as the likely cause.
struct suspect {
    band weight;
    std::string mistake;
};
/// The usual mistakes in w_t = kst (1 - F) from index `eta1` into `eta2` at incidence
/// cosine `cos_i` (Schlick, stage_04.hh step 5): the cosine taken on the wrong side of the
/// surface, R0 not squared, kst F in place of kst (1 - F), and kst with no F. Each weight
/// is the mistake's value within 0.005; check_bounced names one only where its weight lies
/// wholly outside the right one's band (near the normal, the two cosines give nearly the
/// same F).
inline std::vector<suspect> transmitted_suspects(real eta1, real eta2, real cos_i, real kst) {
    const real eta = eta1 / eta2, k = 1 - eta * eta * (1 - cos_i * cos_i);
    std::vector<suspect> out;
    if (k < 0) return out;  // total internal reflection: nothing is transmitted
    const real cos_t = std::sqrt(k), right_cos = eta1 <= eta2 ? cos_i : cos_t, wrong_cos = eta1 <= eta2 ? cos_t : cos_i;
    const real r0 = ((eta1 - eta2) / (eta1 + eta2)) * ((eta1 - eta2) / (eta1 + eta2));
    const real unsquared = (eta1 - eta2) / (eta1 + eta2);
    const auto f = [](real r, real c) { return r + (1 - r) * std::pow(1 - c, 5); };
    const auto near = [&](real w) { return band{w - 0.005L, w + 0.005L}; };
    out.push_back({near(kst * (1 - f(r0, wrong_cos))),
                   std::string("Schlick's F with the cosine on the wrong side (") +
                       (eta1 <= eta2 ? "cos_t, in the glass; entering glass it takes cos_i, in the air)"
                                     : "cos_i, in the glass; leaving glass it takes cos_t, in the air)")});
    out.push_back({near(kst * (1 - f(unsquared, right_cos))), "Schlick's F with R0 = (n1 - n2) / (n1 + n2), not squared"});
    out.push_back({near(kst * f(r0, right_cos)), "kst F, the reflected share, in place of kst (1 - F)"});
    out.push_back({near(kst), "kst alone, without the (1 - F) that Fresnel's reflection leaves"});
    return out;
}

/// Snell's law in long double: the transmitted direction of unit `d` at a surface whose
/// unit normal `n` faces the incoming ray (d.n < 0); `total` when there is none.
struct snell {
    bool total = true;
    rvec t;
};
inline snell refract(const rvec& d, const rvec& n, real eta1, real eta2) {
    const real eta = eta1 / eta2, cos_i = -dot(d, n), k = 1 - eta * eta * (1 - cos_i * cos_i);
    snell out;
    if (k < 0) return out;
    out.total = false;
    out.t = eta * d + (eta * cos_i - std::sqrt(k)) * n;
    return out;
}
/// The mirror direction of `d` about `n`.
inline rvec mirror(const rvec& d, const rvec& n) { return d - (2 * dot(d, n)) * n; }

// --- surfaces ---------------------------------------------------------------------------------

/// A surface from its values (the rest "absent").
inline surface make_surface(const color& c, double kdr, double ksr = 0, double kst = 0, double n = 1, double ior = 1,
                            double zero_t = rtab_component::default_zero_t) {
    surface s;
    s.clr = c;
    s.kdr = kdr;
    s.ksr = ksr;
    s.kst = kst;
    s.n = n;
    s.ior = ior;
    s.zero_t = zero_t;
    return s;
}
/// An emitter of colour `c`: under ambient (1, 1, 1) and no lights it returns exactly `c`.
inline surface emitter(const color& c) { return make_surface(c, 1); }
/// Glass of index `ior`: no diffuse part, `ksr` and `kst` as given (a clear pane by
/// default), in colour `c`.
inline surface glass(double ior, double ksr = 0, double kst = 1, const color& c = color(1, 1, 1)) {
    return make_surface(c, 0, ksr, kst, 1, ior);
}

/// Every surface value in words, for messages.
/// The surface in words: its colour and kdr, and each other value that is not the default.
inline std::string words(const surface& s) {
    std::string out = "color " + show(s.clr) + ", kdr " + num(s.kdr);
    if (s.ksr != 0) out += ", ksr " + num(s.ksr);
    if (s.kst != 0) out += ", kst " + num(s.kst);
    if (s.n != 1) out += ", n " + num(s.n);
    if (s.ior != 1) out += ", ior " + num(s.ior);
    if (s.zero_t != rtab_component::default_zero_t) out += ", zero_t " + num(s.zero_t);
    return out;
}

// --- probes -----------------------------------------------------------------------------------

/// An infinite plane through `at` with the unit normal `normal` (made unit in long
/// double). Its interior is chosen: none (a thin sheet), or every point on the side its
/// normal points away from (a solid half-space, as a block of glass).
class probe_plane final : public primitive {
public:
    enum class interior { none, below };
    probe_plane(const point& at, const vector& normal, const surface& s, interior inside = interior::none,
                std::string name = "PROBEPLANE")
        : at_(to_r(at)), n_(unit(to_r(normal))), inside_(inside), name_(std::move(name)) {
        set_surface(s);
    }
    std::string type_name() const override { return name_; }
    vector normal(const point&) const override { return to_vector(n_); }
    bool contains(const point& p) const override {
        return inside_ == interior::below && dot(to_r(p) - at_, n_) < 0;
    }
    /// The first hit beyond |zero_t()| in long double, 0 for none.
    real exact_t(const ray& r) const {
        const rvec o = to_r(r.origin()), d = unit(to_r(r.direction()));
        const real dn = dot(d, n_);
        if (dn == 0) return 0;
        const real t = dot(at_ - o, n_) / dn;
        return t > std::fabs(static_cast<real>(zero_t())) ? t : 0;
    }
    const rvec& unit_normal() const { return n_; }
    std::string describe() const {
        return "the plane through " + show(at_) + " with the normal " + show(n_) +
               (inside_ == interior::below ? " (solid on the side away from its normal)" : " (a thin sheet)");
    }

private:
    intersection find_intersection(const ray& r) const override {
        const real t = exact_t(r);
        return t > 0 ? intersection::at(static_cast<double>(t), this) : intersection::none();
    }
    rvec at_, n_;
    interior inside_;
    std::string name_;
};

/// A solid sphere whose hits are computed in long double.
class probe_ball final : public primitive {
public:
    probe_ball(const point& center, double radius, const surface& s, std::string name = "PROBEBALL")
        : c_(to_r(center)), radius_(radius), name_(std::move(name)) {
        set_surface(s);
    }
    std::string type_name() const override { return name_; }
    vector normal(const point& p) const override { return to_vector(unit(to_r(p) - c_)); }
    /// Inside: nearer the centre than the radius, or than radius * (1 + slack) when a test
    /// wants the points of the surface itself to count as inside.
    bool contains(const point& p) const override { return len(to_r(p) - c_) < radius_ * (1 + slack); }
    real slack = 0;
    /// When > 0, only rays that start within this distance of the centre hit the sphere
    /// (so a test can light its inside without the sphere blocking its own light).
    real hit_only_from_within = 0;
    /// When true, only rays that start outside the sphere hit it: a ray that has entered
    /// it passes out through the far side unhindered (so light inside it never bounces
    /// for ever, whatever the depth).
    bool enter_only = false;
    point min_point() const override { return to_point(c_ - rvec{radius_, radius_, radius_}); }
    point max_point() const override { return to_point(c_ + rvec{radius_, radius_, radius_}); }
    real exact_t(const ray& r) const {
        const rvec o = to_r(r.origin()), d = unit(to_r(r.direction())), f = o - c_;
        if (hit_only_from_within > 0 && len(f) > hit_only_from_within) return 0;
        if (enter_only && len(f) < radius_) return 0;
        const real b = dot(f, d);
        const rvec side = f - b * d;
        const real rr = radius_, ls = len(side);
        const real disc = (rr - ls) * (rr + ls);
        if (disc < 0) return 0;
        const real q = -(b + std::copysign(std::sqrt(disc), b));
        const real cc = (len(f) - rr) * (len(f) + rr);
        real t0 = q == 0 ? 0 : cc / q, t1 = q;
        if (t0 > t1) std::swap(t0, t1);
        const real eps = std::fabs(static_cast<real>(zero_t()));
        if (t0 > eps) return t0;
        if (t1 > eps) return t1;
        return 0;
    }
    const rvec& centre() const { return c_; }
    double radius() const { return radius_; }
    std::string describe() const { return "the sphere around " + show(c_) + " of radius " + num(radius_); }

private:
    intersection find_intersection(const ray& r) const override {
        const real t = exact_t(r);
        return t > 0 ? intersection::at(static_cast<double>(t), this) : intersection::none();
    }
    rvec c_;
    double radius_;
    std::string name_;
};

/// \brief Never hit: writes down every ray the tracer asks the scene about (primary,
/// shadow, reflected, transmitted), in order.
class probe_watcher final : public primitive {
public:
    std::string type_name() const override { return "WATCHER"; }
    std::vector<ray> rays() const {
        std::lock_guard<std::mutex> lock(mutex_);
        return rays_;
    }
    void clear() {
        std::lock_guard<std::mutex> lock(mutex_);
        rays_.clear();
    }

private:
    intersection find_intersection(const ray& r) const override {
        std::lock_guard<std::mutex> lock(mutex_);
        rays_.push_back(r);
        return intersection::none();
    }
    mutable std::mutex mutex_;
    mutable std::vector<ray> rays_;
};

/// \brief A root LIST that, when none of its children is hit, answers composite_only
/// of itself (rule 2: as if the ray had entered its bound), never a plain miss.
class probe_root final : public object_list {
public:
    std::string type_name() const override { return "PROBEROOT"; }

private:
    intersection find_intersection(const ray& r) const override {
        const intersection i = nearest_child_hit(r);
        return i.hit() ? i : intersection::composite_only(this);
    }
};

// --- scenes and traces ------------------------------------------------------------------------

/// A scene built by a test: black ambient and background, no lights, until it says otherwise.
struct world {
    scene s;
    world() {
        s.ambient = BLACK;
        s.background = BLACK;
        s.lights.clear();
    }
    template <class P>
    P* add(std::unique_ptr<P> p) {
        P* raw = p.get();
        s.root->insert(std::move(p));
        return raw;
    }
    probe_plane* plane(const point& at, const vector& n, const surface& surf,
                       probe_plane::interior inside = probe_plane::interior::none) {
        return add(std::make_unique<probe_plane>(at, n, surf, inside));
    }
    probe_ball* ball(const point& c, double r, const surface& surf) {
        return add(std::make_unique<probe_ball>(c, r, surf));
    }
    probe_watcher* watcher() { return add(std::make_unique<probe_watcher>()); }
    void light(const color& c, const point& p) { s.lights.push_back(color_point(c, p)); }
    /// For bounce tests: emitters are seen as their colours.
    void emitters_shine() {
        s.ambient = color(1, 1, 1);
        s.lights.clear();
    }
};

/// What one trace() call gave: its colour, or what it threw.
struct traced {
    color c;
    std::string error;  ///< empty when trace() returned normally
    bool ok() const { return error.empty(); }
    std::string words() const { return ok() ? show(c) : error; }
};

/// Runs `f`, turning anything it throws into words.
template <class F>
std::string thrown_by(F&& f) {
    try {
        f();
    } catch (const std::exception& e) {
        return std::string("trace() threw: ") + e.what();
    } catch (...) {
        return "trace() threw something that is not a std::exception";
    }
    return "";
}

/// Your tracer for `w`'s scene (made by your make_whitted_tracer), traced once.
inline traced trace_in(const scene& s, const ray& r, int depth) {
    traced out;
    out.error = thrown_by([&] {
        const std::unique_ptr<tracer> t = make_whitted_tracer(s);
        out.c = t->trace(r, depth);
    });
    return out;
}
inline traced trace_with(const tracer& t, const ray& r, int depth) {
    traced out;
    out.error = thrown_by([&] { out.c = t.trace(r, depth); });
    return out;
}

/// What the bounces off `object` add to trace(r, depth): your trace() of r, minus your
/// trace() of the same ray with the object's ksr and kst set to 0 (its own light alone;
/// the bounce tests have no lights, so ksr's highlight is not in play).
struct bounced {
    traced all, local;
    color part;
    bool ok() const { return all.ok() && local.ok(); }
    std::string words() const {
        if (!all.ok()) return all.error;
        if (!local.ok()) return local.error + " (with ksr = kst = 0)";
        return show(part) + " (yours returned " + show(all.c) + ", and " + show(local.c) +
               " for the same ray with the surface's ksr and kst set to 0)";
    }
};
inline bounced bounce_part(const scene& s, primitive& object, const ray& r, int depth) {
    bounced out;
    out.all = trace_in(s, r, depth);
    const surface keep = object.surf();
    surface flat = keep;
    flat.ksr = 0;
    flat.kst = 0;
    object.set_surface(flat);
    out.local = trace_in(s, r, depth);
    object.set_surface(keep);
    if (out.ok()) out.part = out.all.c - out.local.c;
    return out;
}
/// True when the ray from `o` along unit `d` passes farther than `r` from `c`.
inline bool passes_by(const rvec& o, const rvec& d, const rvec& c, real r) {
    const real u = std::max(static_cast<real>(0), dot(c - o, d));
    return len(o + u * d - c) > r;
}

/// The hit point of a ray with a probe, in long double.
inline rvec hit_point(const ray& r, real t) { return to_r(r.origin()) + t * unit(to_r(r.direction())); }

/// Seeded random numbers (the public tests' generator).
using dice = stage02::testing::random_numbers;

/// The hidden suites' tally (grading.hh), whose report() here also fails a loop that
/// checked nothing.
class tally : public grading::tally {
public:
    using grading::tally::tally;
    /// Fails when more than `allowed` inputs went wrong (0: any), or none was checked.
    void report(int allowed = 0) const {
        if (tried() == 0) {
            FAIL_CHECK(what() << ": nothing was checked");
            return;
        }
        grading::tally::report(allowed);
    }
};

/// Checks one traced colour against `want` within `tol`; `asked` says what was traced.
inline void check_color(tally& t, const std::string& asked, const traced& got, const rgb& want, real tol) {
    t.check(got.ok() && same(got.c, want, tol), [&] {
        return "trace() should return " + show(want) + " ± " + num(static_cast<double>(tol)) + "; yours returned " +
               got.words() + ". Asked: " + asked;
    });
}

/// The rays in `log` that start within `tol` of `p` (the secondary rays of a hit at p).
inline std::vector<ray> rays_from(const std::vector<ray>& log, const rvec& p, real tol) {
    std::vector<ray> out;
    for (const ray& r : log)
        if (len(to_r(r.origin()) - p) <= tol) out.push_back(r);
    return out;
}
/// The rays of `log`, in words (at most the first 3).
inline std::string show_rays(const std::vector<ray>& rays) {
    if (rays.empty()) return "no ray";
    std::string s;
    for (std::size_t k = 0; k < rays.size() && k < 3; ++k) s += (k ? "; " : "") + show(rays[k]);
    if (rays.size() > 3) s += "; and " + std::to_string(rays.size() - 3) + " more";
    return s;
}
/// `from`, the rays of `log` that start within `tol` of the hit point `p`, in words. When
/// there is none but a ray of `log` starts near `p` (within 0.01 times the coordinates'
/// size), says how far the nearest one starts: a secondary ray offset by a fixed or too
/// large distance is cast, just not from where the contract says.
inline std::string show_rays(const std::vector<ray>& from, const std::vector<ray>& log, const rvec& p, real tol) {
    if (!from.empty()) return show_rays(from);
    const real scale = std::max(static_cast<real>(1), std::max({std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)}));
    const ray* nearest = nullptr;
    real distance = 0;
    for (const ray& r : log) {
        const real d = len(to_r(r.origin()) - p);
        if (d <= 0.01L * scale && (nearest == nullptr || d < distance)) {
            nearest = &r;
            distance = d;
        }
    }
    if (nearest == nullptr) return "no ray";
    return "no ray within " + num(static_cast<double>(tol)) + "; the nearest starts " +
           num(static_cast<double>(distance)) + " from the hit point, " + show(*nearest) +
           " (start a secondary ray at the hit point moved off the surface by delta = 1e-9 * max(1, |P.x|, |P.y|, "
           "|P.z|), as stage_04.hh says, not by a fixed or larger distance)";
}

/// Checks that your tracer shows an emitter (traced along `r`, depth 0) as a colour with
/// `channel` clearly lit (a tracer that returns black everywhere does not pass).
inline bool emitter_shows(tally& t, const scene& s, const ray& r, double color::*channel, const std::string& what,
                          traced& seen) {
    seen = trace_in(s, r, 0);
    const bool ok = seen.ok() && seen.c.*channel > 0.2 && seen.c.*channel < 2;
    t.check(ok, [&] {
        return "the emitter itself (" + what + ", kdr 1 under ambient (1, 1, 1), no lights) should show its colour; "
               "yours returned " + seen.words() + " for " + show(r) + " aimed straight at it, at depth 0";
    });
    return ok;
}

// --- the optics bench: a block of glass and emitters placed where the rays go ---------------

/// \brief Glass fills y < 0 (the plane y = 0 with the normal (0, 1, 0), solid below it).
/// A ray meets it at the origin, from above (entering) or from below (leaving). There are
/// no lights and the ambient light is (1, 1, 1); emitters (kdr 1) are added where a test
/// wants to see light arrive:
/// - red_green(): a red emitter plane on the side the reflected ray goes to, a green one on
///   the side the transmitted ray goes to (for the tests that read the rays themselves);
/// - both_sides(): a green emitter plane on each side, so what comes back is
///   (w_r + w_t) times green, whichever way the light goes;
/// - mirror_side(): a red emitter plane on the reflected side only: w_r times red;
/// - patch(r): only a small green emitter ball where Snell's transmitted ray lands, away
///   from every other line the light could take: w_t times green.
/// The bounces' part of a trace is graded (see bounce_part), never the glass's own light.
struct bench {
    world w;
    probe_plane* glass = nullptr;
    const probe_watcher* watch = nullptr;
    bool inside = false;
    surface glass_surface;
    std::string layout = "no emitters";
    rvec land;  ///< the patch's centre
    rvec toward;  ///< the transmitted direction that reaches it
    static constexpr real patch_radius = 0.01L;

    /// `from_inside`: the rays start inside the glass (below y = 0) and go up.
    bench(const surface& s, bool from_inside) : inside(from_inside), glass_surface(s) {
        w.emitters_shine();
        glass = w.plane(point(0, 0, 0), vector(0, 1, 0), s, probe_plane::interior::below);
        watch = w.watcher();
    }
    /// The y of the ray's own side (+2 entering) and of the far side.
    double near_y() const { return inside ? -2 : 2; }
    double far_y() const { return -near_y(); }
    void red_green() {
        w.plane(point(0, near_y(), 0), vector(0, inside ? 1 : -1, 0), emitter(color(1, 0, 0)));
        w.plane(point(0, far_y(), 0), vector(0, inside ? -1 : 1, 0), emitter(color(0, 1, 0)));
        layout = "the reflected ray sees a red emitter plane, the transmitted one a green one";
    }
    void both_sides() {
        w.plane(point(0, near_y(), 0), vector(0, inside ? 1 : -1, 0), emitter(color(0, 1, 0)));
        w.plane(point(0, far_y(), 0), vector(0, inside ? -1 : 1, 0), emitter(color(0, 1, 0)));
        layout = "a green emitter plane on each side of the surface, so the bounces bring back (w_r + w_t) * green";
    }
    void mirror_side() {
        w.plane(point(0, near_y(), 0), vector(0, inside ? 1 : -1, 0), emitter(color(1, 0, 0)));
        layout = "a red emitter plane on the reflected side only, so the bounces bring back w_r * red";
    }
    /// A small green emitter where Snell's transmitted ray of `r` lands, 4 from the surface;
    /// false when there is no transmitted ray or another line of light passes near it.
    bool patch(const ray& r, const color& c = color(0, 1, 0)) {
        const rvec d = unit(to_r(r.direction())), p = hit(r);
        const snell s = refract(d, facing(), eta1(), eta2());
        if (s.total) return false;
        toward = unit(s.t);
        land = p + 4.0L * toward;
        if (!passes_by(p, d, land, 3 * patch_radius) || !passes_by(p, mirror(d, facing()), land, 3 * patch_radius))
            return false;
        w.ball(to_point(land), static_cast<double>(patch_radius), emitter(c));
        layout = "only a small emitter " + show(c) + " of radius " + num(static_cast<double>(patch_radius)) + " at " +
                 show(land) + ", where Snell's transmitted ray lands: the bounces bring back w_t times it";
        return true;
    }
    /// The ray along the transmitted direction, aimed straight at the patch.
    ray at_patch() const { return ray(to_point(land - 0.5L * toward), to_vector(toward)); }
    /// A ray aimed straight at the emitter plane on the ray's own side (the reflected side).
    ray at_near_side() const { return ray(point(0, near_y() / 2, 0), vector(0, inside ? -1 : 1, 0)); }
    /// The ray that meets the surface at the origin at `theta` (radians) from the normal,
    /// turned by `phi` about it, starting 1 away.
    ray at_angle(real theta, real phi = 0) const {
        const rvec d{std::sin(theta) * std::cos(phi), (inside ? 1 : -1) * std::cos(theta), std::sin(theta) * std::sin(phi)};
        return ray(to_point(-1.0L * d), to_vector(d));
    }
    /// The indices on the ray's side and the far side.
    real eta1() const { return inside ? glass_surface.ior : 1; }
    real eta2() const { return inside ? 1 : glass_surface.ior; }
    /// The normal facing the ray (flipped when it starts inside).
    rvec facing() const { return inside ? rvec{0, -1, 0} : rvec{0, 1, 0}; }
    /// The cosine of the angle of incidence of `r`, in long double.
    real cos_i(const ray& r) const { return -dot(unit(to_r(r.direction())), facing()); }
    /// The hit point of `r` on the glass.
    rvec hit(const ray& r) const { return hit_point(r, glass->exact_t(r)); }
    /// What the glass's bounces add to trace(r, depth).
    bounced bounces(const ray& r, int depth) { return bounce_part(w.s, *glass, r, depth); }
    /// Words for a message.
    std::string about(const ray& r, int depth) const {
        return show(r) + " at depth " + std::to_string(depth) + (inside ? " starts inside" : " comes from outside") +
               " glass filling y < 0 (" + words(glass_surface) + ") and meets it at " +
               num(static_cast<double>(degrees(std::acos(std::min(static_cast<real>(1), cos_i(r)))))) +
               " degrees from the normal (no lights, ambient 1; " + layout + ")";
    }
};

/// Asks `b` for its patch where `r`'s transmitted ray lands (bench::patch()) and checks
/// that it could be placed.
inline bool placed_patch(tally& t, bench& b, const ray& r, const color& c = color(0, 1, 0)) {
    return t.check(b.patch(r, c), [] { return std::string("the test's patch could not be placed"); });
}

/// A band scaled by `k` >= 0 and widened by `tol`.
inline band scaled(const band& b, real k, real tol = 1e-9L) { return {b.lo * k - tol, b.hi * k + tol}; }

/// Checks what the bounces of `b`'s glass add to trace(r, depth) in one channel of an
/// emitter seen along `at`: `weight` times your tracer's colour of that emitter, the other
/// channels 0.
inline void check_bounced(tally& t, bench& b, const ray& r, int depth, const ray& at, double color::*channel,
                          const band& weight, const std::string& name, const std::string& rule,
                          const std::vector<suspect>& suspects = {}) {
    traced seen;
    if (!emitter_shows(t, b.w.s, at, channel, name, seen)) return;
    const bounced got = b.bounces(r, depth);
    const band want = scaled(weight, seen.c.*channel);
    bool ok = got.ok() && want.holds(got.part.*channel);
    for (double color::*other : {&color::r, &color::g, &color::b})
        if (other != channel) ok = ok && got.ok() && std::fabs(got.part.*other - seen.c.*other * (got.part.*channel / seen.c.*channel)) <= 1e-9;
    const std::string channel_name = channel == &color::r ? "red" : channel == &color::g ? "green" : "blue";
    t.check(ok, [&] {
        // What matters first (a report quotes the first 500 characters): the rule, the
        // weight it asks for, yours, and the likely mistake; then the ray; then how w is read.
        std::string yours = got.words();
        if (got.ok()) {
            yours = band::rounded(got.part.*channel / seen.c.*channel, 6);
            if (want.holds(got.part.*channel)) yours += ", but the other channels are not 0 (below)";
            for (const suspect& s : suspects)  // named only where it cannot be mistaken for the right weight
                if ((s.weight.hi < weight.lo || s.weight.lo > weight.hi) &&
                    scaled(s.weight, seen.c.*channel).holds(got.part.*channel)) {
                    yours += ", the w of " + s.mistake;
                    break;
                }
        }
        return rule + ": w " + weight.words() + "; yours is " + yours + ". Asked: " + b.about(r, depth) +
               ". (w is what the bounces bring back, in " + channel_name + ", over what your tracer shows for " + name +
               ", " + show(seen.c) + ", the other channels 0: " + channel_name + " " + want.words() +
               "; they brought back " + got.words() + ".)";
    });
}
/// w_t alone, read on the patch where the transmitted ray lands.
inline void check_transmitted_weight(tally& t, bench& b, const ray& r, int depth, const band& w_t,
                                     const std::string& rule, const std::vector<suspect>& suspects = {}) {
    check_bounced(t, b, r, depth, b.at_patch(), &color::g, w_t, "the green patch", "w_t = kst (1 - F); " + rule,
                  suspects);
}
/// w_r + w_t, read with an emitter on each side.
inline void check_total_weight(tally& t, bench& b, const ray& r, int depth, const band& total, const std::string& rule) {
    check_bounced(t, b, r, depth, b.at_near_side(), &color::g, total, "the green emitter planes", "w_r + w_t; " + rule);
}

}  // namespace vl::stage04::hidden
