#pragma once
// A ray's own frame, built by Gram-Schmidt from the coordinate axis least aligned with
// the ray, and the watertight triangle test in it: the ray is the frame's +z axis and
// passes through a triangle when its three 2D edge functions at (0, 0) agree in sign.

#include <optional>

#include "vl/ray.hh"

namespace vl::stage02 {

struct in_frame {
    double x = 0, y = 0, z = 0;
};

class frame {
public:
    explicit frame(const ray& r);
    in_frame operator()(const point& p) const;

private:
    point o_;
    vector x_, y_, z_;
};

/// t at which the ray crosses the triangle a b c (given in the ray's frame), if it does.
std::optional<double> crossing(const in_frame& a, const in_frame& b, const in_frame& c);

}  // namespace vl::stage02
