// Public tests of the box (stage_03.hh, box.cc). Run them with
// `build/student/stage_03_public_test "[box]"`. The answer key is the slab method
// (Kay and Kajiya) in long double, written in this file.
#include "vl/catch.hh"

#include <cmath>
#include <limits>
#include <vector>

#include "test_support.hh"

using namespace vl;
using namespace vl::stage03;
using namespace vl::stage03::testing;

namespace {

/// The outward normals of the faces: -x, +x, -y, +y, -z, +z.
const vector outward[6] = {{-1, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, 1, 0}, {0, 0, -1}, {0, 0, 1}};
const char* const face_name[6] = {"-x", "+x", "-y", "+y", "-z", "+z"};

/// The answer key: where `r` first meets the box [lo, hi] at t > 1e-6, and on which face.
struct slab_answer {
    bool hit = false;
    double t = 0;
    int face = -1;
};
slab_answer slabs(const point& lo, const point& hi, const ray& r) {
    using ld = long double;
    const double o[3] = {r.origin().x, r.origin().y, r.origin().z};
    const double d[3] = {r.direction().x, r.direction().y, r.direction().z};
    const double l[3] = {lo.x, lo.y, lo.z}, h[3] = {hi.x, hi.y, hi.z};
    ld enter = -std::numeric_limits<ld>::infinity(), leave = std::numeric_limits<ld>::infinity();
    int enter_face = -1, leave_face = -1;
    for (int a = 0; a < 3; ++a) {
        if (d[a] == 0) {
            if (o[a] <= l[a] || o[a] >= h[a]) return {};
            continue;
        }
        ld t_lo = (ld(l[a]) - o[a]) / d[a], t_hi = (ld(h[a]) - o[a]) / d[a];
        int f_lo = 2 * a, f_hi = 2 * a + 1;
        if (t_lo > t_hi) {
            std::swap(t_lo, t_hi);
            std::swap(f_lo, f_hi);
        }
        if (t_lo > enter) enter = t_lo, enter_face = f_lo;
        if (t_hi < leave) leave = t_hi, leave_face = f_hi;
    }
    if (enter > leave) return {};
    if (enter > 1e-6) return {true, static_cast<double>(enter), enter_face};
    if (leave > 1e-6) return {true, static_cast<double>(leave), leave_face};
    return {};
}

const point box_lo(-1, -0.5, -2), box_hi(2, 1.5, 0.5);

/// A random point strictly inside [box_lo, box_hi].
point inside_box(random_numbers& random) {
    return {random.uniform(box_lo.x + 0.01, box_hi.x - 0.01), random.uniform(box_lo.y + 0.01, box_hi.y - 0.01),
            random.uniform(box_lo.z + 0.01, box_hi.z - 0.01)};
}

/// Checks `i`, what the box returned for `r`, against the answer key: a hit on a face
/// (a leaf, never the box), at the key's t.
void check_against_key(const rtab_composite& box, const ray& r, const intersection& i, int& wrong, std::string& first) {
    const slab_answer key = slabs(box_lo, box_hi, r);
    bool same = i.hit() == key.hit;
    if (same && key.hit)
        same = std::fabs(i.t - key.t) <= 1e-9 * (1 + key.t) && i.object != &box && !i.object->is_composite();
    if (!same && wrong++ == 0)
        first = show(r) + " should " +
                (key.hit ? "hit the " + std::string(face_name[key.face]) + " face at t = " + num(key.t) : "miss") +
                "; yours gave " + show(i) +
                (i.object == &box && i.hit() ? " (the box itself: the object must be the face)" : "");
}

}  // namespace

TEST_CASE("box: a ray from outside hits the nearest face at the right distance", "[03][box][essential]") {
    const auto box = make_box(box_lo, box_hi);
    random_numbers random(41);
    int wrong = 0;
    std::string first;
    for (int k = 0; k < 1000; ++k) {
        point from = random.in_box(-6, 6);
        if (box->contains(from)) continue;
        const ray r = ray_through(from, inside_box(random));
        check_against_key(*box, r, box->intersect(r), wrong, first);
    }
    INFO(wrong << " rays from outside of the box " << show(box_lo) << " to " << show(box_hi)
               << " were wrong; the first: " << first);
    CHECK(wrong == 0);
}

TEST_CASE("box: a ray from inside hits the face it leaves through", "[03][box][essential]") {
    const auto box = make_box(box_lo, box_hi);
    random_numbers random(42);
    int wrong = 0;
    std::string first;
    for (int k = 0; k < 500; ++k) {
        const ray r(inside_box(random), random.direction());
        check_against_key(*box, r, box->intersect(r), wrong, first);
    }
    INFO(wrong << " of 500 rays from inside the box " << show(box_lo) << " to " << show(box_hi)
               << " were wrong; the first: " << first);
    CHECK(wrong == 0);
}

