// Hidden tests of stage 03's bounding sphere (bounding_sphere.cc, tag [boundsph]) and
// fractal spheres (frac_sphere.cc, tag [fracsph]), both in the rubric's "bounding_spheres"
// category. A bounding sphere's children are probes (hidden_support.hh): objects your code
// has never seen, which compute their own hits in long double and count their own tests.
// The fractal spheres are checked against a long-double model of the shape written here.
#include "vl/catch.hh"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "composite_checks.hh"
#include "hidden_support.hh"

using vl::intersection;
using vl::point;
using vl::ray;
using vl::rtab_component;
using vl::rtab_composite;
using vl::vector;
using vl::stage03::make_bounding_sphere;
using vl::stage03::make_frac_sphere;
using namespace vl::stage03::hidden;

namespace {

// --- the bounding sphere's model ---------------------------------------------------------------

/// The sphere the contract puts around children: around the union of their boxes, its
/// centre the box's centre, its radius half the box's diagonal.
struct ball {
    rvec c;
    real r = 0;
};
ball sphere_around(const std::vector<const rtab_component*>& children) {
    rvec lo = to_r(children.front()->min_point()), hi = to_r(children.front()->max_point());
    for (const rtab_component* k : children) {
        const rvec a = to_r(k->min_point()), b = to_r(k->max_point());
        lo = {std::min(lo.x, a.x), std::min(lo.y, a.y), std::min(lo.z, a.z)};
        hi = {std::max(hi.x, b.x), std::max(hi.y, b.y), std::max(hi.z, b.z)};
    }
    return {static_cast<real>(0.5) * (lo + hi), len(hi - lo) / 2};
}

/// How a ray meets a sphere as vl::hits_sphere() decides it, in long double: 1 enters,
/// 0 misses, -1 too close to the rim to say (within 1e-9 of the radius).
int meets(const ray& r, const ball& b) {
    const rvec o = to_r(r.origin()), d = unit(to_r(r.direction()));
    const rvec oc = b.c - o;
    const real along = dot(oc, d);
    const real dist = len(oc - along * d);
    if (std::fabs(dist - b.r) <= 1e-9L * b.r) return -1;
    if (dist > b.r) return 0;
    return along >= 0 || len(oc) <= b.r ? 1 : 0;
}

std::string describe(const ball& b) {
    return "the sphere around " + show(b.c) + " of radius " + num(static_cast<double>(b.r));
}

/// A ray from 3 radii away whose line passes at `fraction` of the radius from the centre.
ray ray_at_distance(dice& random, const ball& b, double fraction) {
    const vector d = random.direction();
    vector u = d % vector(0.3, 0.5, 0.8);
    u = u.unit();
    const vector v = (d % u).unit();
    const double turn = random.uniform(0, 2 * std::numbers::pi);
    const vector side = std::cos(turn) * u + std::sin(turn) * v;
    const point c = to_point(b.c);
    const double r = static_cast<double>(b.r);
    return ray(c + (fraction * r) * side - (3 * r) * d, d);
}

/// Random probes of every shape around `centre`, spread over `size`.
void random_probes(probe_set& set, rtab_composite& into, dice& random, int count, const point& centre, double size) {
    for (int k = 0; k < count; ++k) {
        const point c = centre + size * random.uniform(0, 1) * random.direction();
        switch (k % 3) {
            case 0: into.insert(set.add(std::make_unique<probe_sphere>(c, size * random.uniform(0.02, 0.3)))); break;
            case 1: {
                const vector e(size * random.uniform(0.02, 0.4), size * random.uniform(0.02, 0.4), size * random.uniform(0.02, 0.4));
                into.insert(set.add(std::make_unique<probe_cuboid>(c, c + e)));
                break;
            }
            default:
                into.insert(set.add(std::make_unique<probe_capsule>(c, c + size * 0.5 * random.direction(), size * 0.05)));
        }
    }
}

std::vector<const rtab_component*> children_of(const rtab_composite& c) {
    std::vector<const rtab_component*> out;
    for (const auto& k : c.children()) out.push_back(k.get());
    return out;
}

// --- the fractal spheres' model -------------------------------------------------------------

struct frac_node {
    rvec c;
    real r = 0, bound = 0;
    std::vector<std::size_t> kids;
};

/// The contract's fractal sphere, in long double: node 0 is the top.
struct frac_model {
    std::vector<frac_node> nodes;
    real ratio = 0;

    frac_model(const point& c, double r, int depth, double q) : ratio(q) { add(to_r(c), r, depth, -1); }

