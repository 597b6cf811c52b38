// Hidden tests of stage 02's triangle (grader only; students never see this file). Each
// TEST_CASE is one graded item; the tag [triangles] puts it in the rubric's "triangles"
// category.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <sstream>
#include <vector>

#include "hidden_support.hh"
#include "vl/error.hh"

using vl::intersection;
using vl::point;
using vl::primitive;
using vl::ray;
using vl::vector;
using vl::stage02::make_triangle;
using namespace vl::stage02::hidden;

namespace {

using mesh = std::vector<std::unique_ptr<primitive>>;

bool mesh_hit(const mesh& m, const ray& r) {
    bool hit = false;
    for (const auto& t : m) hit = clean_hit(t->intersect(r), t.get()) || hit;
    return hit;
}

}  // namespace

TEST_CASE("triangle: rays aimed at random points of a slanted triangle hit exactly there", "[02][triangle][triangles][essential]") {
    const point a(1.5, -0.2, 3.1), b(-2.2, 1.7, 0.4), c(0.3, 2.9, -1.8);
    const auto tri = make_triangle(a, b, c);
    sampler random(21);
    int missed = 0, misplaced = 0, false_hits = 0;
    for (int k = 0; k < 2000; ++k) {
        double u = random.uniform(0, 1), v = random.uniform(0, 1);
        if (u + v > 1) u = 1 - u, v = 1 - v;
        const point origin = random.in_box(20);
        if (k % 2 == 0) {
            u = 0.001 + 0.998 * u, v = 0.001 + 0.998 * v;
            if (u + v > 0.999) continue;
            const point target = a + u * (b - a) + v * (c - a);
            const ray r = through(origin, target);
            const intersection i = tri->intersect(r);
            if (!clean_hit(i, tri.get())) ++missed;
            else if ((r.t_point(i.t) - target).length() > 1e-9) ++misplaced;
        } else {
            // Outside: one barycentric coordinate below -0.001.
            const double w = 1 - u - v;
            const double out = -random.uniform(0.001, 0.5);
            const int which = k % 3;
            const double bu = which == 0 ? out : u, bv = which == 1 ? out : v;
            const double bw = which == 2 ? out : w;
            const double sum = bu + bv + bw;
            if (std::fabs(sum) < 0.2) continue;
            const point target = a + (bu / sum) * (b - a) + (bv / sum) * (c - a);
            if (bu / sum > -1e-3 && bv / sum > -1e-3 && bw / sum > -1e-3) continue;
            if (!clean_miss(tri->intersect(through(origin, target)))) ++false_hits;
        }
    }
    CHECK(missed == 0);
    CHECK(misplaced == 0);
    CHECK(false_hits == 0);
}

TEST_CASE("triangle: a triangle the ray points away from is not reported", "[02][triangle][triangles]") {
    sampler random(22);
    int reported = 0;
    for (int k = 0; k < 1000; ++k) {
        const point a = random.in_box(3), b = random.in_box(3), c = random.in_box(3);
        if (((b - a) % (c - a)).length() < 0.1) continue;
        const auto tri = make_triangle(a, b, c);
        const point inside = a + 0.3 * (b - a) + 0.3 * (c - a);
        const point origin = inside + random.uniform(0.01, 40) * random.direction();
        // From `origin` away from the point of the triangle it came from.
        if (!clean_miss(tri->intersect(ray(origin, origin - inside)))) ++reported;
    }
    CHECK(reported == 0);
}

TEST_CASE("triangle: rays exactly parallel to a triangle or lying in its plane miss cleanly", "[02][triangle][triangles]") {
    const auto tri = make_triangle(point(-1, -1, 2), point(3, 0, 2), point(0, 4, 2));
    int wrong = 0;
    std::ostringstream first;
    for (const vector d : {vector(1, 0.5, 0), vector(-1, 0, 0), vector(0.2, -1, 0), vector(1, 1, 0)}) {
        for (const double z : {2.0, 2 + 1e-9, 2 - 1e-9, 7.0}) {
            // Starting outside and crossing the triangle's outline, and starting inside it.
            const intersection across = tri->intersect(ray(point(0.5, 0.8, z) - 10 * d.unit(), d));
            const intersection from_inside = tri->intersect(ray(point(0.5, 0.8, z), d));
            if ((!clean_miss(across) || !clean_miss(from_inside)) && wrong++ == 0)
                first << "direction " << d << " at z = " << z << ": t = " << across.t << " and " << from_inside.t;
        }
    }
    INFO("the first ray that did not miss: " << first.str());
    CHECK(wrong == 0);
}

