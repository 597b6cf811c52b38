#include "vl/convex_polygon.hh"

#include <algorithm>
#include <cmath>

namespace vl {

namespace {
bool finite(const point& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }
}  // namespace

vector newell_normal(const std::vector<point>& v, const point& centroid) {
    vector n;
    for (std::size_t i = 0; i < v.size(); ++i) n += (v[i] - centroid) % (v[(i + 1) % v.size()] - centroid);
    return n;
}

point centroid_of(const std::vector<point>& v) {
    vector sum;
    for (const point& p : v) sum += p - point(0, 0, 0);
    return point(0, 0, 0) + sum / static_cast<double>(v.size());
}

std::optional<polygon_problem> find_polygon_problem(const std::vector<point>& v) {
    const auto name = [](std::size_t i) { return "vertex " + std::to_string(i + 1); };
    if (v.size() < 3)
        return polygon_problem{v.size(), "a POLYGON needs at least 3 vertices, found " + std::to_string(v.size())};
    for (std::size_t i = 0; i < v.size(); ++i)
        if (!finite(v[i])) return polygon_problem{i, name(i) + " is not a finite point (w is 0)"};

    point lo = v[0], hi = v[0];
    for (const point& p : v) {
        lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
        hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
    }
    const double size = (hi - lo).length();  // tolerances are relative to it
    for (std::size_t i = 0; i < v.size(); ++i) {
        const std::size_t next = (i + 1) % v.size();
        if ((v[next] - v[i]).length() <= 1e-12 * size || size == 0)
            return polygon_problem{next, name(next) + " is the same point as " + name(i)};
    }

    const point centroid = centroid_of(v);
    const vector newell = newell_normal(v, centroid);
    if (!(newell.length() > 1e-12 * size * size))
        return polygon_problem{2, "all its vertices are on one line: it has no area"};
    const vector n = newell.unit();

    // Planar: every vertex on the plane of vertices 1, 2 and the one furthest from
    // their line (the best-conditioned choice of three), within 1e-6 of the size.
    std::size_t k = 2;
    for (std::size_t i = 3; i < v.size(); ++i)
        if (((v[1] - v[0]) % (v[i] - v[0])).length() > ((v[1] - v[0]) % (v[k] - v[0])).length()) k = i;
    const vector m = ((v[1] - v[0]) % (v[k] - v[0])).unit();
    for (std::size_t i = 0; i < v.size(); ++i) {
        const double off = std::fabs((v[i] - v[0]) * m);
        if (off > 1e-6 * size)
            return polygon_problem{i, name(i) + " is " + std::to_string(off) + " away from the plane of vertices 1, 2 and " +
                                          std::to_string(k + 1) + ": a POLYGON must be planar"};
    }
    // Convex: every vertex lies on the inner side (or on the line) of every edge.
    for (std::size_t i = 0; i < v.size(); ++i) {
        const std::size_t next = (i + 1) % v.size();
        const vector edge = v[next] - v[i];
        for (std::size_t j = 0; j < v.size(); ++j) {
            const double side = ((edge % (v[j] - v[i])) * n) / edge.length();  // signed distance from the edge's line
            if (side < -1e-6 * size)
                return polygon_problem{j, name(j) + " lies outside the edge from " + name(i) + " to " + name(next) +
                                              ": a POLYGON must be convex (split it into convex pieces)"};
        }
    }
    return std::nullopt;
}

}  // namespace vl
