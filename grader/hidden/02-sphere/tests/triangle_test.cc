// Hidden tests of stage 02's triangle (triangle.cc). Each TEST_CASE is one graded item;
// the tag [triangle] puts it in the rubric's "triangles" category. Every expected answer
// comes from the long-double formulas in hidden_support.hh, never from another of your
// objects; on an edge shared by two triangles either may report the hit.
#include "vl/catch.hh"

#include <cmath>
#include <exception>
#include <limits>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "hidden_support.hh"

using vl::intersection;
using vl::point;
using vl::primitive;
using vl::ray;
using vl::rtab_component;
using vl::vector;
using vl::stage02::make_triangle;
using namespace vl::stage02::hidden;

namespace {

using mesh = std::vector<std::unique_ptr<primitive>>;

struct corners {
    point a, b, c;
};

std::string describe(const corners& k) { return "the triangle " + show(k.a) + " " + show(k.b) + " " + show(k.c); }

double size_of(const corners& k) { return (k.b - k.a).length() + (k.c - k.a).length() + (k.c - k.b).length(); }

// A hit distance to 1e-11 of the numbers involved, over the cosine of incidence.
double tolerance_of(const corners& k, const ray& r, double t) {
    const vector n = ((k.b - k.a) % (k.c - k.a)).unit();
    const double cosine = std::max(std::fabs(r.direction() * n), 1e-2);
    const double coordinates = std::fabs(k.a.x) + std::fabs(k.a.y) + std::fabs(k.a.z);
    return 1e-11 * ((r.origin() - k.a).length() + std::fabs(t) + size_of(k) + coordinates) / cosine;
}

// Checks one ray whose target is clearly inside (every barycentric coordinate above
// `margin`) or clearly outside (one below -margin); rays in between are skipped.
void check_ray(tally& t, const primitive& tri, const corners& k, const ray& r, double margin = 1e-6) {
    const triangle_answer exact = triangle_oracle(k.a, k.b, k.c, r);
    if (exact.meets && std::fabs(static_cast<double>(exact.min_weight())) < margin) return;
    const double want = static_cast<double>(exact.t);
    const bool hits = exact.meets && exact.min_weight() > 0 && want > std::fabs(tri.zero_t());
    const intersection i = tri.intersect(r);
    const vector n = ((k.b - k.a) % (k.c - k.a));
    const std::string side = (r.origin() - k.a) * n > 0 ? " from the front" : " from behind";
    if (hits) {
        const double tol = tolerance_of(k, r, want);
        check_hit_at(t, i, tri, r, want, tol, [&] { return describe(k); }, side);
    } else {
        t.check(clean_miss(i), [&] {
            return show(r) + side + " should miss " + describe(k) +
                   (exact.meets && exact.min_weight() > 0 ? " (the triangle is behind it)" : " (it passes outside an edge)") +
                   "; yours returned " + show(i, &tri);
        });
    }
}

point at(const corners& k, double wb, double wc) { return k.a + wb * (k.b - k.a) + wc * (k.c - k.a); }

const std::vector<corners> triangles = {
    {point(0, 0, -2), point(2, 0, -2), point(0, 2, -2)},
    {point(1.5, -0.2, 3.1), point(-2.2, 1.7, 0.4), point(0.3, 2.9, -1.8)},
    {point(120.3, -7.2, 40.1), point(131.9, 2.4, 36.3), point(118.1, 8.5, 47.6)},
    {point(0.01, 0.02, -0.03), point(0.011, 0.025, -0.031), point(0.004, 0.021, -0.027)},
    {point(-3, 1, 1), point(4, 1, 1.5), point(0.5, 1, -6)},  // nearly horizontal
};

/// For each of `rays`, whether it hits at least one triangle of `m` cleanly.
std::vector<bool> mesh_hits(const mesh& m, const std::vector<ray>& rays) { return hits_any(m, rays); }
bool mesh_hit(const mesh& m, const ray& r) { return mesh_hits(m, {r})[0]; }

// `got` answers like `want`, the same triangle made another way.
void check_same_triangle(tally& t, const rtab_component& got, const primitive& want, const corners& k, const std::string& who) {
    t.check(got.type_name() == "TRIANGLE",
            [&] { return who + "'s type_name() is \"" + got.type_name() + "\", not \"TRIANGLE\""; });
    const double coordinates = std::max({std::fabs(k.a.x), std::fabs(k.a.y), std::fabs(k.a.z), std::fabs(k.b.x),
                                         std::fabs(k.b.y), std::fabs(k.b.z), std::fabs(k.c.x), std::fabs(k.c.y),
                                         std::fabs(k.c.z)});
    const double slack = 8 * std::numeric_limits<double>::epsilon() * coordinates;
    check_same_box(t, got, want, who, slack);
    const point middle = at(k, 0.3, 0.3);
    const vector gn = got.normal(middle), wn = want.normal(middle);
    t.check((gn - wn).length() <= 1e-12 + 100 * slack / size_of(k), [&] {
        return who + ".normal(" + show(middle) + ") is " + show(gn) + " where the triangle's is " + show(wn);
    });
    t.check(!got.contains(middle), [&] { return who + ".contains() should be false (a triangle has no inside)"; });
    sampler random(401);
    const vector n = ((k.b - k.a) % (k.c - k.a)).unit();
    for (int j = 0; j < 40; ++j) {
        double u = random.uniform(-0.5, 1.2), v = random.uniform(-0.5, 1.2);
        const point target = at(k, u, v);
        const ray r = ray_through(target + size_of(k) * random.uniform(0.5, 5) * (j % 2 == 0 ? n : -n) + random.offset(size_of(k)),
                              target);
        const triangle_answer exact = triangle_oracle(k.a, k.b, k.c, r);
        if (std::fabs(static_cast<double>(exact.min_weight())) < 1e-6) continue;
        const intersection i = got.intersect(r), w = want.intersect(r);
        check_same_answer(t, r, got, i, want, w, tolerance_of(k, r, w.t) + slack, who, "triangle");
    }
}

std::string triangle_text(const corners& k, const vl::surface& s, bool with_surface) {
    std::string text = "TRIANGLE { c " + num(k.c.x) + " " + num(k.c.y) + " " + num(k.c.z) + " a (" + num(k.a.x) + ", " +
                       num(k.a.y) + ", " + num(k.a.z) + ") b " + num(k.b.x) + " " + num(k.b.y) + " " + num(k.b.z);
    if (with_surface)
        text += surface_text(s);
    return text + " }";
}

}  // namespace

