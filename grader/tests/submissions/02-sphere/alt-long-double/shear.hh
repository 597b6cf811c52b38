#pragma once
// Woop, Benthin and Wald's watertight test (JCGT 2(1), 2013) in long double: the ray's
// axes permuted so its largest component is z, the vertices sheared so the ray is +z.

#include <optional>

#include "vl/ray.hh"

namespace vl::stage02 {

struct sheared {
    long double x = 0, y = 0, z = 0;
};

class shear {
public:
    explicit shear(const ray& r);
    sheared operator()(const point& p) const;

private:
    long double ox_, oy_, oz_;
    int ix_, iy_, iz_;
    long double sx_, sy_, sz_;
};

/// Edge function of p -> q; exactly minus that of q -> p.
inline long double edge_of(const sheared& p, const sheared& q) { return p.x * q.y - p.y * q.x; }

/// t of the ray through the triangle a b c, if it passes through it (from either side).
std::optional<double> through_triangle(const sheared& a, const sheared& b, const sheared& c);

}  // namespace vl::stage02
