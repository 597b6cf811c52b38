// Hidden tests of robustness: no "shadow acne" where objects have zero_t 0, however far
// from the origin the scene is, and one tracer shared by threads. Each TEST_CASE is one
// graded item in the rubric's "robust" category. These tests compare your tracer with
// itself: a scene far from the origin (camera, lights and objects moved together, every
// object with zero_t 0) must show the same colours as the same scene at the origin with
// the default zero_t, on nearly every ray of a grid; a tracer used by two threads at once
// must give exactly the colours it gives one thread. So a mistake in a shading term alone
// does not cost points here; a secondary ray that hits the surface it leaves does.
#include "vl/catch.hh"

#include <atomic>
#include <cmath>
#include <functional>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "hidden_support.hh"

using vl::color;
using vl::point;
using vl::ray;
using vl::surface;
using vl::vector;
using namespace vl::stage04::hidden;

namespace {

/// Builds a scene moved by `offset`, its objects' zero_t set to `zero_t`.
using builder = std::function<void(world&, const vector& offset, double zero_t)>;

surface with_zero_t(surface s, double zero_t) {
    s.zero_t = zero_t;
    return s;
}

/// Floor, back wall and side wall, all planes; a light; some of them shiny.
void planes_scene(world& w, const vector& o, double zero_t) {
    w.s.ambient = color(0.1, 0.1, 0.1);
    w.light(color(0.9, 0.9, 0.8), point(2, 4, 3) + o);
    w.light(color(0.3, 0.3, 0.4), point(-2, 3, 4) + o);
    w.plane(point(0, 0, 0) + o, vector(0, 1, 0), with_zero_t(make_surface(color(0.9, 0.8, 0.6), 0.6, 0.3, 0, 10), zero_t));
    w.plane(point(0, 0, -4) + o, vector(0, 0, 1), with_zero_t(make_surface(color(0.6, 0.7, 0.9), 0.5, 0.4, 0, 30), zero_t));
    w.plane(point(-3, 0, 0) + o, vector(1, 0.1, 0), with_zero_t(make_surface(color(0.8, 0.5, 0.5), 0.7), zero_t));
}

/// Spheres, diffuse, shiny and a mirror, over a diffuse floor sphere (a huge one).
void spheres_scene(world& w, const vector& o, double zero_t) {
    w.s.ambient = color(0.1, 0.1, 0.1);
    w.s.background = color(0.2, 0.3, 0.5);
    w.light(color(1, 1, 1), point(3, 5, 4) + o);
    w.ball(point(0, -100, 0) + o, 100, with_zero_t(make_surface(color(0.7, 0.7, 0.6), 0.8, 0.2, 0, 5), zero_t));
    w.ball(point(-1.2, 0.7, 0) + o, 0.7, with_zero_t(make_surface(color(0.9, 0.3, 0.2), 0.7, 0.3, 0, 20), zero_t));
    w.ball(point(0.9, 0.6, -0.5) + o, 0.6, with_zero_t(make_surface(color(0.9, 0.9, 0.9), 0.1, 0.8, 0, 50), zero_t));
    w.ball(point(0.2, 0.3, 1.0) + o, 0.3, with_zero_t(make_surface(color(0.3, 0.8, 0.4), 0.9), zero_t));
}

/// Two glass spheres over a lit floor, before a mirror-like wall. The glass spheres are
/// hit only by rays from outside (a ray that has entered one passes out through its far
/// side unhindered), so no ray bounces inside them for ever.
void glass_scene(world& w, const vector& o, double zero_t) {
    w.s.ambient = color(0.15, 0.15, 0.15);
    w.s.background = color(0.3, 0.4, 0.6);
    w.light(color(1, 1, 1), point(-2, 6, 5) + o);
    w.plane(point(0, 0, 0) + o, vector(0, 1, 0), with_zero_t(make_surface(color(0.8, 0.7, 0.5), 0.8), zero_t));
    w.plane(point(0, 0, -5) + o, vector(0, 0, 1), with_zero_t(make_surface(color(0.7, 0.8, 1), 0.3, 0.6), zero_t));
    w.ball(point(0, 1, 0) + o, 1, with_zero_t(make_surface(color(1, 1, 1), 0, 0.05, 0.95, 100, 1.5), zero_t))
        ->enter_only = true;
    w.ball(point(1.8, 0.5, 0.8) + o, 0.5, with_zero_t(make_surface(color(0.9, 1, 0.9), 0, 0.1, 0.9, 100, 1.33), zero_t))
        ->enter_only = true;
}

/// The eye and a grid of rays through the scene (before moving).
std::vector<ray> grid_rays(const vector& o, int n) {
    std::vector<ray> out;
    const point eye = point(0.3, 2.2, 6) + o;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const point target = point(-3 + 6.0 * (i + 0.5) / n, 2.5 - 3.5 * (j + 0.5) / n, 0) + o;
            out.push_back(ray_through(eye, target));
        }
    return out;
}