// --- hits and misses ---------------------------------------------------------------------

TEST_CASE("triangle: rays aimed at points inside a triangle hit it there - from the front and from behind", "[02][triangle][hits][essential]") {
    tally t("rays aimed inside triangles");
    sampler random(411);
    for (const corners& k : triangles) {
        const auto tri = make_triangle(k.a, k.b, k.c);
        const vector n = ((k.b - k.a) % (k.c - k.a)).unit();
        for (int j = 0; j < 300; ++j) {
            double u = random.uniform(0, 1), v = random.uniform(0, 1);
            if (u + v > 1) u = 1 - u, v = 1 - v;
            const point target = at(k, 0.002 + 0.996 * u, 0.002 + 0.996 * v);
            const point from = target + size_of(k) * random.uniform(0.05, 20) * (j % 2 == 0 ? n : -n) +
                               random.offset(size_of(k) * 3);
            const ray r = ray_through(from, target);
            if (std::fabs(r.direction() * n) < 0.02) continue;
            check_ray(t, *tri, k, r);
        }
    }
    t.report();
}

TEST_CASE("triangle: rays aimed just outside each edge - beyond each corner or away from it miss", "[02][triangle][misses][essential]") {
    tally t("rays that pass a triangle by");
    sampler random(412);
    for (const corners& k : triangles) {
        const auto tri = make_triangle(k.a, k.b, k.c);
        const vector n = ((k.b - k.a) % (k.c - k.a)).unit();
        const point p[3] = {k.a, k.b, k.c};
        for (int e = 0; e < 3; ++e) {
            const point q = p[e], s = p[(e + 1) % 3], opposite = p[(e + 2) % 3];
            for (const double f : {-0.2, 0.02, 0.5, 0.98, 1.2}) {
                const point on_edge = q + f * (s - q);
                const vector outward = ((s - q) % n).unit() * (((s - q) % n) * (opposite - q) > 0 ? -1.0 : 1.0);
                for (const double gap : {1e-4, 1e-2, 0.3}) {
                    const point target = on_edge + gap * size_of(k) * outward;
                    for (const double side : {1.0, -1.0}) {
                        const point from = target + size_of(k) * random.uniform(0.5, 10) * side * n + random.offset(0.5 * size_of(k));
                        check_ray(t, *tri, k, ray_through(from, target));
                    }
                }
            }
            // Beyond the corner, along the line from the centre.
            const point centre = at(k, 1.0 / 3, 1.0 / 3);
            check_ray(t, *tri, k, ray_through(centre + size_of(k) * n, centre + 1.05 * (q - centre)));
        }
        // Pointing away from the triangle, from either side.
        for (int j = 0; j < 50; ++j) {
            const point inside = at(k, 0.3, 0.3);
            const point origin = inside + size_of(k) * random.uniform(0.01, 10) * (j % 2 == 0 ? n : -n) + random.offset(0.3 * size_of(k));
            check_ray(t, *tri, k, ray(origin, origin - inside));
        }
    }
    t.report();
}

