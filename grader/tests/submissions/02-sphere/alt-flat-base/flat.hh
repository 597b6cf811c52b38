#pragma once
// What the triangle and the polygon share: a flat, convex loop of vertices with a normal,
// a box, and the watertight intersection test. Both are flat_loops; each adds only its
// name, its scene format and its checks of the vertices.

#include <vector>

#include "stage_02.hh"

namespace vl::stage02 {

class flat_loop : public primitive {
public:
    vector normal(const point&) const override { return normal_; }
    bool contains(const point&) const override { return false; }
    point min_point() const override { return low_; }
    point max_point() const override { return high_; }

protected:
    /// Stores `loop` (already checked), its unit normal (`normal`, made unit) and its box.
    void set_loop(std::vector<point> loop, const vector& normal);
    const std::vector<point>& loop() const { return loop_; }

private:
    // Woop, Benthin and Wald's test (JCGT 2(1), 2013): in the ray's permuted and sheared
    // frame, one 2D edge function per edge; the ray is inside when none disagree in sign.
    // A polygon that shares an edge with another computes the same function for it.
    intersection find_intersection(const ray& r) const override;

    std::vector<point> loop_;
    vector normal_;
    point low_, high_;
};

}  // namespace vl::stage02