    std::size_t add(const rvec& c, real r, int depth, int parent_direction) {
        static const rvec directions[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
        const std::size_t at = nodes.size();
        nodes.push_back({});
        real bound = r, step = r;
        for (int level = 1; level <= depth; ++level) {
            step *= ratio;
            bound += 2 * step;
        }
        nodes[at].c = c;
        nodes[at].r = r;
        nodes[at].bound = bound;
        if (depth > 0) {
            const real small = r * ratio;
            for (int k = 0; k < 6; ++k) {
                if (k == parent_direction) continue;
                const std::size_t kid = add(c + (r + small) * directions[k], small, depth - 1, k ^ 1);
                nodes[at].kids.push_back(kid);
            }
        }
        return at;
    }

    /// The nearest sphere hit beyond `eps`: t (0 for none) and which node.
    std::pair<real, std::size_t> nearest(const ray& r, real eps) const {
        const rvec o = to_r(r.origin()), d = unit(to_r(r.direction()));
        real best = 0;
        std::size_t which = 0;
        for (std::size_t k = 0; k < nodes.size(); ++k) {
            const real t = first_beyond(sphere_roots(o, d, nodes[k].c, nodes[k].r), eps);
            if (t > 0 && (best == 0 || t < best)) {
                best = t;
                which = k;
            }
        }
        return {best, which};
    }

    /// What the tight nested bounds cost a ray: sphere tests and big-sphere tests; false
    /// when the ray passes too close to a bound's rim to say.
    bool cost_of(const ray& r, std::uint64_t& bounds, std::uint64_t& spheres) const {
        bounds = spheres = 0;
        bool clear = true;
        visit(r, 0, bounds, spheres, clear);
        return clear;
    }

private:
    void visit(const ray& r, std::size_t k, std::uint64_t& bounds, std::uint64_t& spheres, bool& clear) const {
        ++bounds;
        const int m = meets(r, {nodes[k].c, nodes[k].bound});
        if (m < 0) clear = false;
        if (m <= 0) return;
        ++spheres;
        for (const std::size_t kid : nodes[k].kids) visit(r, kid, bounds, spheres, clear);
    }
};

std::size_t sphere_count(int depth) {
    std::size_t p = 1;
    for (int k = 0; k < depth; ++k) p *= 5;
    return 1 + 6 * (p - 1) / 4;
}

std::string describe_frac(const point& c, double r, int depth, double q) {
    return "the FRACSPH of center " + show(c) + ", radius " + num(r) + ", depth " + std::to_string(depth) + " and ratio " +
           num(q);
}

/// Every primitive inside `o`, however deeply nested.
void leaves(const rtab_component& o, std::vector<const rtab_component*>& out) {
    const auto* c = dynamic_cast<const rtab_composite*>(&o);
    if (c == nullptr || !o.is_composite()) {
        out.push_back(&o);
        return;
    }
    for (const auto& k : c->children()) leaves(*k, out);
}

/// A sphere's centre and radius from its box (the spheres are stage 02's).
ball ball_of(const rtab_component& s) {
    const rvec lo = to_r(s.min_point()), hi = to_r(s.max_point());
    return {static_cast<real>(0.5) * (lo + hi), (hi.x - lo.x) / 2};
}

/// Checks that the primitives inside `frac` are the model's spheres, no more, no fewer.
void check_sphere_set(tally& t, const rtab_component& frac, const frac_model& model, const std::string& who) {
    std::vector<const rtab_component*> found;
    leaves(frac, found);
    const std::size_t want = model.nodes.size();
    if (!t.check(found.size() == want, [&] {
            return who + " should be made of " + std::to_string(want) + " spheres (1 + 6 (5^D - 1) / 4); yours holds " +
                   std::to_string(found.size()) + " primitives";
        }))
        return;
    auto key = [](const ball& b) { return std::make_tuple(b.c.x, b.c.y, b.c.z, b.r); };
    std::vector<ball> got, expected;
    for (const rtab_component* s : found) got.push_back(ball_of(*s));
    for (const frac_node& n : model.nodes) expected.push_back({n.c, n.r});
    real scale = 0;
    for (const ball& b : expected) scale = std::max(scale, len(b.c - expected.front().c) + b.r);
    const real tol = 1e-12L * (scale + std::fabs(expected.front().c.x) + std::fabs(expected.front().c.y) +
                               std::fabs(expected.front().c.z));
    // Match each expected sphere with a found one (sorted by x, then a local search).
    std::sort(got.begin(), got.end(), [&](const ball& a, const ball& b) { return key(a) < key(b); });
    std::vector<bool> used(got.size(), false);
    int missing = 0;
    std::string first_missing;
    for (const ball& e : expected) {
        auto from = std::lower_bound(got.begin(), got.end(), e.c.x - 2 * tol, [](const ball& a, real x) { return a.c.x < x; });
        bool matched = false;
        for (auto it = from; it != got.end() && it->c.x <= e.c.x + 2 * tol; ++it) {
            const std::size_t i = static_cast<std::size_t>(it - got.begin());
            if (!used[i] && len(it->c - e.c) <= 2 * tol && std::fabs(it->r - e.r) <= 2 * tol) {
                used[i] = matched = true;
                break;
            }
        }
        if (!matched && missing++ == 0) first_missing = describe(e);
    }
    t.check(missing == 0, [&] {
        return who + ": " + std::to_string(missing) + " of its " + std::to_string(want) +
               " spheres are not where the contract puts them (each of depth D - 1 and radius r Q at c + (r + r Q) u, "
               "in the six axis directions u but the one back to its parent); the first missing is " + first_missing;
    });
}

}  // namespace

// ================================================================================================
// BOUNDSPH
// ================================================================================================

TEST_CASE("boundsph: the sphere is the smallest one around the union of the children's boxes - not around their centres", "[03][boundsph][sphere][essential]") {
    // Rays that miss every child but pass inside the contract's sphere get composite_only of
    // the bounding sphere after one sphere test and one test of each child; rays that pass
    // outside it get a miss after that one sphere test alone.
    tally t("rays near the bounding sphere's rim");
    dice random(100);
    namer names;
    for (int scene = 0; scene < 6; ++scene) {
        probe_set set;
        auto bs = make_bounding_sphere();
        names.name(bs.get(), "the bounding sphere itself");
        if (scene == 0) {
            // A big child far off-centre and a tiny one: the sphere around the centres
            // would cut the big one off.
            bs->insert(set.add(std::make_unique<probe_sphere>(point(10, 0, 0), 5)));
            bs->insert(set.add(std::make_unique<probe_sphere>(point(-10, 0, 0), 0.1)));
        } else {
            random_probes(set, *bs, random, 2 + scene * 3, random.in_cube(-5, 5), random.uniform(0.5, 4));
        }
        for (const probe* p : set.all) names.name(p, p->describe());
        const ball want = sphere_around(children_of(*bs));
        const std::string who = "BOUNDSPH of " + std::to_string(set.all.size()) + " children whose boxes' union has " +
                                describe(want);
        for (int k = 0; k < 300; ++k) {
            const ray r = ray_at_distance(random, want, random.uniform(0, 1.3));
            const int m = meets(r, want);
            if (m < 0) continue;
            intersection got;
            const cost c = measure([&] { got = bs->intersect(r); });
            check_against_list(t, who, bs.get(), set, r, got, m == 1);
            if (set.nearest(r) > 0) continue;
            const std::uint64_t want_children = m == 1 ? set.all.size() : 0;
            t.check(c.counts.bounding_volume_tests == 1 && c.probe == want_children && c.counts.primitive_tests == want_children, [&] {
                return show(r) + (m == 1 ? " enters " : " misses ") + "the " + who + " and hits no child: it should cost one "
                       "sphere test and " + std::to_string(want_children) + " child tests; yours made " +
                       std::to_string(c.counts.bounding_volume_tests) + " bound tests and " + std::to_string(c.probe) +
                       " child tests";
            });
        }
    }
    t.report();
}

TEST_CASE("boundsph: the nearest hit of the children wins and names the leaf - also in bounding spheres inside bounding spheres and LISTs", "[03][boundsph][hits][essential]") {
    tally t("rays at nested bounding spheres");
    dice random(110);
    for (int scene = 0; scene < 5; ++scene) {
        probe_set set;
        auto outer = make_bounding_sphere();
        random_probes(set, *outer, random, 4 + scene, point(0, 0, 0), 2);
        for (int g = 0; g < 3; ++g) {
            auto inner = make_bounding_sphere();
            random_probes(set, *inner, random, 3 + g, random.in_cube(-3, 3), 1);
            if (g == 1) {
                auto deeper = make_bounding_sphere();
                random_probes(set, *deeper, random, 3, random.in_cube(-2, 2), 0.5);
                inner->insert(std::move(deeper));
                auto list = std::make_unique<vl::object_list>();
                random_probes(set, *list, random, 3, random.in_cube(-2, 2), 0.7);
                inner->insert(std::move(list));
            }
            outer->insert(std::move(inner));
        }
        const ball b = sphere_around(children_of(*outer));
        for (int k = 0; k < 400; ++k) {
            const ray r = k % 3 == 2 ? ray(to_point(b.c) + static_cast<double>(b.r) * 0.8 * random.direction(), random.direction())
                                     : ray_at_distance(random, b, random.uniform(0, 1.1));
            const int m = meets(r, b);
            if (m < 0) continue;
            intersection got;
            const cost c = measure([&] { got = outer->intersect(r); });
            check_against_list(t, "BOUNDSPH holding bounding spheres, a LIST and probes", outer.get(), set, r, got, m == 1);
            t.check(c.probe == c.counts.primitive_tests, [&] {
                return show(r) + ": the children counted " + std::to_string(c.probe) + " tests of their own, but vl::counts() "
                       "saw " + std::to_string(c.counts.primitive_tests) + " primitive tests (reach each child only through "
                       "its intersect())";
            });
        }
    }
    t.report();
}

TEST_CASE("boundsph: a ray that misses costs one sphere test - one that enters tests each child once - and nested spheres are tested only when entered", "[03][boundsph][budget][essential]") {
    tally t("the cost of rays at nested bounding spheres");
    dice random(120);
    for (int scene = 0; scene < 4; ++scene) {
        probe_set set;
        auto outer = make_bounding_sphere();
        std::vector<std::vector<const probe*>> groups;
        std::vector<ball> spheres;
        random_probes(set, *outer, random, 2, point(0, 0, 0), 1);
        const std::size_t direct = set.all.size();
        for (int g = 0; g < 4; ++g) {
            auto inner = make_bounding_sphere();
            const std::size_t before = set.all.size();
            random_probes(set, *inner, random, 3 + g, random.in_cube(-4, 4), 0.8);
            groups.emplace_back(set.all.begin() + static_cast<std::ptrdiff_t>(before), set.all.end());
            spheres.push_back(sphere_around(children_of(*inner)));
            outer->insert(std::move(inner));
        }
        const ball whole = sphere_around(children_of(*outer));
        for (int k = 0; k < 300; ++k) {
            const ray r = k % 2 == 0 ? ray_at_distance(random, whole, random.uniform(0, 1.2))
                                     : ray_at_distance(random, spheres[static_cast<std::size_t>(k / 2) % 4], random.uniform(0, 1.3));
            const int m = meets(r, whole);
            if (m < 0) continue;
            std::uint64_t want_bounds = 1, want_children = 0;
            bool clear = true;
            if (m == 1) {
                want_bounds += spheres.size();
                want_children += direct;
                for (std::size_t g = 0; g < spheres.size(); ++g) {
                    const int mg = meets(r, spheres[g]);
                    if (mg < 0) clear = false;
                    if (mg == 1) want_children += groups[g].size();
                }
            }
            if (!clear) continue;
            intersection got;
            const cost c = measure([&] { got = outer->intersect(r); });
            t.check(c.counts.bounding_volume_tests == want_bounds && c.probe == want_children, [&] {
                return show(r) + " at a BOUNDSPH of " + std::to_string(direct) + " probes and 4 bounding spheres of probes (" +
                       describe(whole) + "): the contract's spheres give " + std::to_string(want_bounds) + " sphere tests and " +
                       std::to_string(want_children) + " probe tests (each child of an entered sphere once, nothing inside a "
                       "sphere that is missed); yours made " + std::to_string(c.counts.bounding_volume_tests) + " and " +
                       std::to_string(c.probe);
            });
        }
    }
    t.report();
}

TEST_CASE("boundsph: rule 2 names the bounding sphere itself - also when a child answered composite_only - and an empty one is missed at no cost", "[03][boundsph][rules]") {
    tally t("the rules for no hit");
    namer names;
    auto bs = make_bounding_sphere();
    names.name(bs.get(), "the bounding sphere itself");
    insert_hollow_child(names, *bs);
    probe_set set;
    bs->insert(set.add(std::make_unique<probe_sphere>(point(3, 0, 0), 0.25)));
    check_composite_only_of(t, names, *bs, ray(point(0.5, 0.5, -5), vector(0, 0, 1)),
                            " enters only a child that answers composite_only of itself: the BOUNDSPH should return "
                            "composite_only of the BOUNDSPH");
    auto outer = make_bounding_sphere();
    names.name(outer.get(), "the outer bounding sphere");
    auto inner = make_bounding_sphere();
    names.name(inner.get(), "the inner bounding sphere (rule 2: the outer one names itself)");
    inner->insert(set.add(std::make_unique<probe_sphere>(point(0, 0, 0), 0.5)));
    inner->insert(set.add(std::make_unique<probe_sphere>(point(2, 2, 0), 0.5)));
    outer->insert(std::move(inner));
    check_composite_only_of(t, names, *outer, ray(point(1, 1, -5), vector(0, 0, 1)),
                            " enters a bounding sphere inside a bounding sphere but hits nothing: the outer one should "
                            "return composite_only of itself");
    auto empty = make_bounding_sphere();
    for (const ray& r : {ray(point(0, 0, 5), vector(0, 0, -1)), ray(point(0, 0, 0), vector(1, 0, 0))}) {
        intersection g3;
        const cost c = measure([&] { g3 = empty->intersect(r); });
        t.check(g3.is_miss() && g3.t == 0 && c.counts.bounding_volume_tests == 0, [&] {
            return show(r) + " at an empty BOUNDSPH should be a miss that costs no sphere test; yours returned " +
                   show(g3, names) + " after " + std::to_string(c.counts.bounding_volume_tests) + " bound tests";
        });
    }
    t.check(unknown(empty->min_point()) && unknown(empty->max_point()), [&] {
        return "an empty BOUNDSPH's box should be unknown (NaN_point); yours runs from " + show(empty->min_point()) + " to " +
               show(empty->max_point());
    });
    t.report();
}

TEST_CASE("boundsph: min_point() and max_point() are the union of the children's boxes - and contains() asks the children", "[03][boundsph][bounds]") {
    tally t("the bounding sphere's box");
    dice random(130);
    auto bs = make_bounding_sphere();
    probe_set set;
    box_union children;
    for (int k = 0; k < 12; ++k) {
        random_probes(set, *bs, random, 1, random.in_cube(-4, 4), random.uniform(0.2, 3));
        children.add(*set.all.back());
        check_box_is(t, *bs, children, "the BOUNDSPH of its first " + std::to_string(k + 1) + " children");
    }
    auto two = make_bounding_sphere();
    check_contains_of_two_spheres(t, *two, "BOUNDSPH");
    t.report();
}

TEST_CASE("boundsph: insert() refuses a child whose box is unknown - a null pointer and the bounding sphere itself", "[03][boundsph][refusals]") {
    tally t("refusals");
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    auto bs = make_bounding_sphere();
    probe_set set;
    bs->insert(set.add(std::make_unique<probe_sphere>(point(0, 0, -5), 1)));
    check_insert_refuses(t, *bs, "BOUNDSPH", {
        {"a PLANE", [] { return vl::stage02::make_plane(point(0, 0, 0), vector(0, 1, 0)); }},
        {"an empty LIST", [] { return std::make_unique<vl::object_list>(); }},
        {"an empty BOUNDSPH", [] { return make_bounding_sphere(); }},
        {"an object whose max_point() is NaN_point", [] { return std::make_unique<probe_boxless>(point(0, 0, 0), vl::NaN_point); }},
        {"an object whose box has a NaN coordinate",
         [nan] { return std::make_unique<probe_boxless>(point(0, nan, 0), point(1, 1, 1)); }},
        {"an object whose box is infinite", [inf] { return std::make_unique<probe_boxless>(point(0, 0, 0), point(1, 1, inf)); }},
        {"a null pointer", [] { return std::unique_ptr<rtab_component>(); }},
    }, [](const bad_child&, const std::string&) {});
    {
        rtab_composite* raw = make_bounding_sphere().release();
        raw->insert(std::make_unique<probe_sphere>(point(0, 0, 0), 1));
        std::string message;
        // When refused, the pointer handed over owned the sphere and has deleted it;
        // otherwise the sphere holds itself and is left alone (it cannot be destroyed).
        const bool refused = throws_usage_error([&] { raw->insert(std::unique_ptr<rtab_component>(raw)); }, message);
        t.check(refused, [&] { return "insert() of a BOUNDSPH into itself should throw vl::usage_error; " + message; });
    }
    // After the refusals the sphere still holds its one child, and its box is that child's.
    const ray r(point(0, 0, 0), vector(0, 0, -1));
    check_against_list(t, "BOUNDSPH after the refusals", bs.get(), set, r, bs->intersect(r), std::nullopt);
    check_point(t, "min_point() of the BOUNDSPH after the refusals", bs->min_point(), rvec{-1, -1, -6}, 0);
    check_point(t, "max_point() of the BOUNDSPH after the refusals", bs->max_point(), rvec{1, 1, -4}, 0);
    t.report();
}

TEST_CASE("boundsph: the refusal of an unbounded child names both types and the way out - and a scene file reports it at the child's place", "[03][boundsph][scene_io][detail]") {
    tally t("refused children");
    auto bs = make_bounding_sphere();
    std::string message;
    const bool refused =
        throws_usage_error([&] { bs->insert(vl::stage02::make_plane(point(0, 0, 0), vector(0, 1, 0))); }, message);
    t.check(refused && message.find("BOUNDSPH") != std::string::npos && message.find("PLANE") != std::string::npos &&
                message.find("LIST") != std::string::npos,
            [&] {
                return "inserting a PLANE into a BOUNDSPH should throw a vl::usage_error that names both types (BOUNDSPH, "
                       "PLANE) and says to put the plane beside it in a LIST; " + std::string(refused ? "yours says: " : "") + message;
            });
    check_refused(t, {{"BOUNDSPH {\n  PROBE { }\n  PLANE { }\n}", "hidden.ray_trace:3:3"},
                      {"BOUNDSPH { SPHERE { } LIST { } }", "hidden.ray_trace:1:23"},
                      {"LIST { BOUNDSPH {\n\n    BOUNDSPH { }\n} }", "hidden.ray_trace:3:5"}});
    t.report();
}

TEST_CASE("boundsph: BOUNDSPH { ... } is read from a scene file with its children - and write() gives them back", "[03][boundsph][scene_io]") {
    tally t("BOUNDSPH in scene files");
    dice random(140);
    std::string text = "BOUNDSPH {\n";
    for (int k = 0; k < 12; ++k) {
        const point c = random.in_cube(-2, 2);
        text += "  PROBE { center " + num(c.x) + " " + num(c.y) + " " + num(c.z) + " radius " + num(random.uniform(0.1, 0.8)) +
                " id " + std::to_string(k) + " }\n";
    }
    text += "}";
    check_read_write_read(
        t, text, "BOUNDSPH", 12,
        [&](const rtab_composite& bs, const probe_set& set, int pass) {
            if (set.all.empty()) return false;
            const ball b = sphere_around(children_of(bs));
            for (int k = 0; k < 200; ++k) {
                const ray r = ray_at_distance(random, b, random.uniform(0, 1.2));
                const int m = meets(r, b);
                if (m < 0) continue;
                check_against_list(t, pass == 0 ? "BOUNDSPH read from a scene file" : "BOUNDSPH read back from what write() wrote",
                                   &bs, set, r, bs.intersect(r), m == 1);
            }
            return true;
        },
        [&](const std::string& written) {
            t.check(written.rfind("BOUNDSPH", 0) == 0, [&] { return "write() of a BOUNDSPH should start with \"BOUNDSPH {\"; yours wrote \"" + written.substr(0, 100) + "\""; });
        });
    t.report();
}

// ================================================================================================
// FRACSPH
// ================================================================================================

namespace {
struct frac_case {
    point c;
    double r;
    int depth;
    double q;
};
const frac_case frac_cases[] = {{point(0, 0, 0), 1, 3, 0.4},       {point(1.5, -2, 0.25), 0.75, 2, 0.5},
                                {point(0, 0, 0), 1, 0, 0.4},       {point(-3, 1, 2), 2, 1, 0.3},
                                {point(0.1, 0.2, -0.3), 1, 4, 0.45}, {point(100, -50, 25), 10, 3, 0.25},
                                {point(0, 0, 0), 1, 2, 0.9}};
}  // namespace

TEST_CASE("fracsph: the spheres are the contract's: six children on the top sphere - five on every other - none towards the parent", "[03][fracsph][shape][essential]") {
    tally t("the spheres of fractal spheres");
    for (const frac_case& fc : frac_cases) {
        const auto frac = make_frac_sphere(fc.c, fc.r, fc.depth, fc.q);
        const frac_model model(fc.c, fc.r, fc.depth, fc.q);
        t.check(model.nodes.size() == sphere_count(fc.depth), [] { return std::string("(the tests' own model is wrong)"); });
        check_sphere_set(t, *frac, model, describe_frac(fc.c, fc.r, fc.depth, fc.q));
    }
    t.report();
}

TEST_CASE("fracsph: rays hit the nearest sphere of the fractal at the right distance - and that sphere is the object", "[03][fracsph][hits][essential]") {
    tally t("rays at fractal spheres");
    dice random(150);
    for (const frac_case& fc : frac_cases) {
        const auto frac = make_frac_sphere(fc.c, fc.r, fc.depth, fc.q);
        const frac_model model(fc.c, fc.r, fc.depth, fc.q);
        const std::string who = describe_frac(fc.c, fc.r, fc.depth, fc.q);
        const real extent = model.nodes[0].bound;
        for (int k = 0; k < 250; ++k) {
            // At random spheres of the model, at their rims, and at random points near the whole.
            const frac_node& aim = model.nodes[static_cast<std::size_t>(random.below(static_cast<int>(model.nodes.size())))];
            const point target = k % 2 == 0 ? to_point(aim.c) + static_cast<double>(aim.r) * random.uniform(0, 1.1) * random.direction()
                                            : to_point(model.nodes[0].c) + static_cast<double>(extent) * random.uniform(0, 1.1) * random.direction();
            const ray r = ray_through(to_point(model.nodes[0].c) + static_cast<double>(extent) * 3 * random.direction(), target);
            const auto [want, which] = model.nearest(r, 1e-6L);
            const intersection got = frac->intersect(r);
            const real scale = extent + len(to_r(r.origin()) - model.nodes[0].c);
            const double tol = static_cast<double>(1e-11L * scale);
            if (want > 0) {
                bool ok = got.hit() && std::fabs(got.t - static_cast<double>(want)) <= tol && got.object != frac.get() &&
                          !got.object->is_composite();
                if (ok) {
                    const ball b = ball_of(*got.object);
                    ok = len(b.c - model.nodes[which].c) <= 1e-11L * scale && std::fabs(b.r - model.nodes[which].r) <= 1e-11L * scale;
                }
                t.check(ok, [&] {
                    return show(r) + " at " + who + " should hit the sphere around " + show(model.nodes[which].c) + " of radius " +
                           num(static_cast<double>(model.nodes[which].r)) + " at t = " + num(static_cast<double>(want)) + " ± " +
                           num(tol) + ", with that sphere as the object; yours returned " +
                           (got.hit() ? "a hit at t = " + num(got.t) +
                                            (got.object->is_composite() ? " naming a composite, not the sphere"
                                                                        : " on the sphere of box " + show(got.object->min_point()) +
                                                                              " to " + show(got.object->max_point()))
                                      : got.object ? std::string("composite_only") : std::string("a miss"));
                });
            } else {
                t.check(!got.hit(), [&] { return show(r) + " at " + who + " should hit no sphere; yours hit at t = " + num(got.t); });
            }
        }
    }
    t.report();
}

TEST_CASE("fracsph: the bounds are tight: each ray makes exactly the sphere tests the nested bounds of radius r (1 + 2Q + ... + 2Q^D) imply", "[03][fracsph][budget][essential]") {
    tally t("the cost of rays at fractal spheres");
    dice random(160);
    for (const frac_case& fc : frac_cases) {
        const auto frac = make_frac_sphere(fc.c, fc.r, fc.depth, fc.q);
        const frac_model model(fc.c, fc.r, fc.depth, fc.q);
        const std::string who = describe_frac(fc.c, fc.r, fc.depth, fc.q);
        const real extent = model.nodes[0].bound;
        for (int k = 0; k < 250; ++k) {
            const frac_node& aim = model.nodes[static_cast<std::size_t>(random.below(static_cast<int>(model.nodes.size())))];
            const point target = k % 3 == 0 ? to_point(aim.c) + static_cast<double>(aim.bound) * random.uniform(0, 1.3) * random.direction()
                                            : to_point(model.nodes[0].c) + static_cast<double>(extent) * random.uniform(0, 1.3) * random.direction();
            const ray r = ray_through(to_point(model.nodes[0].c) + static_cast<double>(extent) * random.uniform(1.5, 4) * random.direction(), target);
            std::uint64_t bounds = 0, spheres = 0;
            if (!model.cost_of(r, bounds, spheres)) continue;
            const cost c = measure([&] { frac->intersect(r); });
            t.check(c.counts.bounding_volume_tests == bounds && c.counts.primitive_tests == spheres, [&] {
                return show(r) + " at " + who + ": the tight nested bounds give " + std::to_string(bounds) +
                       " sphere-bound tests (one per fractal sphere whose parent's bound the ray enters) and " +
                       std::to_string(spheres) + " sphere tests (one per bound entered); yours made " +
                       std::to_string(c.counts.bounding_volume_tests) + " bound tests and " +
                       std::to_string(c.counts.primitive_tests) + " sphere tests";
            });
        }
        // A ray that misses the whole fractal: one bound test.
        const ray away(to_point(model.nodes[0].c) + vector(0, 0, 3 * static_cast<double>(extent)), vector(0, 0, 1));
        const cost c = measure([&] { frac->intersect(away); });
        t.check(c.counts.bounding_volume_tests == 1 && c.counts.primitive_tests == 0, [&] {
            return show(away) + " points away from " + who + ": it should cost one bound test and no sphere test; yours made " +
                   std::to_string(c.counts.bounding_volume_tests) + " and " + std::to_string(c.counts.primitive_tests);
        });
    }
    t.report();
}

TEST_CASE("fracsph: rays that enter a bound for nothing get composite_only of the fractal - rays beside it a miss", "[03][fracsph][rules]") {
    tally t("rules at fractal spheres");
    dice random(170);
    for (const frac_case& fc : frac_cases) {
        const auto frac = make_frac_sphere(fc.c, fc.r, fc.depth, fc.q);
        const frac_model model(fc.c, fc.r, fc.depth, fc.q);
        const std::string who = describe_frac(fc.c, fc.r, fc.depth, fc.q);
        const ball top{model.nodes[0].c, model.nodes[0].bound};
        for (int k = 0; k < 200; ++k) {
            const ray r = ray_at_distance(random, top, random.uniform(0.5, 1.3));
            const int m = meets(r, top);
            if (m < 0 || model.nearest(r, 1e-6L).first > 0) continue;
            const intersection got = frac->intersect(r);
            const bool ok = m == 1 ? got.is_composite_only() && got.object == frac.get() : got.is_miss() && got.t == 0;
            t.check(ok, [&] {
                return show(r) + (m == 1 ? " enters the bound of " : " passes beside the bound of ") + who +
                       " and hits no sphere: it should return " +
                       (m == 1 ? "composite_only of the FRACSPH (rule 2)" : "a miss (rule 3)") + "; yours returned " +
                       (got.hit() ? "a hit at t = " + num(got.t)
                        : got.object == frac.get() ? std::string("composite_only of the FRACSPH")
                        : got.object ? "composite_only of another object (" + got.object->type_name() + ")"
                                     : std::string("a miss"));
            });
        }
    }
    t.report();
}

TEST_CASE("fracsph: min_point() and max_point() are the union of the spheres' boxes - and contains() is true inside any sphere", "[03][fracsph][bounds]") {
    tally t("the fractal's box and inside");
    dice random(180);
    for (const frac_case& fc : frac_cases) {
        const auto frac = make_frac_sphere(fc.c, fc.r, fc.depth, fc.q);
        const frac_model model(fc.c, fc.r, fc.depth, fc.q);
        const std::string who = describe_frac(fc.c, fc.r, fc.depth, fc.q);
        rvec lo = model.nodes[0].c, hi = lo;
        for (const frac_node& n : model.nodes) {
            lo = {std::min(lo.x, n.c.x - n.r), std::min(lo.y, n.c.y - n.r), std::min(lo.z, n.c.z - n.r)};
            hi = {std::max(hi.x, n.c.x + n.r), std::max(hi.y, n.c.y + n.r), std::max(hi.z, n.c.z + n.r)};
        }
        const real tol = 1e-12L * (model.nodes[0].bound + len(model.nodes[0].c));
        check_point(t, "min_point() of " + who, frac->min_point(), lo, tol);
        check_point(t, "max_point() of " + who, frac->max_point(), hi, tol);
        for (int k = 0; k < 60; ++k) {
            const frac_node& n = model.nodes[static_cast<std::size_t>(random.below(static_cast<int>(model.nodes.size())))];
            const point in = to_point(n.c) + static_cast<double>(n.r) * random.uniform(0, 0.95) * random.direction();
            t.check(frac->contains(in), [&] { return "contains(" + show(in) + ") of " + who + " should be true (inside one of its spheres)"; });
            const point out = to_point(model.nodes[0].c) + static_cast<double>(model.nodes[0].bound) * random.uniform(0, 1.2) * random.direction();
            bool inside = false;
            bool near_surface = false;
            for (const frac_node& m : model.nodes) {
                const real d = len(to_r(out) - m.c);
                inside = inside || d < m.r;
                near_surface = near_surface || std::fabs(d - m.r) < 1e-9L * m.r;
            }
            if (near_surface) continue;
            t.check(frac->contains(out) == inside, [&] {
                return "contains(" + show(out) + ") of " + who + " should be " + (inside ? "true" : "false") + "; yours is " +
                       (inside ? "false" : "true");
            });
        }
    }
    t.report();
}

TEST_CASE("fracsph: FRACSPH { } is center 0 0 0 - radius 1 - depth 3 - ratio 0.4 - and its surface keys reach every sphere", "[03][fracsph][scene_io]") {
    tally t("FRACSPH in scene files");
    const auto plain = read_one("FRACSPH { }");
    check_sphere_set(t, *plain, frac_model(point(0, 0, 0), 1, 3, 0.4), "FRACSPH { }");
    const vl::surface surf = full_precision_surface(1e-7 / 3);
    const std::string text = "FRACSPH { depth 2 ratio 0.35 center 0.5 -1 2 radius 1.25" + surface_text(surf) + " }";
    const auto read = read_one(text);
    const frac_model model(point(0.5, -1, 2), 1.25, 2, 0.35);
    check_sphere_set(t, *read, model, text);
    std::vector<const rtab_component*> found;
    leaves(*read, found);
    int wrong = 0;
    for (const rtab_component* s : found) {
        tally each("");
        compare_surface(surface_of(*s), surf, "a sphere", each);
        if (each.failed() > 0 && wrong++ == 0) compare_surface(surface_of(*s), surf, "a sphere of " + text, t);
    }
    t.check(wrong == 0, [&] {
        return std::to_string(wrong) + " of the " + std::to_string(found.size()) + " spheres of " + text +
               " do not have its surface keys (every sphere must)";
    });
    // The object a ray hits is a sphere with those keys.
    const ray r(point(0.5, -1, 10), vector(0, 0, -1));
    const intersection got = read->intersect(r);
    t.check(got.hit() && got.object != nullptr && got.object->clr() == surf.clr && got.object->kdr() == surf.kdr, [&] {
        return show(r) + " should hit a sphere of " + text + " with its colour and kdr; " +
               (got.hit() ? "the object hit has colour (" + num(got.object->clr().r) + ", " + num(got.object->clr().g) + ", " +
                                num(got.object->clr().b) + ") and kdr " + num(got.object->kdr())
                          : std::string("yours did not hit"));
    });
    t.report();
}

TEST_CASE("fracsph: write() gives back the FRACSPH it was read from - which reads back as the same spheres", "[03][fracsph][scene_io]") {
    tally t("FRACSPH written and read back");
    const std::string text = "FRACSPH { center 0.1 -0.2 0.3 radius 0.7 depth 2 ratio 0.45 kdr 0.25 }";
    const auto first = read_one(text);
    const std::string written = text_of(*first);
    t.check(written.rfind("FRACSPH", 0) == 0 && written.find("SPHERE {") == std::string::npos, [&] {
        return "write() of " + text + " should write one FRACSPH { ... }, never its generated spheres; yours wrote \"" +
               written.substr(0, 200) + "\"";
    });
    const auto back = read_one(written);
    check_sphere_set(t, *back, frac_model(point(0.1, -0.2, 0.3), 0.7, 2, 0.45), "the FRACSPH read back from \"" + written + "\"");
    std::vector<const rtab_component*> found;
    leaves(*back, found);
    t.check(!found.empty() && found.front()->kdr() == 0.25,
            [&] { return "the FRACSPH read back from \"" + written + "\" should keep kdr 0.25"; });
    t.report();
}

TEST_CASE("fracsph: make_frac_sphere() and the scene file refuse a depth outside 0 to 7 - a ratio not between 0 and 1 and a radius that is not > 0 - and insert() is refused", "[03][fracsph][refusals][detail]") {
    tally t("refusals");
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const struct {
        point c;
        double r;
        int depth;
        double q;
    } bad[] = {{point(0, 0, 0), 1, 8, 0.4},  {point(0, 0, 0), 1, -1, 0.4}, {point(0, 0, 0), 1, 3, 0},
               {point(0, 0, 0), 1, 3, 1},    {point(0, 0, 0), 0, 3, 0.4},  {point(0, 0, 0), -1, 3, 0.4},
               {point(nan, 0, 0), 1, 3, 0.4}, {point(0, 0, 0), 1, 3, nan}, {point(0, 0, 0), nan, 3, 0.4}};
    for (const auto& b : bad) {
        std::string message;
        t.check(throws_usage_error([&] { make_frac_sphere(b.c, b.r, b.depth, b.q); }, message), [&] {
            return "make_frac_sphere(" + show(b.c) + ", " + num(b.r) + ", " + std::to_string(b.depth) + ", " + num(b.q) +
                   ") should throw vl::usage_error; " + message;
        });
    }
    check_refused(t, {{"FRACSPH { depth 8 }", "hidden.ray_trace:1:17"},
                      {"FRACSPH {\n  ratio 1\n}", "hidden.ray_trace:2:9"},
                      {"FRACSPH { radius 0 }", "hidden.ray_trace:1:18"}});
    auto frac = make_frac_sphere(point(0, 0, 0), 1, 1, 0.5);
    std::string message;
    t.check(throws_usage_error([&] { frac->insert(std::make_unique<probe_sphere>(point(5, 0, 0), 1)); }, message),
            [&] { return "insert() into a FRACSPH should throw vl::usage_error (it makes its own spheres); " + message; });
    // The limits themselves are fine: depth 0 and 7, a ratio just inside (0, 1).
    check_sphere_set(t, *frac, frac_model(point(0, 0, 0), 1, 1, 0.5), "the FRACSPH of depth 1 after insert() was refused");
    check_sphere_set(t, *make_frac_sphere(point(0, 0, 0), 1, 0, 0.999), frac_model(point(0, 0, 0), 1, 0, 0.999),
                     "the FRACSPH of depth 0 and ratio 0.999");
    const auto deepest = make_frac_sphere(point(0, 0, 0), 1, 7, 0.3);
    std::vector<const rtab_component*> found;
    leaves(*deepest, found);
    t.check(found.size() == sphere_count(7), [&] {
        return "a FRACSPH of depth 7 should hold " + std::to_string(sphere_count(7)) + " spheres; yours holds " +
               std::to_string(found.size());
    });
    t.report();
}