TEST_CASE("triangle: a triangle is hit from behind as well as from the front", "[02][triangle][hits][essential]") {
    tally t("pairs of rays from either side through the same point");
    sampler random(413);
    for (int j = 0; j < 500; ++j) {
        const corners k{random.in_cube(3), random.in_cube(3), random.in_cube(3)};
        const vector cross = (k.b - k.a) % (k.c - k.a);
        if (cross.length() < 0.5) continue;
        const auto tri = make_triangle(k.a, k.b, k.c);
        const point target = at(k, random.uniform(0.05, 0.45), random.uniform(0.05, 0.45));
        vector d = random.direction();
        if (std::fabs(d * cross.unit()) < 0.1) d = d + 0.5 * cross.unit();
        check_ray(t, *tri, k, ray_through(target + random.uniform(0.1, 10) * d, target));
        check_ray(t, *tri, k, ray_through(target - random.uniform(0.1, 10) * d, target));
    }
    t.report();
}

TEST_CASE("triangle: rays exactly parallel to a triangle or lying in its plane miss cleanly", "[02][triangle][parallel]") {
    tally t("rays parallel to a triangle");
    const corners k{point(-1, -1, 2), point(3, 0, 2), point(0, 4, 2)};
    const auto tri = make_triangle(k.a, k.b, k.c);
    check_parallel_rays_miss(t, *tri, describe(k), point(0.5, 0.8, 2), vector(0, 0, 1),
                             {vector(1, 0.5, 0), vector(-1, 0, 0), vector(0.2, -1, 0), vector(1, 1, 0)},
                             {0.0, 1e-9, -1e-9, 5.0});
    t.report();
}

TEST_CASE("triangle: rays leaving a point of the triangle never hit it again - whatever the sign of zero_t", "[02][triangle][surface]") {
    tally t("rays leaving a triangle");
    sampler random(414);
    for (const double zero_t : {1e-6, -1e-6}) {
        for (const corners& k : triangles) {
            const auto tri = make_triangle(k.a, k.b, k.c);
            vl::surface s;
            s.zero_t = zero_t * std::min(1.0, size_of(k));
            tri->set_surface(s);
            const vector n = ((k.b - k.a) % (k.c - k.a)).unit();
            vector u, v;
            plane_axes(n, u, v);
            for (int j = 0; j < 300; ++j) {
                double a = random.uniform(0, 1), b = random.uniform(0, 1);
                if (a + b > 1) a = 1 - a, b = 1 - b;
                const point on = at(k, a, b);
                const vector d = leaving_direction(random, j, n, u, v, -5);
                check_leaving_misses(t, *tri, ray(on, d), tri->zero_t(), [&] { return describe(k); });
            }
        }
    }
    t.report();
}

TEST_CASE("triangle: zero_t - positive or negative - hides a hit up to its absolute value", "[02][triangle][zero_t]") {
    tally t("a triangle hit at t = 0.3 with different zero_t");
    const corners k{point(0, 0, -0.3), point(1, 0, -0.3), point(0, 1, -0.3)};
    const auto tri = make_triangle(k.a, k.b, k.c);
    check_zero_t_hides_hit_at_0_3(t, *tri, describe(k), {ray(point(0.25, 0.25, 0), vector(0, 0, -1)), ray(point(0.25, 0.25, -0.6), vector(0, 0, 1))});
    t.report();
}

