#pragma once
// Spheres for bench_counters, defined in bench_shapes.cc so that the benchmark loops see
// only the interfaces and must make a real virtual call for both the counted and the
// uncounted sphere (a class hierarchy visible in one file lets the compiler inline it).
#include <memory>

#include "vl/rt_base_objects.hh"

namespace bench {

/// The same shape of code as rtab_component without counting: public non-virtual ->
/// private virtual.
class uncounted_base {
public:
    virtual ~uncounted_base();
    vl::intersection intersect(const vl::ray& r) const { return find_intersection(r); }

private:
    virtual vl::intersection find_intersection(const vl::ray& r) const = 0;
};

std::unique_ptr<vl::rtab_component> make_counted_sphere(vl::point center, double radius);
std::unique_ptr<uncounted_base> make_uncounted_sphere(vl::point center, double radius);

}  // namespace bench
