// Public tests of the fractal spheres (stage_03.hh, frac_sphere.cc). Run them with
// `build/student/stage_03_public_test "[fracsph]"`. The answer key is a fractal built by
// the test itself from the contract's description, in long double.
#include "vl/catch.hh"

#include <cmath>
#include <vector>

#include "test_support.hh"
#include "vl/object_list.hh"

using namespace vl;
using namespace vl::stage03;
using namespace vl::stage03::testing;

namespace {

/// One sphere of the answer key.
struct ball {
    long double x, y, z, r;
};

/// The contract's fractal: the sphere, then a fractal of depth - 1 and radius r Q
/// touching it in each axis direction but the one back to the parent.
void fractal(std::vector<ball>& out, long double x, long double y, long double z, long double r, int depth,
             long double ratio, int parent_direction = -1) {
    out.push_back({x, y, z, r});
    if (depth == 0) return;
    static const int axis[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    const long double small = r * ratio, step = r + small;
    for (int k = 0; k < 6; ++k) {
        if (k == parent_direction) continue;
        fractal(out, x + step * axis[k][0], y + step * axis[k][1], z + step * axis[k][2], small, depth - 1, ratio,
                k ^ 1);  // the child in direction k has its parent in the opposite direction
    }
}

/// r (1 + 2Q + 2Q^2 + ... + 2Q^D): from the centre to the tip of the longest chain.
double extent(double r, int depth, double ratio) {
    long double e = r, step = r;
    for (int level = 1; level <= depth; ++level) {
        step *= ratio;
        e += 2 * step;
    }
    return static_cast<double>(e);
}

/// Every leaf (non-composite) below `c`, found through children().
void collect_leaves(const rtab_component& c, std::vector<const rtab_component*>& out) {
    if (!c.is_composite()) {
        out.push_back(&c);
        return;
    }
    for (const auto& child : dynamic_cast<const rtab_composite&>(c).children()) collect_leaves(*child, out);
}

/// Your fractal's spheres (from their boxes) matched against the answer key: "" when
/// every sphere of the key is there once and nothing else, else the first problem.
std::string compare_spheres(const rtab_component& frac, const std::vector<ball>& key) {
    std::vector<const rtab_component*> leaves;
    collect_leaves(frac, leaves);
    if (leaves.size() != key.size())
        return "it has " + std::to_string(leaves.size()) + " spheres (leaves below it), the contract's fractal " +
               std::to_string(key.size());
    std::vector<bool> used(leaves.size(), false);
    for (const ball& b : key) {
        const double tolerance = 1e-12 * (1 + static_cast<double>(std::fabs(b.x) + std::fabs(b.y) + std::fabs(b.z)));
        bool found = false;
        for (std::size_t k = 0; k < leaves.size() && !found; ++k) {
            if (used[k]) continue;
            const point lo = leaves[k]->min_point(), hi = leaves[k]->max_point();
            const double x = (lo.x + hi.x) / 2, y = (lo.y + hi.y) / 2, z = (lo.z + hi.z) / 2, r = (hi.x - lo.x) / 2;
            if (std::fabs(x - static_cast<double>(b.x)) <= tolerance &&
                std::fabs(y - static_cast<double>(b.y)) <= tolerance &&
                std::fabs(z - static_cast<double>(b.z)) <= tolerance &&
                std::fabs(r - static_cast<double>(b.r)) <= tolerance)
                used[k] = found = true;
        }
        if (!found)
            return "the sphere of radius " + num(static_cast<double>(b.r)) + " at " +
                   show(point(static_cast<double>(b.x), static_cast<double>(b.y), static_cast<double>(b.z))) +
                   " is missing (or there twice, or at another place)";
    }
    return "";
}

/// The answer key as a LIST of the tests' own spheres.
std::unique_ptr<object_list> key_list(const std::vector<ball>& key) {
    auto list = std::make_unique<object_list>();
    int id = 0;
    for (const ball& b : key)
        list->insert(std::make_unique<test_sphere>(
            point(static_cast<double>(b.x), static_cast<double>(b.y), static_cast<double>(b.z)),
            static_cast<double>(b.r), id++));
    return list;
}

}  // namespace

TEST_CASE("fractal spheres: depth D has 1 + 6 (5^D - 1) / 4 spheres where the contract puts them",
          "[03][fracsph][essential]") {
    const int count[] = {1, 7, 37, 187, 937};
    for (int depth = 0; depth <= 4; ++depth) {
        const auto frac = make_frac_sphere(point(0.5, -1, 2), 1.5, depth, 0.4);
        std::vector<ball> key;
        fractal(key, 0.5, -1, 2, 1.5, depth, 0.4);
        REQUIRE(key.size() == static_cast<std::size_t>(count[depth]));
        const std::string diff = compare_spheres(*frac, key);
        INFO("make_frac_sphere((0.5, -1, 2), radius 1.5, depth " << depth << ", ratio 0.4): " << diff);
        CHECK(diff.empty());
    }
}

TEST_CASE("fractal spheres: give the same nearest hits as a LIST of the same spheres", "[03][fracsph][essential]") {
    const point c(0.5, -0.25, 1);
    const auto frac = make_frac_sphere(c, 1, 3, 0.4);
    std::vector<ball> key;
    fractal(key, 0.5, -0.25, 1, 1, 3, 0.4);
    const auto list = key_list(key);
    random_numbers random(31);
    int wrong = 0;
    std::string first;
    for (int k = 0; k < 1500; ++k) {
        // From 8 units away towards a random point within the fractal's extent (2.248).
        const vector u = random.direction();
        const ray r = ray_through(c + 8 * u, c + 2.3 * random.uniform(0, 1) * random.direction());
        const intersection got = frac->intersect(r), want = list->intersect(r);
        bool same = got.hit() == want.hit();
        if (same && want.hit()) {
            // The object must be the sphere hit (a leaf), and the point must lie on it.
            const point p = r.t_point(got.t);
            const point lo = got.object->min_point(), hi = got.object->max_point();
            const point centre((lo.x + hi.x) / 2, (lo.y + hi.y) / 2, (lo.z + hi.z) / 2);
            same = !got.object->is_composite() && std::fabs(got.t - want.t) <= 1e-9 &&
                   std::fabs((p - centre).length() - (hi.x - lo.x) / 2) <= 1e-9;
        }
        if (!same && wrong++ == 0) first = show(r) + " should give " + show(want) + "; yours gave " + show(got);
    }
    INFO(wrong << " of 1500 rays differ from a LIST of the same 187 spheres (the object of a hit must be the "
                  "sphere itself, never a fractal); the first: "
               << first);
    CHECK(wrong == 0);
}

TEST_CASE("fractal spheres: a ray that misses the fractal costs one bounding-volume test", "[03][fracsph][essential]") {
    // Depth 3, ratio 0.4, radius 0.5: the tight bound has radius E = 0.5 (1 + 0.8 + 0.32 +
    // 0.128) = 1.124. Rays that pass 2% outside it test nothing else. (A bound around the
    // box of the spheres would be sqrt(3) times too big: these rays would enter it.)
    const point c(1, 2, 3);
    const auto frac = make_frac_sphere(c, 0.5, 3, 0.4);
    const double e = extent(0.5, 3, 0.4);
    random_numbers random(32);
    for (int k = 0; k < 100; ++k) {
        const vector d = random.direction();
        const ray r(c + 1.02 * e * perpendicular(d) - 10 * d, d);
        intersection i;
        const intersection_counts cost = cost_of([&] { i = frac->intersect(r); });
        INFO(show(r) << " passes 1.02 E from the centre, E = " << num(e) << "; it gave " << show(i) << " and cost "
                     << show(cost));
        CHECK(i.is_miss());
        CHECK(cost.bounding_volume_tests == 1);
        CHECK(cost.primitive_tests == 0);
    }
}

TEST_CASE("fractal spheres: the bound reaches the tip of the longest chain - and a ray inside it that hits nothing is composite_only",
    "[03][fracsph]") {
    const point c(0, 0, 0);
    const double r = 1, q = 0.4;
    const auto frac = make_frac_sphere(c, r, 3, q);
    const double e = extent(r, 3, q), tip = r * q * q * q;  // the last sphere of the chain along +x
    // A ray down -z through the middle of the tip sphere's right half hits it.
    const ray graze(point(e - 0.5 * tip, 0, 10), vector(0, 0, -1));
    const intersection i = frac->intersect(graze);
    INFO(show(graze) << " should hit the smallest sphere at the tip of the +x chain (centre x = " << num(e - tip)
                     << ", radius " << num(tip) << ") at t = " << num(10 - tip * std::sqrt(0.75)) << "; it gave "
                     << show(i));
    REQUIRE(i.hit());
    CHECK(i.t == Approx(10 - tip * std::sqrt(0.75)).epsilon(1e-12));
    // A ray 2% inside the bound, along a diagonal where no sphere reaches: it enters the
    // bound for nothing, rule 2, with the fractal itself as the object.
    const vector u = vector(1, 1, 1).unit(), d = vector(1, -1, 0).unit();
    const ray inside(c + 0.98 * e * u - 10 * d, d);
    const intersection j = frac->intersect(inside);
    INFO(show(inside) << " enters the bound and hits no sphere; it gave " << show(j));
    CHECK(j.is_composite_only());
    CHECK(j.object == frac.get());
}

TEST_CASE("fractal spheres: a ray near one small sphere tests only the levels whose bounds it enters",
          "[03][fracsph]") {
    // The ray that grazes the tip of the +x chain enters the bounds of that chain only:
    // a few sphere tests per level, not all 187.
    const auto frac = make_frac_sphere(point(0, 0, 0), 1, 3, 0.4);
    const double e = extent(1, 3, 0.4), tip = 0.064;
    const ray graze(point(e - 0.5 * tip, 0, 10), vector(0, 0, -1));
    intersection i;
    const intersection_counts cost = cost_of([&] { i = frac->intersect(graze); });
    INFO(show(graze) << " gave " << show(i) << " and cost " << show(cost));
    CHECK(i.hit());
    CHECK(cost.primitive_tests <= 8);
    CHECK(cost.bounding_volume_tests <= 30);
}

TEST_CASE("fractal spheres: min_point and max_point reach the tips of the six chains", "[03][fracsph]") {
    const point c(1, -2, 0.5);
    const auto frac = make_frac_sphere(c, 2, 2, 0.3);
    const double e = extent(2, 2, 0.3);  // 2 (1 + 0.6 + 0.18) = 3.56
    const point lo = frac->min_point(), hi = frac->max_point();
    INFO("centre (1, -2, 0.5), radius 2, depth 2, ratio 0.3: the box should be the centre -+ "
         << num(e) << " in each axis; yours is " << show(lo) << " to " << show(hi));
    CHECK(lo.x == Approx(c.x - e).epsilon(1e-12));
    CHECK(lo.y == Approx(c.y - e).epsilon(1e-12));
    CHECK(lo.z == Approx(c.z - e).epsilon(1e-12));
    CHECK(hi.x == Approx(c.x + e).epsilon(1e-12));
    CHECK(hi.y == Approx(c.y + e).epsilon(1e-12));
    CHECK(hi.z == Approx(c.z + e).epsilon(1e-12));
}

TEST_CASE("fractal spheres: contains is true inside any sphere and false between them", "[03][fracsph]") {
    const auto frac = make_frac_sphere(point(0, 0, 0), 1, 3, 0.4);
    CHECK(frac->contains(point(0.2, 0.3, -0.1)));          // the big sphere
    CHECK(frac->contains(point(0, 1.4, 0.35)));            // the +y child
    CHECK(frac->contains(point(0, 0, -(2.248 - 0.064))));  // the tip of the -z chain
    CHECK_FALSE(frac->contains(point(1.1, 1.1, 0)));       // between the spheres
    CHECK_FALSE(frac->contains(point(0.8, 0.8, 0)));
    CHECK_FALSE(frac->contains(point(0, 0, -2.3)));  // beyond the tip
}

TEST_CASE("fractal spheres: bad values and insert are refused", "[03][fracsph][detail]") {
    // A good one first (the refusals below are done for you; building the spheres is not).
    const auto frac = make_frac_sphere(point(0, 0, 0), 1, 1, 0.5);
    CHECK(frac->intersect(ray(point(0, 0, 5), vector(0, 0, -1))).t == Approx(3).epsilon(1e-12));  // the +z child
    CHECK_THROWS_AS(make_frac_sphere(point(0, 0, 0), 0, 3, 0.4), usage_error);
    CHECK_THROWS_AS(make_frac_sphere(point(0, 0, 0), 1, -1, 0.4), usage_error);
    CHECK_THROWS_AS(make_frac_sphere(point(0, 0, 0), 1, 8, 0.4), usage_error);
    CHECK_THROWS_AS(make_frac_sphere(point(0, 0, 0), 1, 3, 1), usage_error);
    CHECK_THROWS_AS(make_frac_sphere(point(0, 0, 0), 1, 3, 0), usage_error);
    CHECK_THROWS_AS(make_frac_sphere(point(0, NaN, 0), 1, 3, 0.4), usage_error);
    const std::string insert = usage_error_of([&] { frac->insert(std::make_unique<test_sphere>(point(5, 5, 5), 1)); });
    INFO("inserting into a FRACSPH: " << insert);
    CHECK(insert != "(no error)");
}

TEST_CASE("scene: FRACSPH reads its values and writes them back", "[03][fracsph][scene]") {
    const std::string text = "FRACSPH { center 1 2 -3  radius 0.5  depth 2  ratio 0.3  color 1 0 0 }";
    const auto first = read_object(text);
    const std::string out = written(*first);
    INFO("read: " << text << "\nwritten: " << out);
    const auto second = read_object(out);
    CHECK(written(*second) == out);
    std::vector<ball> key;
    fractal(key, 1, 2, -3, 0.5, 2, 0.3);
    const std::string diff = compare_spheres(*second, key);
    INFO("read back: " << diff);
    CHECK(diff.empty());
    // Down -z onto the tip of the +z chain: -3 + 0.5 (1 + 0.6 + 0.18) = -2.11.
    CHECK(first->intersect(ray(point(1, 2, 0), vector(0, 0, -1))).t == Approx(2.11).epsilon(1e-12));

    // The defaults: centre 0 0 0, radius 1, depth 3, ratio 0.4.
    std::vector<ball> defaults;
    fractal(defaults, 0, 0, 0, 1, 3, 0.4);
    const std::string default_diff = compare_spheres(*read_object("FRACSPH { }"), defaults);
    INFO("FRACSPH { }: " << default_diff);
    CHECK(default_diff.empty());
}

TEST_CASE("scene: a bad FRACSPH is refused at the value at fault", "[03][fracsph][scene][detail]") {
    CHECK_THAT(read_error("FRACSPH { depth 8 }"), Catch::Contains("test.ray_trace:1:17") && Catch::Contains("depth"));
    CHECK_THAT(read_error("FRACSPH { ratio 1 }"), Catch::Contains("test.ray_trace:1:17") && Catch::Contains("ratio"));
    CHECK_THAT(read_error("FRACSPH { radius 0 }"), Catch::Contains("test.ray_trace:1:18") && Catch::Contains("radius"));
    CHECK_THAT(read_error("LIST { FRACSPH { depth 1 SPHERE { } } }"), Catch::Contains("test.ray_trace:1:"));
}
