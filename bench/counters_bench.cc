// What the always-on intersection counters cost.
//
// The same leaf test (a ray against a sphere, the most common primitive test) run three
// ways over the same rays:
//   baseline  a virtual call through a non-counting wrapper (what the thesis did with
//             _INTRSCT_PRFM off);
//   counted   rtab_component::intersect(), which counts in thread-local counters;
//   list      an object_list of 64 spheres, counted at every level.
// The overhead of counting is counted / baseline - 1; the goal is under 3%.
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include "vl/object_list.hh"
#include "vl/rt_base_objects.hh"

namespace {

// Geometric ray-sphere test, enough to give the call realistic work.
inline vl::intersection sphere_hit(const vl::ray& r, const vl::point& c, double radius, const void* self) {
    const vl::vector oc = r.origin() - c;
    const double b = oc * r.direction();
    const double disc = b * b - (oc * oc - radius * radius);
    if (disc < 0) return vl::intersection::none();
    const double t = -b - std::sqrt(disc);
    return t > 1e-6 ? vl::intersection::at(t, static_cast<const vl::rtab_component*>(self)) : vl::intersection::none();
}

class counted_sphere final : public vl::rtab_component {
public:
    counted_sphere(vl::point c, double r) : c_(c), r_(r) {}
    std::string type_name() const override { return "SPHERE"; }

private:
    vl::intersection find_intersection(const vl::ray& r) const override { return sphere_hit(r, c_, r_, this); }
    vl::point c_;
    double r_;
};

// The same shape of code without counting: public non-virtual -> private virtual.
class uncounted_base {
public:
    virtual ~uncounted_base() = default;
    vl::intersection intersect(const vl::ray& r) const { return find_intersection(r); }

private:
    virtual vl::intersection find_intersection(const vl::ray& r) const = 0;
};

class uncounted_sphere final : public uncounted_base {
public:
    uncounted_sphere(vl::point c, double r) : c_(c), r_(r) {}

private:
    vl::intersection find_intersection(const vl::ray& r) const override { return sphere_hit(r, c_, r_, this); }
    vl::point c_;
    double r_;
};

std::vector<vl::ray> make_rays(std::size_t n) {
    std::mt19937_64 rng(42);
    std::uniform_real_distribution<double> u(-1, 1);
    std::vector<vl::ray> rays;
    for (std::size_t k = 0; k < n; ++k) rays.emplace_back(vl::point(u(rng), u(rng), 5), vl::vector(u(rng) * 0.2, u(rng) * 0.2, -1));
    return rays;
}

const std::vector<vl::ray>& rays() {
    static const std::vector<vl::ray> r = make_rays(4096);
    return r;
}

template <class Sphere>
std::vector<std::unique_ptr<Sphere>> make_spheres() {
    std::vector<std::unique_ptr<Sphere>> s;
    for (int k = 0; k < 64; ++k) s.push_back(std::make_unique<Sphere>(vl::point((k % 8) * 0.25 - 1, (k / 8) * 0.25 - 1, 0), 0.1));
    return s;
}

void baseline_uncounted(benchmark::State& state) {
    const auto spheres = make_spheres<uncounted_sphere>();
    std::vector<const uncounted_base*> list;
    for (const auto& s : spheres) list.push_back(s.get());
    for (auto _ : state) {
        for (const vl::ray& r : rays()) {
            vl::intersection best;
            for (const uncounted_base* s : list) {
                const vl::intersection i = s->intersect(r);
                if (i.nearer_than(best)) best = i;
            }
            benchmark::DoNotOptimize(best);
        }
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * rays().size() * list.size()));
}

void counted_intersect(benchmark::State& state) {
    const auto spheres = make_spheres<counted_sphere>();
    std::vector<const vl::rtab_component*> list;
    for (const auto& s : spheres) list.push_back(s.get());
    for (auto _ : state) {
        for (const vl::ray& r : rays()) {
            vl::intersection best;
            for (const vl::rtab_component* s : list) {
                const vl::intersection i = s->intersect(r);
                if (i.nearer_than(best)) best = i;
            }
            benchmark::DoNotOptimize(best);
        }
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * rays().size() * list.size()));
}

void counted_object_list(benchmark::State& state) {
    vl::object_list list;
    for (auto& s : make_spheres<counted_sphere>()) list.insert(std::move(s));
    for (auto _ : state) {
        for (const vl::ray& r : rays()) benchmark::DoNotOptimize(list.intersect(r));
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * rays().size() * list.num_children()));
}

}  // namespace

// Interleaved repetitions so both see the same machine state; compare the medians.
BENCHMARK(baseline_uncounted)->Repetitions(5)->ReportAggregatesOnly(true);
BENCHMARK(counted_intersect)->Repetitions(5)->ReportAggregatesOnly(true);
BENCHMARK(counted_object_list)->Repetitions(5)->ReportAggregatesOnly(true);
BENCHMARK_MAIN();
