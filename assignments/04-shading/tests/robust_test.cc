// Public tests of robustness (stage_04.hh, "Leaving a surface without hitting it again",
// and make_whitted_tracer's promise to keep no state): no shadow acne, no self-reflection
// and no self-refraction for objects with zero_t 0 far from the origin, and one tracer
// shared by two threads. Run them with `build/student/stage_04_public_test "[robust]"`.
//
// The acne tests compare your tracer with itself: a scene moved far from the origin with
// zero_t 0 must look like the same scene at the origin with the default zero_t (1e-6),
// where round-off (about 1e-16) is far below zero_t and cannot cause acne. So they fail
// only when a secondary ray hits the surface it leaves.
#include "vl/catch.hh"

#include <exception>
#include <string>
#include <thread>
#include <vector>

#include "test_support.hh"

using namespace vl;
using namespace vl::stage04::testing;

namespace {

/// `x` as scene text, exactly (the shortest form that reads back as `x`).
std::string text(double x) { return num(x); }
std::string text(const point& p) { return text(p.x) + " " + text(p.y) + " " + text(p.z); }

/// A sphere standing on a floor, both moved by (D, D, D), in the scene format; `zero_t`
/// is written into both objects when `far` (the moved scene), left at its default else.
/// `sphere_extra` and `floor_extra` are added to the sphere's and the floor's surface keys.
/// With `lift` the sphere floats that high above the floor instead of standing on it.
scene sphere_on_floor(double d, bool far, const std::string& sphere_extra, const std::string& floor_extra, bool lit,
                      double lift = 0) {
    const vector move(d, d, d);
    const std::string zero = far ? " zero_t 0" : "";
    std::string s = "tracer whitted  ambient 0.1 0.1 0.1  background 0.2 0.3 0.5\n";
    if (lit) s += "light { color 1 1 1  position " + text(point(2, 6, 3) + move) + " }\n";
    s += "SPHERE { center " + text(point(0, 1 + lift, 0) + move) + " radius 1  color 1 0.8 0.6  kdr 0.8 " + sphere_extra + zero +
         " }\n";
    s += "PLANE { point " + text(point(0, 0, 0) + move) + " normal 0 1 0  color 0.6 0.7 0.8  kdr 0.6 " + floor_extra + zero +
         " }\n";
    return read_scene_text(s);
}

/// Rays from the eye (0, 2, 6) (moved by D) at a grid of points on and around the sphere.
std::vector<ray> rays_at(double d) {
    const vector move(d, d, d);
    std::vector<ray> rays;
    for (int i = -4; i <= 4; ++i)
        for (int j = -4; j <= 4; ++j)
            rays.push_back(ray_through(point(0, 2, 6) + move, point(0.3 * i, 1 + 0.3 * j, 0) + move));
    return rays;
}

/// Compares the scene moved by `d` (zero_t 0) with the same at the origin ray by ray;
/// "" when they agree within `tolerance`, else how many differ and the first three.
std::string differences(double d, const std::string& sphere_extra, const std::string& floor_extra, bool lit,
                        int depth, double tolerance) {
    const scene moved = sphere_on_floor(d, true, sphere_extra, floor_extra, lit),
                home = sphere_on_floor(0, false, sphere_extra, floor_extra, lit);
    const std::vector<ray> far_rays = rays_at(d), near_rays = rays_at(0);
    int wrong = 0;
    std::string first;
    for (std::size_t k = 0; k < far_rays.size(); ++k) {
        const color got = trace_in(moved, far_rays[k], depth), want = trace_in(home, near_rays[k], depth);
        if (!near(got, want, tolerance) && wrong++ < 3)
            first += "\n  " + show(far_rays[k]) + " gives " + show(got) + "; the same ray at the origin " + show(want);
    }
    if (wrong == 0) return "";
    return std::to_string(wrong) + " of " + std::to_string(far_rays.size()) + " rays differ by more than " +
           num(tolerance) + (wrong > 3 ? "; the first three:" : ":") + first;
}

}  // namespace