std::vector<traced> trace_all(const vl::tracer& t, const std::vector<ray>& rays, int depth) {
    std::vector<traced> out;
    out.reserve(rays.size());
    for (const ray& r : rays) out.push_back(trace_with(t, r, depth));
    return out;
}

/// The scene at the origin (default zero_t) against the same scene moved by 1 .. 1e6
/// (zero_t 0): nearly every ray the same colour.
void check_far(const builder& build, const std::string& what, double tol) {
    const vector toward(0.48, 0.6, -0.64);
    const int n = 20, depth = 4;
    world home;
    build(home, vector(0, 0, 0), vl::rtab_component::default_zero_t);
    const std::vector<ray> home_rays = grid_rays(vector(0, 0, 0), n);
    const std::vector<traced> want = trace_all(*vl::stage04::make_whitted_tracer(home.s), home_rays, depth);
    for (const double distance : {1.0, 1e2, 1e4, 1e6}) {
        const vector o = distance * toward;
        tally t(what + " moved " + num(distance) + " from the origin, every object with zero_t 0, against the same scene at the origin");
        world far;
        build(far, o, 0);
        const std::vector<ray> rays = grid_rays(o, n);
        const std::unique_ptr<vl::tracer> tracer = vl::stage04::make_whitted_tracer(far.s);
        for (std::size_t k = 0; k < rays.size(); ++k) {
            const traced got = trace_with(*tracer, rays[k], depth);
            t.check(got.ok() && want[k].ok() && same(got.c, want[k].c, tol), [&] {
                return "trace() should return what the same ray gives at the origin, " + want[k].words() + " ± " +
                       num(tol) + "; yours returned " + got.words() +
                       " (a secondary ray that hits the surface it leaves? Start it off the surface, by an amount "
                       "relative to the size of the coordinates). Asked: " + show(rays[k]) + " at depth " +
                       std::to_string(depth) + " in " + what + " moved by " + show(o) + " (zero_t 0)";
            });
        }
        t.report(static_cast<int>(rays.size()) / 100);  // 1% may differ: edges of shadows and silhouettes
    }
}

}  // namespace

TEST_CASE("robust: planes with zero_t 0 show no acne from 1 to 1e6 away from the origin", "[04][robust][essential]") {
    check_far(planes_scene, "a floor and two walls (planes) under two lights", 1e-3);
}

TEST_CASE("robust: spheres with zero_t 0 show no acne from 1 to 1e6 away from the origin", "[04][robust][essential]") {
    check_far(spheres_scene, "diffuse, shiny and mirror spheres on a huge sphere under a light", 1e-3);
}

TEST_CASE("robust: glass and mirrors with zero_t 0 show no acne from 1 to 1e6 away from the origin", "[04][robust]") {
    // Light through glass far away takes paths that start 1e-3 off each surface (the offset
    // grows with the coordinates), so its colours may move a little more.
    check_far(glass_scene, "two glass spheres over a floor before a mirror-like wall", 1e-2);
}

