// Stability sweeps of stage 04 (grader/hidden/common/grading.hh, sweep_point): each test
// moves one parameter to where naive methods break and reports, per value, how many of
// its fixed trials went wrong. The tests check nothing themselves; the rubric's [[sweep]]
// entries say over which values a correct tracer must not fail.
//
// - Acne: a lit surface with zero_t 0 (a plane or a large sphere, both mirrors) placed X
//   from the origin, X = 1 .. 1e8. A trial shades one point of it at depth 1; it fails
//   when a secondary ray (shadow or reflected) that leaves the surface on its normal's
//   side hits it again (in exact geometry none can), or the point comes out unlit though
//   the light sees it.
// - The critical angle: a ray leaving glass (a half-space) at the critical angle plus or
//   minus delta, delta = 1e-12 .. 0.1. A trial fails when total internal reflection is
//   decided wrongly (below the critical angle a transmitted ray must be cast besides the
//   reflected one, above it none: all secondary rays go one way), a secondary ray has a
//   NaN or non-unit direction, the colour is NaN, or light goes missing
//   (w_r + w_t < ksr + kst, read with a green emitter on each side). Which way the rays
//   go is graded by the other tests, so a wrong mirror direction or a normal not negated
//   inside does not fail this sweep.
#include "vl/catch.hh"

#include <cmath>
#include <functional>
#include <memory>
#include <mutex>
#include <utility>
#include <string>
#include <vector>

#include "hidden_support.hh"

using vl::color;
using vl::point;
using vl::ray;
using vl::surface;
using vl::vector;
using namespace vl::stage04::hidden;

namespace {

/// A probe (plane or ball) that writes down every hit it reports, with the ray asked.
template <class Probe>
class recording final : public vl::primitive {
public:
    template <class... Args>
    explicit recording(const surface& s, Args&&... args) : inner_(std::forward<Args>(args)..., s) {
        set_surface(s);
    }
    std::string type_name() const override { return "PROBESURFACE"; }
    vector normal(const point& p) const override { return inner_.normal(p); }
    bool contains(const point& p) const override { return inner_.contains(p); }
    point min_point() const override { return inner_.min_point(); }
    point max_point() const override { return inner_.max_point(); }
    std::vector<std::pair<ray, real>> hits() const {
        std::lock_guard<std::mutex> lock(mutex_);
        return hits_;
    }

private:
    vl::intersection find_intersection(const ray& r) const override {
        const real t = inner_.exact_t(r);
        if (!(t > 0)) return vl::intersection::none();
        std::lock_guard<std::mutex> lock(mutex_);
        hits_.push_back({r, t});
        return vl::intersection::at(static_cast<double>(t), this);
    }
    Probe inner_;
    mutable std::mutex mutex_;
    mutable std::vector<std::pair<ray, real>> hits_;
};

/// A unit vector at `elevation` (its cosine with n, in (0, 1]) above the plane of unit n,
/// turned by `phi` about n.
rvec above(const rvec& n, real elevation, real phi) {
    const rvec helper = std::fabs(n.x) < 0.6L ? rvec{1, 0, 0} : rvec{0, 1, 0};
    const rvec u = unit(helper - dot(helper, n) * n);
    const rvec v{n.y * u.z - n.z * u.y, n.z * u.x - n.x * u.z, n.x * u.y - n.y * u.x};
    const real s = std::sqrt(1 - elevation * elevation);
    return elevation * n + (s * std::cos(phi)) * u + (s * std::sin(phi)) * v;
}

rvec random_unit(dice& random) { return to_r(random.direction()); }

}  // namespace