TEST_CASE("triangle: a small triangle a million units away is hit inside and missed outside its edges", "[02][triangle][far]") {
    tally t("rays at a far triangle");
    const point centre(3e5, -4e5, -8.5e5);
    const corners k{centre + vector(-1, -0.5, 0.2), centre + vector(1, -0.6, -0.1), centre + vector(0.1, 1, 0.3)};
    const auto tri = make_triangle(k.a, k.b, k.c);
    const point eye(0, 0, 0);
    const point p[3] = {k.a, k.b, k.c};
    for (int e = 0; e < 3; ++e) {
        const point q = p[e], s = p[(e + 1) % 3], opposite = p[(e + 2) % 3];
        for (const double f : {0.1, 0.5, 0.9}) {
            const point on_edge = q + f * (s - q);
            const vector inward = (opposite - on_edge).unit();
            check_ray(t, *tri, k, ray_through(eye, on_edge + 1e-3 * inward), 1e-5);
            check_ray(t, *tri, k, ray_through(eye, on_edge - 1e-3 * inward), 1e-5);
        }
    }
    check_ray(t, *tri, k, ray_through(eye, at(k, 1.0 / 3, 1.0 / 3)));
    t.report();
}

TEST_CASE("triangle: a huge triangle seen from just above keeps the digits of the short distance", "[02][triangle][precision]") {
    tally t("rays at a huge triangle from just above it");
    const corners k{point(-1e7, 0, 1e7), point(1e7, 0, 1e7), point(0, 0, -1e7)};
    const auto ground = make_triangle(k.a, k.b, k.c);
    sampler random(415);
    for (int j = 0; j < 100; ++j) {
        const point origin(random.uniform(-100, 100), random.uniform(0.1, 1), random.uniform(-100, 100));
        const vector d = j % 2 == 0 ? vector(0, -1, 0) : vector(random.uniform(-0.1, 0.1), -1, random.uniform(-0.1, 0.1));
        const ray r(origin, d);
        const double want = static_cast<double>(triangle_oracle(k.a, k.b, k.c, r).t), tol = 1e-8 * want;
        const intersection i = ground->intersect(r);
        check_hit_at(t, i, *ground, r, want, tol, [&] { return describe(k); });
    }
    t.report();
}

// --- watertight meshes -------------------------------------------------------------------

TEST_CASE("triangle: rays through the spokes and the hub of a fan of sixteen triangles never slip through", "[02][triangle][watertight][essential]") {
    const point hub(512.37, -80.21, 33.3);
    std::vector<point> rim;
    for (int k = 0; k < 16; ++k) {
        const double angle = 2 * std::numbers::pi * k / 16 + 0.05 * std::sin(5.0 * k);
        rim.push_back(hub + vector(3 * std::cos(angle), 0.1 * std::sin(2.0 * k), 3 * std::sin(angle)));
    }
    mesh fan;
    for (std::size_t k = 0; k < rim.size(); ++k) fan.push_back(make_triangle(hub, rim[k], rim[(k + 1) % rim.size()]));
    tally t("rays through the shared edges and the hub of a fan (none of its triangles hit)");
    sampler random(25);
    std::vector<ray> rays;
    std::vector<point> targets;
    for (int k = 0; k < 20000; ++k) {
        const std::size_t spoke = static_cast<std::size_t>(random.uniform(0, 16)) % 16;
        const point target = k % 4 == 0 ? hub : hub + random.uniform(0.02, 0.9) * (rim[spoke] - hub);
        vector d = random.direction();
        if (std::fabs(d.y) < 0.4) continue;  // across the fan, not along it
        rays.push_back(ray_through(target + random.uniform(1, 50) * d, target));
        targets.push_back(target);
    }
    const std::vector<bool> hit = mesh_hits(fan, rays);
    for (std::size_t k = 0; k < rays.size(); ++k)
        t.check(hit[k], [&] { return show(rays[k]) + " passes through " + show(targets[k]) + " and hits none of the triangles"; });
    t.check(t.tried() > 10000, [] { return std::string("too few rays were tried"); });
    t.report();
}