TEST_CASE("box: a ray that misses the box costs one box test and no face test", "[03][box][essential]") {
    const auto box = make_box(box_lo, box_hi);
    random_numbers random(43);
    int rays = 0;
    for (int k = 0; k < 400 && rays < 100; ++k) {
        const ray r(random.in_box(-6, 6), random.direction());
        if (slabs(box_lo, box_hi, r).hit) continue;
        ++rays;
        intersection i;
        const intersection_counts cost = cost_of([&] { i = box->intersect(r); });
        INFO(show(r) << " misses the box " << show(box_lo) << " to " << show(box_hi) << "; it gave " << show(i)
                     << " and cost " << show(cost));
        CHECK(i.is_miss());
        CHECK(cost.bounding_volume_tests == 1);
        CHECK(cost.primitive_tests == 0);
    }
    CHECK(rays == 100);
}

TEST_CASE("box: a ray that hits it tests the box once and each face at most once", "[03][box]") {
    const auto box = make_box(box_lo, box_hi);
    const ray r = ray_through(point(5, 4, 3), point(0.5, 0.5, -0.5));
    intersection i;
    const intersection_counts cost = cost_of([&] { i = box->intersect(r); });
    INFO(show(r) << " gave " << show(i) << " and cost " << show(cost));
    CHECK(i.hit());
    CHECK(cost.bounding_volume_tests == 1);
    CHECK(cost.primitive_tests >= 1);
    CHECK(cost.primitive_tests <= 6);
}

TEST_CASE("box: every face's normal points out of the box", "[03][box][essential]") {
    // The hit object is the face: its normal() is what a tracer shades with, so each face
    // must wind counter-clockwise seen from outside. box->normal() must agree.
    const auto box = make_box(box_lo, box_hi);
    const point middle(0.5, 0.5, -0.75);
    const vector half(1.5, 1, 1.25);
    for (int f = 0; f < 6; ++f) {
        const vector n = outward[f];
        // Aim at a point of the face off its centre, from 3 units outside it.
        const point on_face = middle + vector(n.x * half.x, n.y * half.y, n.z * half.z) +
                              0.3 * vector(n.y + n.z, n.z + n.x, n.x + n.y).unit();
        const ray r(on_face + 3 * n, -n);
        const intersection i = box->intersect(r);
        INFO("the " << face_name[f] << " face, " << show(r) << ": " << show(i));
        REQUIRE(i.hit());
        CHECK(i.t == Approx(3).epsilon(1e-12));
        const point p = r.t_point(i.t);
        const vector face_normal = i.object->normal(p), box_normal = box->normal(p);
        INFO("the face's normal at " << show(p) << " is " << show(face_normal) << ", the box's normal "
                                     << show(box_normal) << "; outward is " << show(n));
        CHECK(face_normal * n == Approx(1).epsilon(1e-12));
        CHECK(box_normal * n == Approx(1).epsilon(1e-12));
    }
}

TEST_CASE("box: normal is the outward normal of the face the point lies on", "[03][box]") {
    const auto box = make_box(point(0, 0, 0), point(4, 2, 1));
    random_numbers random(44);
    for (int k = 0; k < 60; ++k) {
        const int f = k % 6;
        point p(random.uniform(0.1, 3.9), random.uniform(0.1, 1.9), random.uniform(0.1, 0.9));
        if (f == 0) p.x = 0;
        if (f == 1) p.x = 4;
        if (f == 2) p.y = 0;
        if (f == 3) p.y = 2;
        if (f == 4) p.z = 0;
        if (f == 5) p.z = 1;
        const vector n = box->normal(p);
        INFO("the point " << show(p) << " on the " << face_name[f] << " face of the box (0, 0, 0) to (4, 2, 1): normal "
                          << show(n));
        CHECK(n * outward[f] == Approx(1).epsilon(1e-12));
        CHECK(n.length() == Approx(1).epsilon(1e-12));
    }
}

TEST_CASE("box: contains is true strictly inside and false on the faces and outside", "[03][box]") {
    const auto box = make_box(point(-1, 0, 2), point(1, 3, 4));
    CHECK(box->contains(point(0, 1, 3)));
    CHECK(box->contains(point(0.99, 2.99, 2.01)));
    CHECK_FALSE(box->contains(point(1, 1, 3)));  // on the +x face
    CHECK_FALSE(box->contains(point(0, 0, 3)));  // on the -y face
    CHECK_FALSE(box->contains(point(0, 1, 4.5)));
    CHECK_FALSE(box->contains(point(-2, 1, 3)));
}