TEST_CASE("robust: one tracer used by two threads at once gives the colours it gives one thread", "[04][robust][essential]") {
    tally t("rays traced by two threads at once");
    world w;
    glass_scene(w, vector(0, 0, 0), vl::rtab_component::default_zero_t);
    w.light(color(0.4, 0.3, 0.3), point(3, 3, 3));
    const std::vector<ray> rays = grid_rays(vector(0, 0, 0), 24);
    const std::unique_ptr<vl::tracer> tracer = vl::stage04::make_whitted_tracer(w.s);
    const std::vector<traced> want = trace_all(*tracer, rays, 5);
    std::vector<std::vector<traced>> got(2);
    std::atomic<int> ready{0};
    std::vector<std::thread> threads;
    for (int k = 0; k < 2; ++k)
        threads.emplace_back([&, k] {
            ready.fetch_add(1);
            while (ready.load() < 2) std::this_thread::yield();
            // The two threads go through the rays in opposite orders.
            std::vector<traced>& mine = got[static_cast<std::size_t>(k)];
            mine.resize(rays.size());
            for (std::size_t i = 0; i < rays.size(); ++i) {
                const std::size_t j = k == 0 ? i : rays.size() - 1 - i;
                mine[j] = trace_with(*tracer, rays[j], 5);
            }
        });
    for (std::thread& th : threads) th.join();
    for (int k = 0; k < 2; ++k)
        for (std::size_t i = 0; i < rays.size(); ++i) {
            const traced& g = got[static_cast<std::size_t>(k)][i];
            t.check(g.ok() && want[i].ok() && g.c.r == want[i].c.r && g.c.g == want[i].c.g && g.c.b == want[i].c.b, [&] {
                return "trace() should return exactly what one thread got, " + want[i].words() + "; yours returned " +
                       g.words() + " (a tracer keeps no state between calls). Asked: " + show(rays[i]) +
                       " at depth 5, traced by thread " + std::to_string(k + 1) +
                       " while another thread used the same tracer";
            });
        }
    t.report();
}

TEST_CASE("robust: the same ray traced again - after other rays - gives the same colour", "[04][robust][detail]") {
    tally t("rays traced twice");
    world w;
    spheres_scene(w, vector(0, 0, 0), vl::rtab_component::default_zero_t);
    const std::vector<ray> rays = grid_rays(vector(0, 0, 0), 12);
    const std::unique_ptr<vl::tracer> tracer = vl::stage04::make_whitted_tracer(w.s);
    const std::vector<traced> first = trace_all(*tracer, rays, 3);
    for (std::size_t i = rays.size(); i-- > 0;) {
        const traced again = trace_with(*tracer, rays[i], 3);
        t.check(again.ok() && first[i].ok() && again.c.r == first[i].c.r && again.c.g == first[i].c.g &&
                    again.c.b == first[i].c.b,
                [&] {
                    return show(rays[i]) + " at depth 3 gave " + first[i].words() + " the first time and " + again.words() +
                           " the second: trace() keeps no state between calls";
                });
    }
    t.report();
}

TEST_CASE("robust: objects are used only through rtab_component - whatever their type_name() says", "[04][robust][detail]") {
    tally t("objects whose type names lie");
    // The same scene twice: once with probes named as probes, once with the same probes
    // calling themselves SPHERE, PLANE and POLYGON. Nothing may change.
    const auto build = [](world& w, bool lying) {
        w.s.ambient = color(0.1, 0.1, 0.1);
        w.light(color(1, 1, 1), point(2, 5, 3));
        w.add(std::make_unique<probe_plane>(point(0, 0, 0), vector(0, 1, 0), make_surface(color(0.8, 0.8, 0.7), 0.7, 0.3, 0, 10),
                                            probe_plane::interior::none, lying ? "SPHERE" : "PROBEPLANE"));
        w.add(std::make_unique<probe_ball>(point(0, 1, 0), 1, make_surface(color(1, 1, 1), 0, 0.1, 0.9, 50, 1.5),
                                           lying ? "PLANE" : "PROBEBALL"))
            ->enter_only = true;  // a ray that has entered it passes out unhindered
        w.add(std::make_unique<probe_ball>(point(1.5, 0.5, -1), 0.5, make_surface(color(0.9, 0.4, 0.3), 0.3, 0.7, 0, 40),
                                           lying ? "POLYGON" : "PROBEBALL"));
    };
    world honest, lying;
    build(honest, false);
    build(lying, true);
    const std::vector<ray> rays = grid_rays(vector(0, 0, 0), 12);
    const std::vector<traced> want = trace_all(*vl::stage04::make_whitted_tracer(honest.s), rays, 4);
    const std::vector<traced> got = trace_all(*vl::stage04::make_whitted_tracer(lying.s), rays, 4);
    for (std::size_t i = 0; i < rays.size(); ++i)
        t.check(got[i].ok() && want[i].ok() && same(got[i].c, want[i].c, 0.0), [&] {
            return show(rays[i]) + " at depth 4 gave " + want[i].words() +
                   " with objects of types your code has never seen, and " + got[i].words() +
                   " with the same objects calling themselves SPHERE, PLANE and POLYGON: the tracer must not ask "
                   "what it hit";
        });
    t.report();
}