TEST_CASE("triangle: rays from inside a closed octahedron mesh never escape through its edges or corners", "[02][triangle][watertight][essential]") {
    // Six corners, slightly irregular and turned, eight faces: a closed surface, so every
    // ray from inside must hit at least one face, also when it is aimed at an edge or a corner.
    const point centre(-3.3, 1.9, 0.7);
    const vector x = vector(0.8, 0.6, 0), y = vector(-0.36, 0.48, 0.8), z = x % y;
    const point px = centre + 1.1 * x, nx = centre - 0.9 * x, py = centre + 1.3 * y, ny = centre - 0.8 * y,
                pz = centre + 1.05 * z, nz = centre - 1.2 * z;
    mesh solid;
    for (const point& h : {py, ny})
        for (const auto& [p, q] : {std::pair{px, pz}, std::pair{pz, nx}, std::pair{nx, nz}, std::pair{nz, px}})
            solid.push_back(make_triangle(h, p, q));
    const point corner[] = {px, nx, py, ny, pz, nz};
    const std::pair<point, point> edges[] = {{py, px}, {py, pz}, {py, nx}, {py, nz}, {ny, px}, {ny, pz},
                                             {ny, nx}, {ny, nz}, {px, pz}, {pz, nx}, {nx, nz}, {nz, px}};
    tally t("rays from inside a closed octahedron (none of its faces hit)");
    sampler random(26);
    std::vector<ray> rays;
    std::vector<point> targets;
    for (int k = 0; k < 20000; ++k) {
        const point from = centre + 0.3 * vector(random.uniform(-1, 1), random.uniform(-1, 1), random.uniform(-1, 1));
        const auto& [p, q] = edges[k % 12];
        const point target = k % 5 == 0 ? corner[k % 6] : p + random.uniform(0, 1) * (q - p);
        rays.push_back(ray_through(from, target));
        targets.push_back(target);
    }
    const std::vector<bool> hit = mesh_hits(solid, rays);
    for (std::size_t k = 0; k < rays.size(); ++k)
        t.check(hit[k], [&] { return show(rays[k]) + " aimed at " + show(targets[k]) + " escapes through the mesh"; });
    t.report();
}

TEST_CASE("triangle: a bumpy grid mesh lets no ray through its shared edges and vertices", "[02][triangle][watertight][essential]") {
    constexpr int n = 8;
    const auto height = [](int i, int j) { return 0.08 * std::sin(1.3 * i + 0.4) * std::cos(0.9 * j - 0.2); };
    std::vector<std::vector<point>> grid(n + 1, std::vector<point>(n + 1));
    for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= n; ++j) grid[i][j] = point(0.37 * i - 1.1, height(i, j), 0.41 * j + 2.3);
    mesh surface;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const point &p00 = grid[i][j], &p10 = grid[i + 1][j], &p01 = grid[i][j + 1], &p11 = grid[i + 1][j + 1];
            if ((i + j) % 2 == 0) {
                surface.push_back(make_triangle(p00, p01, p11));
                surface.push_back(make_triangle(p00, p11, p10));
            } else {
                surface.push_back(make_triangle(p00, p01, p10));
                surface.push_back(make_triangle(p10, p01, p11));
            }
        }
    tally t("rays through the grid's shared edges and vertices (none of its triangles hit)");
    sampler random(27);
    std::vector<ray> rays;
    std::vector<point> targets;
    for (int k = 0; k < 20000; ++k) {
        const int i = 1 + static_cast<int>(random.uniform(0, n - 2)), j = 1 + static_cast<int>(random.uniform(0, n - 2));
        point target;
        switch (k % 4) {
        case 0: target = grid[i][j]; break;                                                          // a vertex
        case 1: target = grid[i][j] + random.uniform(0, 1) * (grid[i + 1][j] - grid[i][j]); break;  // an edge
        case 2: target = grid[i][j] + random.uniform(0, 1) * (grid[i][j + 1] - grid[i][j]); break;  // an edge
        default: {  // a diagonal
            const bool even = (i + j) % 2 == 0;
            const point& p = even ? grid[i][j] : grid[i + 1][j];
            const point& q = even ? grid[i + 1][j + 1] : grid[i][j + 1];
            target = p + random.uniform(0, 1) * (q - p);
        }
        }
        const vector d = vector(random.uniform(-0.6, 0.6), 1, random.uniform(-0.6, 0.6)) * (k % 2 == 0 ? 1 : -1);
        rays.push_back(ray_through(target + random.uniform(2, 30) * d.unit(), target));
        targets.push_back(target);
    }
    const std::vector<bool> hit = mesh_hits(surface, rays);
    for (std::size_t k = 0; k < rays.size(); ++k)
        t.check(hit[k], [&] { return show(rays[k]) + " aimed at " + show(targets[k]) + " passes through the mesh"; });
    t.report();
}

// --- normal, contains, bounds -------------------------------------------------------------

