// A chart of stage 03 (grader only): what each composite costs per ray as the scene grows.
// Tagged [chart]: it checks nothing and is worth no points; the rubric's [[chart]] draws
// the submission's points over the reference's in report.html. The x values (N) and the
// series names are fixed, so the submission's points line up with the reference's; the
// cost is counted (intersect() calls plus bound tests), never timed. A structure that
// throws is left out, so the others' curves still show. The series bvh-children is the
// BVH's children's tests alone: the probes count them in the judge, so no code of the
// submission's can change them (bound tests are declared by the code that makes them).
#include "vl/catch.hh"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "bvh_scenes.hh"

using vl::point;
using vl::ray;
using vl::rtab_composite;
using namespace vl::stage03::hidden;

namespace {

/// The N random spheres of `random_spheres` (the same centres and radius), as probes.
std::vector<std::unique_ptr<probe_sphere>> spheres(probe_set& set, std::size_t n, unsigned seed) {
    dice random(seed);
    const double r = small_radius(n);
    std::vector<std::unique_ptr<probe_sphere>> out;
    for (std::size_t k = 0; k < n; ++k) out.push_back(set.add(std::make_unique<probe_sphere>(random.in_cube(), r, true)));
    return out;
}

/// What a ray of `rays` costs at `c`, on average: every test (intersect() calls plus
/// bound tests), and the children's tests alone, which the children count themselves.
struct per_ray {
    double tests = 0;
    double children = 0;
};
per_ray cost_per_ray(const rtab_composite& c, const std::vector<ray>& rays) {
    std::uint64_t total = 0, children = 0;
    for (const ray& r : rays) {
        const cost k = measure([&] { (void)c.intersect(r); });
        total += k.counts.total_tests();
        children += k.probe;
    }
    const auto n = static_cast<double>(rays.size());
    return {static_cast<double>(total) / n, static_cast<double>(children) / n};
}
double tests_per_ray(const rtab_composite& c, const std::vector<ray>& rays) { return cost_per_ray(c, rays).tests; }

/// Reports `series` at N = `n` as `measure()` gives it. A structure that throws (a stub not
/// written yet, a refusal) is left out from there on, so the others' curves still show.
template <class F>
void point_of(std::set<std::string>& broken, const std::string& series, std::size_t n, F&& measure) {
    if (broken.contains(series)) return;
    try {
        const double y = measure();
        vl::grading::chart_point(series, static_cast<double>(n), y);
    } catch (const std::exception& e) {
        broken.insert(series);
        WARN(series << " left out of the chart from N = " << n << ": " << e.what());
    }
}

}  // namespace

TEST_CASE("chart: composites: tests per ray against the number of random spheres - per structure", "[03][chart]") {
    const std::vector<ray> rays = rays_through_cube(200, 901);
    const std::vector<ray> few_rays(rays.begin(), rays.begin() + 8);
    std::set<std::string> broken;
    for (std::size_t n = 16; n <= 4096; n *= 2) {
        const unsigned seed = 900 + static_cast<unsigned>(n);
        point_of(broken, "list", n, [&] {  // A LIST: every child, every ray.
            probe_set set;
            vl::object_list list;
            for (auto& s : spheres(set, n, seed)) list.insert(std::move(s));
            return tests_per_ray(list, rays);
        });
        point_of(broken, "bounding-sphere", n, [&] {  // One around them all: a ray that enters it tests every child.
            probe_set set;
            auto one = vl::stage03::make_bounding_sphere();
            for (auto& s : spheres(set, n, seed)) one->insert(std::move(s));
            // Its cost is all or nothing (1 + N for a ray that enters, 1 for one that
            // misses), and every ray here crosses the cube it holds, so a few rays tell it
            // as well as many once N is large (each child test crosses to the judge).
            return tests_per_ray(*one, n <= 64 ? rays : few_rays);
        });
        // Two levels: the cube cut into k^3 cells of about 8 spheres, each cell's spheres in a
        // bounding sphere, the cells in one bounding sphere.
        point_of(broken, "bounding-spheres-in-cells", n, [&] {
            probe_set set;
            const int k = std::max(1, static_cast<int>(std::lround(std::cbrt(static_cast<double>(n) / 8))));
            std::map<int, std::unique_ptr<rtab_composite>> cells;
            for (auto& s : spheres(set, n, seed)) {
                auto cell = [&](double v) { return std::clamp(static_cast<int>(v * k), 0, k - 1); };
                const point c = s->center();
                const int key = cell(c.x) + k * (cell(c.y) + k * cell(c.z));
                auto& group = cells[key];
                if (!group) group = vl::stage03::make_bounding_sphere();
                group->insert(std::move(s));
            }
            auto outer = vl::stage03::make_bounding_sphere();
            for (auto& [key, group] : cells) outer->insert(std::move(group));
            return tests_per_ray(*outer, rays);
        });
        // The BVH, leaf_size 4, and its children's tests alone: the leaderboard's series,
        // since the children count those themselves, where bound tests are what the BVH's
        // code says it made.
        double children = NAN;
        point_of(broken, "bvh", n, [&] {
            probe_set set;
            auto bvh = vl::stage03::make_bvh();
            for (auto& s : spheres(set, n, seed)) bvh->insert(std::move(s));
            const per_ray k = cost_per_ray(*bvh, rays);
            children = k.children;
            return k.tests;
        });
        if (!std::isnan(children)) vl::grading::chart_point("bvh-children", static_cast<double>(n), children);
    }
}