TEST_CASE("box: min_point and max_point are its corners", "[03][box][detail]") {
    const auto box = make_box(point(-1, 0, 2), point(1, 3, 4));
    CHECK(box->min_point() == point(-1, 0, 2));
    CHECK(box->max_point() == point(1, 3, 4));
    const auto halved = make_box(point(2, 4, 6, 2), point(4, 6, 8, 2));  // w = 2: (1, 2, 3) to (2, 3, 4)
    CHECK(halved->min_point() == point(1, 2, 3));
    CHECK(halved->max_point() == point(2, 3, 4));
    CHECK(halved->intersect(ray(point(1.5, 2.5, 10), vector(0, 0, -1))).t == Approx(6).epsilon(1e-12));
}

TEST_CASE("box: refuses insert - delete_all_children and corners that are not below each other", "[03][box][detail]") {
    const auto box = make_box(point(0, 0, -3), point(1, 1, -2));
    const std::string insert = usage_error_of([&] { box->insert(std::make_unique<test_sphere>(point(0, 0, 0), 1)); });
    INFO("insert into a BOX: " << insert);
    CHECK_THAT(insert, Catch::Contains("LIST"));
    const std::string remove = usage_error_of([&] { box->delete_all_children(); });
    INFO("delete_all_children of a BOX: " << remove);
    CHECK(remove != "(no error)");
    // The box is unchanged.
    CHECK(box->intersect(ray(point(0.5, 0.5, 0), vector(0, 0, -1))).t == Approx(2).epsilon(1e-12));
    CHECK_THROWS_AS(make_box(point(0, 0, 0), point(1, 0, 1)), usage_error);  // no volume
    CHECK_THROWS_AS(make_box(point(2, 0, 0), point(1, 1, 1)), usage_error);
    CHECK_THROWS_AS(make_box(point(0, 0, 0), point(1, INFINITY, 1)), usage_error);
}

TEST_CASE("box: rays through an edge or a corner hit at the right distance", "[03][box][detail]") {
    // Two faces meet at an edge: a ray through it must not slip between them.
    const auto box = make_box(point(-1, -1, -1), point(1, 1, 1));
    const ray edge = ray_through(point(3, 0.25, 3), point(1, 0.25, 1));  // the edge x = z = 1
    const intersection i = box->intersect(edge);
    INFO(show(edge) << " through the edge x = z = 1 gave " << show(i));
    CHECK(i.hit());
    CHECK(i.t == Approx(2 * std::sqrt(2.0)).epsilon(1e-9));
    const ray corner = ray_through(point(3, 3, 3), point(1, 1, 1));
    const intersection j = box->intersect(corner);
    INFO(show(corner) << " through the corner (1, 1, 1) gave " << show(j));
    CHECK(j.hit());
    CHECK(j.t == Approx(2 * std::sqrt(3.0)).epsilon(1e-9));
}

TEST_CASE("scene: BOX reads its corners and surface and writes them back", "[03][box][scene]") {
    const std::string text = "BOX { min -1 0 -2  max 1 0.5 -1  color 0 1 0  kdr 0.5 }";
    const auto first = read_object(text);
    const std::string out = written(*first);
    INFO("read: " << text << "\nwritten: " << out);
    const auto second = read_object(out);
    CHECK(written(*second) == out);
    CHECK(second->min_point() == point(-1, 0, -2));
    CHECK(second->max_point() == point(1, 0.5, -1));
    // Every face has the surface that was read: shoot each face from outside.
    const point middle(0, 0.25, -1.5);
    const vector half(1, 0.25, 0.5);
    for (int f = 0; f < 6; ++f) {
        const vector n = outward[f];
        const point on_face = middle + vector(n.x * half.x, n.y * half.y, n.z * half.z);
        const intersection i = second->intersect(ray(on_face + 2 * n, -n));
        INFO("the " << face_name[f] << " face: " << show(i));
        REQUIRE(i.hit());
        CHECK(i.t == Approx(2).epsilon(1e-12));
        CHECK(i.object->clr() == color(0, 1, 0));
        CHECK(i.object->kdr() == 0.5);
    }
    // The default is the unit cube.
    const auto unit = read_object("BOX { }");
    CHECK(unit->min_point() == point(0, 0, 0));
    CHECK(unit->max_point() == point(1, 1, 1));
    CHECK(unit->intersect(ray(point(0.5, 0.5, 4), vector(0, 0, -1))).t == Approx(3).epsilon(1e-12));
}

TEST_CASE("scene: a bad BOX is refused at its place in the file", "[03][box][scene][detail]") {
    const std::string flat = read_error("BOX { min 0 0 0  max 1 0 1 }");
    INFO(flat);
    CHECK_THAT(flat, Catch::Contains("test.ray_trace:1:") && Catch::Contains("min"));
    const std::string child = read_error("BOX {\n  SPHERE { }\n}");
    INFO(child);
    CHECK_THAT(child, Catch::Contains("test.ray_trace:2:3"));
}