TEST_CASE("triangle: the normal follows the counter-clockwise winding - whichever vertex comes first", "[02][triangle][normals][essential]") {
    tally t("normals");
    sampler random(416);
    std::vector<corners> all = triangles;
    for (int j = 0; j < 20; ++j) all.push_back({random.in_cube(5), random.in_cube(5), random.in_cube(5)});
    for (const corners& k : all) {
        if (((k.b - k.a) % (k.c - k.a)).length() < 1e-3 * size_of(k) * size_of(k)) continue;
        const rvec want = unit(cross(to_r(k.b) - to_r(k.a), to_r(k.c) - to_r(k.a)));
        const point somewhere = at(k, 0.2, 0.3);
        const corners orders[] = {{k.a, k.b, k.c}, {k.b, k.c, k.a}, {k.c, k.a, k.b}, {k.a, k.c, k.b}, {k.b, k.a, k.c}};
        for (int o = 0; o < 5; ++o) {
            const corners& m = orders[o];
            const auto tri = make_triangle(m.a, m.b, m.c);
            if (o == 2)  // rays from behind must not change it
                for (int j = 0; j < 5; ++j) tri->intersect(ray(somewhere - 3 * vector(1, 1, 1), vector(1, 1, 1)));
            const double sign = o < 3 ? 1 : -1;
            const vector n = tri->normal(somewhere);
            const double gap = static_cast<double>(std::max(
                {std::fabs(n.x - sign * want.x), std::fabs(n.y - sign * want.y), std::fabs(n.z - sign * want.z)}));
            t.check(gap <= 1e-12, [&] {
                return "the normal of " + describe(m) + " should be (" + num(static_cast<double>(sign * want.x)) + ", " +
                       num(static_cast<double>(sign * want.y)) + ", " + num(static_cast<double>(sign * want.z)) +
                       ") ± 1e-12 (unit, counter-clockwise side); yours is " + show(n);
            });
            t.check(!tri->contains(somewhere), [&] { return describe(m) + ".contains() should be false (it has no inside)"; });
        }
    }
    t.report();
}

TEST_CASE("triangle: its box is exactly the smallest one around the three vertices", "[02][triangle][bounds]") {
    tally t("bounds");
    const struct {
        corners k;
        point lo, hi;
    } cases[] = {
        {{point(-1e5, 0.25, 7), point(3, -2e-3, -8.5), point(0.5, 9e4, 7.5)}, point(-1e5, -2e-3, -8.5), point(3, 9e4, 7.5)},
        {{point(1, 1, 4), point(2, 1, 4), point(1, 3, 4)}, point(1, 1, 4), point(2, 3, 4)},
        {{point(1, -2, 3), point(-4, 5, 0), point(2, 2, -6)}, point(-4, -2, -6), point(2, 5, 3)},
        {{point(0.1, 1.0 / 3, -0.7), point(0.3, -1.0 / 7, 0.2), point(-0.2, 0.6, 0.9)}, point(-0.2, -1.0 / 7, -0.7),
         point(0.3, 0.6, 0.9)},
    };
    for (const auto& c : cases) {
        check_exact_box(t, *make_triangle(c.k.a, c.k.b, c.k.c), describe(c.k), c.lo, c.hi);
    }
    t.report();
}

// --- the factory and scene files ----------------------------------------------------------

TEST_CASE("triangle: make_triangle refuses collinear - coincident or non-finite vertices", "[02][triangle][refusals]") {
    const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
    tally t("make_triangle with vertices that are not a triangle");
    const corners bad[] = {
        {point(1, 2, 3), point(1, 2, 3), point(0, 0, 0)},        {point(0, 0, 0), point(1, 0, 0), point(0, 0, 0)},
        {point(0, 0, 0), point(1, 1, 1), point(2, 2, 2)},        {point(0, 0, 0), point(1, 1, 1), point(-3, -3, -3)},
        {point(0, 0, 0), point(1, 1e-15, 0), point(2, 0, 0)},    {point(0, 0, 0), point(1, 0, 0), point(nan, 1, 0)},
        {point(inf, 0, 0), point(1, 0, 0), point(0, 1, 0)},      {point(0, 0, 0), point(1, -inf, 0), point(0, 1, 0)},
        {point(0, 0, 0), point(1, 0, 0), point(0, 1, 0, 0)},
    };
    for (const corners& k : bad)
        expect_usage_error(t, "make_triangle(" + show(k.a) + ", " + show(k.b) + ", " + show(k.c) + ")",
                           [&] { return make_triangle(k.a, k.b, k.c); });
    // Small and thin triangles are triangles: they are made and hit.
    for (const corners& k : {corners{point(0, 0, 0), point(1e-3, 0, 0), point(0, 1e-3, 0)},
                             corners{point(0, 0, 0), point(1, 0, 0), point(0.5, 1e-6, 0)}}) {
        const auto tri = make_triangle(k.a, k.b, k.c);
        check_ray(t, *tri, k, ray(at(k, 0.3, 0.3) + vector(0, 0, 1), vector(0, 0, -1)), 0);
    }
    t.report();
}