TEST_CASE("sweep: no acne on lit planes and spheres with zero_t 0 from 1 to 1e8 away from the origin", "[04][sweep]") {
    dice random(4401);
    const int trials = 32;
    constexpr double radius = 100;
    for (const double distance : {1.0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8}) {
        long failures = 0;
        std::string example;
        for (int k = 0; k < trials; ++k) {
            // Every random number of the trial is drawn before anything is traced.
            const rvec centre = static_cast<real>(distance) * random_unit(random);
            const rvec n = random_unit(random);
            const rvec to_eye = above(n, random.uniform(0.3, 0.95), random.uniform(0, 6.28));
            const rvec to_light = above(n, random.uniform(0.3, 0.95), random.uniform(0, 6.28));
            const rvec aim = above(n, 0, random.uniform(0, 6.28));  // along the surface
            const real spread = random.uniform(0, 0.2);
            const bool sphere = k % 2 == 1;
            const rvec eye = centre + 3.0L * to_eye, target = centre + spread * aim;
            const rvec light = centre + 4.0L * to_light;
            std::string fault;
            try {
                world w;
                w.s.ambient = color(0.1, 0.1, 0.1);
                w.s.background = color(0, 0, 0);
                w.light(color(1, 1, 1), to_point(light));
                const surface s = make_surface(color(0.9, 0.8, 0.7), 0.7, 0.3, 0, 10, 1, 0.0);
                std::string what;
                std::function<std::vector<std::pair<ray, real>>()> hits;
                std::function<rvec(const point&)> outward;  // the surface's normal nearest a point
                if (sphere) {
                    const rvec c = centre - static_cast<real>(radius) * n;
                    auto* ball = w.add(std::make_unique<recording<probe_ball>>(s, to_point(c), radius));
                    hits = [ball] { return ball->hits(); };
                    outward = [c](const point& p) { return unit(to_r(p) - c); };
                    what = "the sphere around " + show(c) + " of radius " + num(radius);
                } else {
                    auto* plane = w.add(std::make_unique<recording<probe_plane>>(s, to_point(centre), to_vector(n)));
                    hits = [plane] { return plane->hits(); };
                    outward = [n](const point&) { return n; };
                    what = "the plane through " + show(centre) + " with the normal " + show(n);
                }
                what += " (color (0.9, 0.8, 0.7), kdr 0.7, ksr 0.3, n 10, zero_t 0) under a white light at " +
                        show(light) + ", the only object";
                const ray primary = ray_through(to_point(eye), to_point(target));
                const traced lit = trace_in(w.s, primary, 1);
                const std::vector<std::pair<ray, real>> seen = hits();
                w.s.lights.clear();
                const traced dark = trace_in(w.s, primary, 1);
                const std::string asked = show(primary) + " at depth 1 meets " + what + ", " + num(distance) +
                                          " from the origin";
                if (!lit.ok() || !dark.ok()) {
                    fault = (lit.ok() ? dark.error : lit.error) + ". Asked: " + asked;
                } else {
                    // A secondary ray (shadow or reflected) that leaves the surface on the side
                    // its normal faces can hit it again only when it starts on the wrong side
                    // of it: acne. (A ray cast into the surface, by a wrong mirror direction,
                    // is no acne and is graded with reflection.)
                    for (const auto& [r, t] : seen)
                        if (len(to_r(r.origin()) - eye) > 0.5L && dot(to_r(r.direction()), outward(r.origin())) > 0) {
                            const bool shadow_ray = len(unit(light - to_r(r.origin())) - to_r(r.direction())) < 0.05L;
                            fault = std::string(shadow_ray ? "the shadow ray" : "the reflected ray") + " from " +
                                    show(r.origin()) + " towards " + show(r.direction()) +
                                    " hit the surface it leaves at t = " + num(static_cast<double>(t)) +
                                    " (start it off the surface by an amount relative to the coordinates); your "
                                    "trace() returned " + lit.words() + " with the light and " + dark.words() +
                                    " without it. Asked: " + asked;
                            break;
                        }
                    const bool brighter = lit.c.r > dark.c.r + 1e-6 || lit.c.g > dark.c.g + 1e-6 || lit.c.b > dark.c.b + 1e-6;
                    if (fault.empty() && !brighter)
                        fault = "the point came out shadowed: your trace() returned " + lit.words() +
                                " with the light and the same, " + dark.words() +
                                ", without it, though nothing lies between the point and the light. Asked: " + asked;
                }
            } catch (...) {
                fault = "the test could not trace this point (something was thrown outside trace())";
            }
            if (!fault.empty()) {
                if (failures == 0) example = fault;
                ++failures;
            }
        }
        vl::grading::sweep_point(distance, trials, failures, example);
    }
}