TEST_CASE("triangle: rays leaving a point of the triangle at grazing angles never hit it again", "[02][triangle][triangles]") {
    const point a(120.3, -7.2, 40.1), b(131.9, 2.4, 36.3), c(118.1, 8.5, 47.6);
    const auto tri = make_triangle(a, b, c);
    const vector n = ((b - a) % (c - a)).unit();
    vector u, v;
    plane_axes(n, u, v);
    sampler random(23);
    int self_hits = 0;
    for (int k = 0; k < 3000; ++k) {
        double s = random.uniform(0, 1), t = random.uniform(0, 1);
        if (s + t > 1) s = 1 - s, t = 1 - t;
        const point on = a + s * (b - a) + t * (c - a);
        const double angle = std::pow(10.0, random.uniform(-5, -1)) * (k % 2 == 0 ? 1 : -1);
        const double turn = random.uniform(0, 2 * std::numbers::pi);
        const vector d = std::cos(angle) * (std::cos(turn) * u + std::sin(turn) * v) + std::sin(angle) * n;
        if (!clean_miss(tri->intersect(ray(on, d)))) ++self_hits;
    }
    CHECK(self_hits == 0);
}

TEST_CASE("triangle: a small triangle a million units away is hit inside and missed outside its edges", "[02][triangle][triangles]") {
    const point centre(3e5, -4e5, -8.5e5);
    const point a = centre + vector(-1, -0.5, 0.2), b = centre + vector(1, -0.6, -0.1), c = centre + vector(0.1, 1, 0.3);
    const auto tri = make_triangle(a, b, c);
    const point eye(0, 0, 0);
    int wrong = 0;
    const point corners[] = {a, b, c};
    for (int e = 0; e < 3; ++e) {
        const point p = corners[e], q = corners[(e + 1) % 3], opposite = corners[(e + 2) % 3];
        for (const double f : {0.1, 0.5, 0.9}) {
            const point on_edge = p + f * (q - p);
            const vector inward = (opposite - on_edge).unit();
            const intersection in = tri->intersect(through(eye, on_edge + 1e-3 * inward));
            const intersection out = tri->intersect(through(eye, on_edge - 1e-3 * inward));
            if (!clean_hit(in, tri.get()) || !clean_miss(out)) ++wrong;
            if (clean_hit(in, tri.get()) && std::fabs(in.t - (on_edge - eye).length()) > 1e-3) ++wrong;
        }
    }
    CHECK(wrong == 0);
}

TEST_CASE("triangle: a huge triangle seen from just above keeps the digits of the short distance", "[02][triangle][triangles]") {
    const auto ground = make_triangle(point(-1e7, 0, 1e7), point(1e7, 0, 1e7), point(0, 0, -1e7));
    sampler random(24);
    int missed = 0, inaccurate = 0;
    for (int k = 0; k < 50; ++k) {
        const point origin(random.uniform(-100, 100), 0.5, random.uniform(-100, 100));
        const vector d(random.uniform(-0.1, 0.1), -1, random.uniform(-0.1, 0.1));
        const intersection slanted = ground->intersect(ray(origin, d)), straight = ground->intersect(ray(origin, vector(0, -1, 0)));
        if (!clean_hit(slanted, ground.get()) || !clean_hit(straight, ground.get())) ++missed;
        else if (std::fabs(straight.t - 0.5) > 0.5e-9 || std::fabs(slanted.t - 0.5 / -d.unit().y) > 1e-9) ++inaccurate;
    }
    CHECK(missed == 0);
    CHECK(inaccurate == 0);
}