TEST_CASE("robust: no shadow acne on a sphere and a plane with zero_t 0 up to 1e6 from the origin", "[04][robust]") {
    // A lit sphere on a floor, both zero_t 0, moved to (D, D, D). The hit point P is
    // rounded by about 1e-16 |P|: half the time it lies just inside the surface, and a
    // shadow ray that starts exactly at P hits that surface again at a tiny t: the point
    // is wrongly in shadow (dark speckles). Start the shadow ray off the surface, on the
    // light's side, by an offset relative to |P| (the contract's delta).
    for (const double d : {1.0, 1e3, 1e6}) {
        const std::string diff = differences(d, "", "", true, 0, 1e-6);
        INFO("the scene moved to (" << num(d) << ", " << num(d) << ", " << num(d)
                                    << ") with zero_t 0, at depth 0, compared with the same scene at the origin: "
                                    << diff);
        CHECK(diff.empty());
    }
}

TEST_CASE("robust: mirrors and glass with zero_t 0 far from the origin do not see themselves", "[04][robust]") {
    // The same sphere and floor, unlit, at depth 3: the sphere a mirror (ksr 0.5), the
    // floor a mirror and partly glass (ksr 0.5, kst 0.4, ior 1.5; a plane, so the light
    // it lets through goes on down into the background). A reflected ray that starts at P
    // may hit the surface it leaves at a tiny t, and a transmitted ray may hit it again
    // instead of going through. Start reflected rays off the surface on N's side and
    // transmitted rays on the other side.
    // The colours may differ by up to 0.01: 1e6 from the origin the contract's offset
    // (1e-9 |P| = 1e-3) itself moves each secondary ray a little (the reference's
    // colours move far less). A ray that sees the surface it leaves is off by
    // far more, typically 0.05 to 0.7.
    for (const double d : {1.0, 1e3, 1e6}) {
        const std::string diff = differences(d, "ksr 0.5", "ksr 0.5 kst 0.4 ior 1.5", false, 3, 0.01);
        INFO("the mirror and glass scene moved to (" << num(d) << ", " << num(d) << ", " << num(d)
                                                     << ") with zero_t 0, at depth 3, compared with the same scene at "
                                                        "the origin: "
                                                     << diff);
        CHECK(diff.empty());
    }
}

TEST_CASE("robust: one tracer serves two threads at once", "[04][robust]") {
    // make_whitted_tracer's tracer keeps no state between calls: the render gives one
    // tracer to all its threads. Two threads trace the same 2000 rays through one tracer
    // at the same time; each must get exactly what one thread alone gets, bit for bit
    // (so a NaN that one thread alone gets too counts as the same). The scene: a lit
    // mirror sphere floating 0.5 above a floor that is a mirror and partly glass.
    const scene s = sphere_on_floor(0, false, "ksr 0.3 n 20", "ksr 0.3 kst 0.3 ior 1.3 n 20", true, 0.5);
    const auto tracer = pieces().make_tracer("whitted", s);
    std::vector<ray> rays;
    for (int k = 0; k < 2000; ++k) {
        const double a = k * 0.0031, b = k * 0.0017;
        rays.push_back(ray_through(point(0, 2, 6), point(2 * std::sin(a * 7), 1 + std::cos(b * 5), 0)));
    }
    std::vector<color> alone;
    for (const ray& r : rays) alone.push_back(tracer->trace(r, 4));

    std::vector<color> results[2];
    std::exception_ptr failure[2];
    std::vector<std::thread> threads;
    for (int which = 0; which < 2; ++which) {
        threads.emplace_back([&, which] {
            try {
                for (const ray& r : rays) results[which].push_back(tracer->trace(r, 4));
            } catch (...) {
                failure[which] = std::current_exception();
            }
        });
    }
    for (std::thread& t : threads) t.join();
    for (int which = 0; which < 2; ++which) {
        if (failure[which]) std::rethrow_exception(failure[which]);
        int wrong = 0;
        std::string first;
        for (std::size_t k = 0; k < rays.size(); ++k) {
            if (!same_bits(results[which][k], alone[k]) && wrong++ == 0)
                first = show(rays[k]) + " gave " + show(results[which][k]) + " in thread " + std::to_string(which) +
                        ", " + show(alone[k]) + " alone";
        }
        INFO(wrong << " of " << rays.size() << " rays traced by two threads at once differ from one thread alone"
                   << (wrong ? "; the first: " + first : std::string()));
        CHECK(wrong == 0);
    }
}