TEST_CASE("sweep: total internal reflection decided right from 1e-12 to 0.1 radians either side of the critical angle",
          "[04][sweep]") {
    dice random(4402);
    const std::vector<double> iors{1.33, 1.5, 2.4};
    const int per_ior = 4;
    const long trials = static_cast<long>(iors.size()) * per_ior * 2;
    for (const double delta : {1e-12, 1e-11, 1e-10, 1e-9, 1e-8, 1e-7, 1e-6, 1e-5, 1e-4, 1e-3, 1e-2, 1e-1}) {
        long failures = 0;
        std::string example;
        for (const double ior : iors)
            for (int k = 0; k < per_ior; ++k) {
                const real phi = random.uniform(0, 6.28);
                const double ksr = k % 2 == 0 ? 0.0 : 0.1, kst = k % 2 == 0 ? 1.0 : 0.9;
                const real critical = std::asin(1 / static_cast<real>(ior));
                for (const int side : {-1, 1}) {
                    std::string fault;
                    try {
                        bench b(make_surface(color(1, 1, 1), 0, ksr, kst, 1, ior), true);
                        b.both_sides();
                        const ray r = b.at_angle(critical + side * static_cast<real>(delta), phi);
                        // The exact answer for the direction your tracer is given.
                        const real cos_i = b.cos_i(r), eta = static_cast<real>(ior);
                        const real kk = 1 - eta * eta * (1 - cos_i * cos_i);
                        const bool transmits = kk > 0;
                        const std::string asked =
                            num(delta) + " radians " + (side < 0 ? "below" : "beyond") + " the critical angle " +
                            num(static_cast<double>(degrees(critical))) + " degrees of glass of ior " + num(ior) +
                            " (k = " + num(static_cast<double>(kk)) + "): " + b.about(r, 3);
                        traced seen;
                        tally unused("emitter");
                        const bool emitter_ok = emitter_shows(unused, b.w.s, b.at_near_side(), &color::g,
                                                              "the green emitter planes", seen);
                        const bounced got = b.bounces(r, 3);
                        const std::vector<ray> from = rays_from(b.watch->rays(), b.hit(r), 1e-6L);
                        // The secondary rays from the hit point (there are no lights, so no shadow
                        // rays): beyond the critical angle all go one way, the reflected one;
                        // below it a transmitted ray goes another way. Which way each goes is
                        // graded elsewhere (Snell's law, the mirror direction), not here.
                        std::vector<rvec> ways;
                        const ray* bad_direction = nullptr;
                        for (const ray& x : from) {
                            const rvec xd = to_r(x.direction());
                            if (!std::isfinite(xd.x) || !std::isfinite(xd.y) || !std::isfinite(xd.z) ||
                                std::fabs(len(xd) - 1) > 1e-9L) {
                                if (!bad_direction) bad_direction = &x;
                                continue;
                            }
                            bool known = false;
                            for (const rvec& w : ways) known = known || len(xd - w) <= 1e-9L;
                            if (!known) ways.push_back(xd);
                        }
                        const int others = static_cast<int>(ways.size()) - 1;
                        const auto finite = [](const color& c) {
                            return std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b);
                        };
                        if (!emitter_ok) {
                            fault = "the emitter itself should show its colour (0, 1, 0); yours returned " + seen.words();
                        } else if (!got.ok()) {
                            fault = got.words() + ". Asked: " + asked;
                        } else if (!finite(got.all.c) || !finite(got.local.c)) {
                            fault = "trace() returned " + got.all.words() + ", not a number. Asked: " + asked;
                        } else if (bad_direction) {
                            fault = "your tracer cast a secondary ray from " + show(bad_direction->origin()) +
                                    " with the direction " + show(bad_direction->direction()) +
                                    ", not a unit vector. Asked: " + asked;
                        } else if (transmits && others < 1) {
                            fault = "below the critical angle the light must be transmitted, but your tracer cast no "
                                    "transmitted ray besides the reflected one (it cast " + show_rays(from, b.watch->rays(), b.hit(r), 1e-6L) +
                                    "). Asked: " + asked;
                        } else if (!transmits && others > 0) {
                            fault = "beyond the critical angle the light is totally internally reflected, but your "
                                    "tracer cast rays in " + std::to_string(others + 1) + " directions (" + show_rays(from) +
                                    "). Asked: " + asked;
                        } else if (got.part.g < (ksr + kst) * seen.c.g - 1e-6) {
                            fault = "light went missing: with a green emitter on each side the bounces should bring "
                                    "back (w_r + w_t) = ksr + kst = " + num(ksr + kst) + " times " + show(seen.c) +
                                    "; they brought back " + got.words() + ". Asked: " + asked;
                        }
                    } catch (...) {
                        fault = "the test could not trace this ray (something was thrown outside trace())";
                    }
                    if (!fault.empty()) {
                        if (failures == 0) example = fault;
                        ++failures;
                    }
                }
            }
        vl::grading::sweep_point(delta, trials, failures, example);
    }
}