TEST_CASE("triangle: rays through the spokes and the hub of a fan of sixteen triangles never slip through", "[02][triangle][triangles][watertight]") {
    const point hub(512.37, -80.21, 33.3);
    std::vector<point> rim;
    for (int k = 0; k < 16; ++k) {
        const double angle = 2 * std::numbers::pi * k / 16 + 0.05 * std::sin(5.0 * k);
        rim.push_back(hub + vector(3 * std::cos(angle), 0.1 * std::sin(2.0 * k), 3 * std::sin(angle)));
    }
    mesh fan;
    for (std::size_t k = 0; k < rim.size(); ++k) fan.push_back(make_triangle(hub, rim[k], rim[(k + 1) % rim.size()]));
    sampler random(25);
    int leaks = 0, tried = 0;
    for (int k = 0; k < 20000; ++k) {
        const std::size_t spoke = static_cast<std::size_t>(random.uniform(0, 16)) % 16;
        const point target = k % 4 == 0 ? hub : hub + random.uniform(0.02, 0.9) * (rim[spoke] - hub);
        vector d = random.direction();
        if (std::fabs(d.y) < 0.4) continue;  // across the fan, not along it
        ++tried;
        if (!mesh_hit(fan, through(target + random.uniform(1, 50) * d, target))) ++leaks;
    }
    CAPTURE(tried);
    CHECK(tried > 10000);
    CHECK(leaks == 0);
}

TEST_CASE("triangle: rays from inside a closed octahedron mesh never escape through its edges or corners", "[02][triangle][triangles][watertight]") {
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
    const point corners[] = {px, nx, py, ny, pz, nz};
    const std::pair<point, point> edges[] = {{py, px}, {py, pz}, {py, nx}, {py, nz}, {ny, px}, {ny, pz},
                                             {ny, nx}, {ny, nz}, {px, pz}, {pz, nx}, {nx, nz}, {nz, px}};
    sampler random(26);
    int leaks = 0;
    for (int k = 0; k < 20000; ++k) {
        const point from = centre + 0.3 * vector(random.uniform(-1, 1), random.uniform(-1, 1), random.uniform(-1, 1));
        const auto& [p, q] = edges[k % 12];
        const point target = k % 5 == 0 ? corners[k % 6] : p + random.uniform(0, 1) * (q - p);
        if (!mesh_hit(solid, through(from, target))) ++leaks;
    }
    CHECK(leaks == 0);
}