TEST_CASE("triangle: a TRIANGLE in a scene file is the triangle its vertices and surface keys describe", "[02][triangle][scene_io]") {
    tally t("TRIANGLE read from a scene file");
    const corners k{point(0.1 + 1e-13, -1.0 / 3, 7.25), point(1.0 / 7, 2.5, -0.2), point(-2.0 / 3, 0.4, 1e-7)};
    const vl::surface surf = full_precision_surface(-1e-7 / 3);
    const std::string text = triangle_text(k, surf, true);
    const auto want = make_triangle(k.a, k.b, k.c);
    check_read_as(t, text, "TRIANGLE", *want, surf,
                  [&](const rtab_component& got, const std::string& what) { check_same_triangle(t, got, *want, k, what); });
    t.report();
}

TEST_CASE("triangle: a bad TRIANGLE in a scene file is refused with its place - a good one is read", "[02][triangle][scene_io][detail]") {
    tally t("TRIANGLE blocks in scene files");
    for (const char* text : {"TRIANGLE { a 0 0 0 b 1 1 1 c 2 2 2 }", "TRIANGLE { a 1 2 3 b 1 2 3 }",
                             "TRIANGLE { c (0.5, 0.5, 0, 0) }"}) {
        const std::string message = read_error(text);
        t.check(message.find("hidden.ray_trace:1:") != std::string::npos, [&] {
            return std::string("reading \"") + text + "\" should fail with a vl::file_error at hidden.ray_trace:1:COL; it gave: " +
                   message;
        });
    }
    const corners k{point(0, 0, -2), point(2, 0, -2), point(0, 2, -1)};
    const auto good = read_one(triangle_text(k, {}, false));
    const auto want = make_triangle(k.a, k.b, k.c);
    check_same_triangle(t, *good, *want, k, triangle_text(k, {}, false));
    t.report();
}

TEST_CASE("triangle: an empty TRIANGLE block is the default one facing plus z with the default surface", "[02][triangle][scene_io][detail]") {
    tally t("TRIANGLE { }");
    const corners k{point(0, 0, 0), point(1, 0, 0), point(0, 1, 0)};
    const auto got = read_one("TRIANGLE { }");
    const auto want = make_triangle(k.a, k.b, k.c);
    compare_surface(surface_of(*got), vl::surface{}, "TRIANGLE { }", t);
    check_same_triangle(t, *got, *want, k, "TRIANGLE { }");
    t.report();
}

TEST_CASE("triangle: write() keeps every digit of the vertices and of each surface key", "[02][triangle][scene_io]") {
    tally t("write() of a TRIANGLE read back");
    for (const corners& k : {corners{point(0.1 + 1e-13, -1.0 / 3, 2.0 / 3 + 1e-12), point(1.0 / 7, 2.5, -0.2),
                                     point(-2.0 / 3, 0.4, 1e-7)},
                             corners{point(123456.789012345, 1e-7, -1.0 / 7), point(123456.789012345 + 1.0 / 3, 0.5, 0.1),
                                     point(123456.5 + 1e-9, 1.0 / 3, 2.0 / 3)}}) {
        const auto original = make_triangle(k.a, k.b, k.c);
        original->set_surface(full_precision_surface(-1e-9 / 3));
        check_write_reads_back(
            t, *original, "TRIANGLE", describe(k),
            [&](const written_object& w, const std::string& who) {
                const std::pair<const char*, point> vertices[] = {{"a", k.a}, {"b", k.b}, {"c", k.c}};
                for (const auto& [name, p] : vertices) {
                    const std::vector<double> q = w.keys.at(name);
                    const bool ok = within_ulps(q[0], p.x, 4) && within_ulps(q[1], p.y, 4) && within_ulps(q[2], p.z, 4);
                    t.check(ok, [&, name = name, p = p] {
                        return who + " has vertex " + name + " = " + show(point(q[0], q[1], q[2])) + "; it should be " + show(p) +
                               " (± 4 ulps)";
                    });
                }
            },
            [&](const rtab_component& back, const std::string& what) { check_same_triangle(t, back, *original, k, what); });
    }
    t.report();
}