TEST_CASE("triangle: a bumpy grid mesh lets no ray through its shared edges and vertices", "[02][triangle][triangles][watertight]") {
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
    sampler random(27);
    int leaks = 0;
    for (int k = 0; k < 20000; ++k) {
        const int i = 1 + static_cast<int>(random.uniform(0, n - 2)), j = 1 + static_cast<int>(random.uniform(0, n - 2));
        point target;
        switch (k % 4) {
        case 0: target = grid[i][j]; break;                                                    // a vertex
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
        if (!mesh_hit(surface, through(target + random.uniform(2, 30) * d.unit(), target))) ++leaks;
    }
    CHECK(leaks == 0);
}

TEST_CASE("triangle: the normal survives a rotation of the vertex order and flips under a swap", "[02][triangle][triangles]") {
    const point a(0.4, -1.3, 2.2), b(3.1, 0.2, -0.7), c(-1.5, 2.6, 0.9);
    const vector expected = ((b - a) % (c - a)).unit();
    const auto abc = make_triangle(a, b, c), bca = make_triangle(b, c, a), cab = make_triangle(c, a, b);
    const auto acb = make_triangle(a, c, b), bac = make_triangle(b, a, c);
    const point somewhere = a + 0.2 * (b - a) + 0.3 * (c - a);
    for (const auto* t : {abc.get(), bca.get(), cab.get()}) {
        const vector n = t->normal(somewhere);
        CHECK(n.x == Approx(expected.x).epsilon(1e-12));
        CHECK(n.y == Approx(expected.y).epsilon(1e-12));
        CHECK(n.z == Approx(expected.z).epsilon(1e-12));
        CHECK(n.length() == Approx(1).epsilon(1e-14));
    }
    for (const auto* t : {acb.get(), bac.get()}) {
        const vector n = t->normal(somewhere);
        CHECK(n.x == Approx(-expected.x).epsilon(1e-12));
        CHECK(n.y == Approx(-expected.y).epsilon(1e-12));
        CHECK(n.z == Approx(-expected.z).epsilon(1e-12));
    }
    CHECK_FALSE(abc->contains(somewhere));
}

TEST_CASE("triangle: its box is exactly the smallest one around the three vertices", "[02][triangle][triangles]") {
    const auto t = make_triangle(point(-1e5, 0.25, 7), point(3, -2e-3, -8.5), point(0.5, 9e4, 7.5));
    CHECK(t->min_point() == point(-1e5, -2e-3, -8.5));
    CHECK(t->max_point() == point(3, 9e4, 7.5));
    const auto flat = make_triangle(point(1, 1, 4), point(2, 1, 4), point(1, 3, 4));
    CHECK(flat->min_point() == point(1, 1, 4));
    CHECK(flat->max_point() == point(2, 3, 4));
}

TEST_CASE("triangle: make_triangle refuses coincident or non-finite vertices", "[02][triangle][triangles]") {
    const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
    CHECK_THROWS_AS(make_triangle(point(1, 2, 3), point(1, 2, 3), point(0, 0, 0)), vl::usage_error);
    CHECK_THROWS_AS(make_triangle(point(0, 0, 0), point(1, 0, 0), point(0, 0, 0)), vl::usage_error);
    CHECK_THROWS_AS(make_triangle(point(0, 0, 0), point(1, 0, 0), point(nan, 1, 0)), vl::usage_error);
    CHECK_THROWS_AS(make_triangle(point(inf, 0, 0), point(1, 0, 0), point(0, 1, 0)), vl::usage_error);
    CHECK_NOTHROW(make_triangle(point(0, 0, 0), point(1e-3, 0, 0), point(0, 1e-3, 0)));
}

TEST_CASE("triangle: an empty TRIANGLE in a scene file is the default one facing plus z", "[02][triangle][triangles][detail]") {
    const auto t = read_one("TRIANGLE { }");
    const intersection i = t->intersect(ray(point(0.25, 0.25, 2), vector(0, 0, -1)));
    REQUIRE(clean_hit(i, t.get()));
    CHECK(i.t == Approx(2).epsilon(1e-12));
    CHECK(clean_miss(t->intersect(ray(point(0.75, 0.75, 2), vector(0, 0, -1)))));
    CHECK(t->normal(point(0.25, 0.25, 0)) == vector(0, 0, 1));
}

TEST_CASE("triangle: a TRIANGLE written by write reads back with its vertices and surface", "[02][triangle][triangles]") {
    const auto first = read_one("TRIANGLE { c -0.3 2.1 0.7 a 0.1 0.2 0.3 b 1.7 -0.4 0.05 color 0.9 0.1 0.3 zero_t 1e-7 }");
    const std::string out = text_of(*first);
    INFO("write() gave: " << out);
    const auto second = read_one(out);
    CHECK(second->type_name() == "TRIANGLE");
    CHECK(text_of(*second) == out);
    CHECK(second->clr() == first->clr());
    CHECK(second->zero_t() == first->zero_t());
    CHECK(second->min_point() == first->min_point());
    CHECK(second->max_point() == first->max_point());
    CHECK(second->normal(point(0, 0, 0)) == first->normal(point(0, 0, 0)));
    sampler random(28);
    int differ = 0, hits = 0;
    for (int k = 0; k < 300; ++k) {
        const point target(random.uniform(-0.5, 2), random.uniform(-0.5, 2.2), random.uniform(0, 0.7));
        const ray r = through(random.in_box(6), target);
        const intersection i = first->intersect(r), j = second->intersect(r);
        if (i.hit() != j.hit() || i.t != j.t) ++differ;
        if (i.hit()) ++hits;
    }
    CHECK(differ == 0);
    CHECK(hits > 10);
}