// --- stability sweep -------------------------------------------------------------------------

TEST_CASE("sweep: triangle: rays aimed 1e-17 to 0.1 of a triangle's size from a shared edge or vertex", "[02][sweep]") {
    // Fans of triangles around a hub, slightly bumpy, at various places and sizes. Each ray
    // comes from the front and crosses a fan at a point x * size from a shared edge (a spoke) or from the shared
    // vertex (the hub), inside one of the triangles next to it; it must hit at least one
    // triangle of the fan. At x = 1e-17 the point is on the edge up to rounding: a test
    // that is exact there (the same edge function for both neighbours, ties counted as
    // inside) leaves no gap; the Moller-Trumbore test, which computes each triangle's
    // coordinates its own way, lets some rays through.
    struct fan {
        point hub;
        std::vector<point> rim;
        double size = 0;
        vector up;
        mesh triangles;
        std::string problem;
    };
    sampler random(27);
    std::vector<fan> fans;
    for (int f = 0; f < 6; ++f) {
        fan n;
        n.size = std::pow(10.0, random.uniform(-1, 2));
        n.hub = random.in_cube(f % 2 == 0 ? 10 : 1e3);
        n.up = random.direction();
        vector u, v;
        plane_axes(n.up, u, v);
        const int corners = 6 + f;
        for (int k = 0; k < corners; ++k) {
            const double angle = 2 * std::numbers::pi * (k + random.uniform(-0.2, 0.2)) / corners;
            n.rim.push_back(n.hub + n.size * (std::cos(angle) * u + std::sin(angle) * v + random.uniform(-0.15, 0.15) * n.up));
        }
        try {
            for (std::size_t k = 0; k < n.rim.size(); ++k)
                n.triangles.push_back(make_triangle(n.hub, n.rim[k], n.rim[(k + 1) % n.rim.size()]));
        } catch (const std::exception& e) {
            n.problem = std::string("make_triangle threw: ") + e.what();
        } catch (...) {
            n.problem = "make_triangle threw";
        }
        fans.push_back(std::move(n));
    }
    for (int e10 = -17; e10 <= -1; ++e10) {
        const double x = std::pow(10.0, e10);
        tally t("rays " + num(x) + " of the size from a shared edge or vertex");
        for (const fan& n : fans) {
            const std::size_t count = n.rim.size();
            for (int k = 0; k < 40; ++k) {
                const std::size_t j = static_cast<std::size_t>(random.uniform(0, static_cast<double>(count))) % count;
                const point& a = n.rim[j];
                const point& b = n.rim[(j + 1) % count];
                // Into triangle j (hub, a, b), from its spoke hub-a, from its spoke hub-b, or from the hub.
                const vector along_a = (a - n.hub).unit(), along_b = (b - n.hub).unit();
                const vector normal = ((a - n.hub) % (b - n.hub)).unit();
                point target;
                std::string near;
                if (k % 3 == 0) {
                    target = n.hub + (x * n.size) * (along_a + along_b).unit();
                    near = "the shared vertex " + show(n.hub);
                } else {
                    const bool first = k % 3 == 1;
                    const vector spoke = first ? along_a : along_b;
                    const vector into = (first ? normal % spoke : spoke % normal).unit();
                    const point on = n.hub + random.uniform(0.2, 0.7) * ((first ? a : b) - n.hub);
                    target = on + (x * n.size) * into;
                    near = "the shared edge from " + show(n.hub) + " to " + show(first ? a : b);
                }
                // From the front (back faces are the hit tests' business), across the fan, not along it.
                vector d = random.direction();
                if (d * normal < 0) d = -d;
                if (d * normal < 0.5) d = (d + normal).unit();
                const ray r = ray_through(target + n.size * random.uniform(0.5, 20) * d, target);
                bool hit = false;
                std::string threw = n.problem;
                if (threw.empty()) {
                    try {
                        hit = mesh_hit(n.triangles, r);
                    } catch (const std::exception& e) {
                        threw = std::string("intersect() threw: ") + e.what();
                    } catch (...) {
                        threw = "intersect() threw";
                    }
                }
                t.check(hit, [&] {
                    return show(r) + " crosses a fan of triangles " + num(x * n.size) + " from " + near +
                           (threw.empty() ? " and hits none of them" : ": " + threw);
                });
            }
        }
        t.report_sweep_point(x);
    }
}
