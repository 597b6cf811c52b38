// Hidden tests of stage 01 (grader only; students never see this file). Each TEST_CASE is
// one graded item; its tags name the rubric category (rubric.toml).
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <set>
#include <vector>

#include "stage_01.hh"
#include "vl/error.hh"

using namespace vl;
using namespace vl::stage01;

namespace {

constexpr double pi = std::numbers::pi;

double max_difference(const matrix& a, const matrix& b) {
    double most = 0;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) most = std::max(most, std::abs(a(r, c) - b(r, c)));
    return most;
}

camera_settings settings(point eye, point look_at, vector up, double fov) {
    camera_settings s;
    s.eye = eye;
    s.look_at = look_at;
    s.up = up;
    s.fov_degrees = fov;
    return s;
}

}  // namespace

// --- transforms ---------------------------------------------------------------------------

TEST_CASE("transforms: a translation moves points and leaves vectors alone", "[01][transforms]") {
    const matrix m = translate_matrix(vector(1, -2, 3));
    const point p = m * point(4, 5, 6);
    CHECK(p.x == Approx(5));
    CHECK(p.y == Approx(3));
    CHECK(p.z == Approx(9));
    const vector v = m * vector(4, 5, 6);
    CHECK(v.x == Approx(4));
    CHECK(v.z == Approx(6));
}

TEST_CASE("transforms: quarter turns follow the right-hand rule", "[01][transforms]") {
    const vector y = rotate_z_matrix(pi / 2) * vector(1, 0, 0);
    CHECK(y.y == Approx(1));
    CHECK(y.x == Approx(0).margin(1e-12));
    const vector z = rotate_x_matrix(pi / 2) * vector(0, 1, 0);
    CHECK(z.z == Approx(1));
    const vector x = rotate_y_matrix(pi / 2) * vector(0, 0, 1);
    CHECK(x.x == Approx(1));
}

TEST_CASE("transforms: a rotation about an axis keeps the axis and turns the rest", "[01][transforms]") {
    CHECK(max_difference(rotate_matrix(vector(0, 0, 5), 0.7), rotate_z_matrix(0.7)) < 1e-12);
    CHECK(max_difference(rotate_matrix(vector(0, 0, -1), 0.7), rotate_z_matrix(-0.7)) < 1e-12);
    const vector axis(1, 1, 1);
    const vector kept = rotate_matrix(axis, 1.3) * axis;
    CHECK((kept - axis).length() < 1e-12);
    CHECK_THROWS_AS(rotate_matrix(vector(0, 0, 0), 1), vl::usage_error);
}

TEST_CASE("transforms: scale and shear act on points and vectors alike", "[01][transforms]") {
    const point p = scale_matrix(2, -1, 0.5) * point(1, 2, 4);
    CHECK(p.x == Approx(2));
    CHECK(p.y == Approx(-2));
    CHECK(p.z == Approx(2));
    const vector v = shear_matrix(0.5, -1) * vector(1, 1, 2);
    CHECK(v.x == Approx(2));
    CHECK(v.y == Approx(-1));
    CHECK(v.z == Approx(2));
}

TEST_CASE("transforms: the look-at matrix takes the eye to the origin, looking down -z", "[01][transforms]") {
    const point eye(1, 2, 3), at(4, 6, 3);
    const matrix m = look_at_matrix(eye, at, vector(0, 0, 1));
    const point o = m * eye;
    CHECK(vector(o.x, o.y, o.z).length() < 1e-12);
    const point a = m * at;
    CHECK(a.x == Approx(0).margin(1e-12));
    CHECK(a.y == Approx(0).margin(1e-12));
    CHECK(a.z == Approx(-5));
    CHECK_THROWS_AS(look_at_matrix(eye, eye, vector(0, 1, 0)), vl::usage_error);
}

// --- inverse ------------------------------------------------------------------------------

TEST_CASE("inverse: a general matrix times its inverse is the identity", "[01][inverse]") {
    const matrix m(2, 1, 0, 3, -1, 4, 2, 0, 0.5, 0, 3, 1, 1, 2, -1, 5);
    CHECK(max_difference(m * inverse(m), IDENTITY) < 1e-12);
    CHECK(max_difference(inverse(m) * m, IDENTITY) < 1e-12);
}

TEST_CASE("inverse: a zero on the diagonal is pivoted away", "[01][inverse]") {
    const matrix m = rotate_z_matrix(pi / 2) * translate_matrix(vector(1, 2, 3));
    const matrix exact(0, 1, 0, 0, -1, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1);
    const matrix r(0, -1, 0, 0, 1, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1);
    CHECK(max_difference(inverse(r), exact) < 1e-15);
    CHECK(max_difference(m * inverse(m), IDENTITY) < 1e-12);
}

TEST_CASE("inverse: a tiny leading pivot does not ruin the result", "[01][inverse]") {
    // Without pivoting, dividing by 1e-20 leaves nothing of the other entries.
    const matrix m(1e-20, 1, 0, 0, 1, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1);
    const matrix x = inverse(m);
    CHECK(x(0, 0) == Approx(-1).epsilon(1e-12));
    CHECK(x(0, 1) == Approx(1).epsilon(1e-12));
    CHECK(x(1, 0) == Approx(1).epsilon(1e-12));
    CHECK(x(1, 1) == Approx(-1e-20).margin(1e-30));
}

TEST_CASE("inverse: a singular matrix gives NaN everywhere", "[01][inverse]") {
    const matrix m(1, 2, 3, 4, 2, 4, 6, 8, 0, 1, 0, 1, 1, 0, 0, 1);
    const matrix x = inverse(m);
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) CHECK(std::isnan(x(r, c)));
}

// --- camera -------------------------------------------------------------------------------

TEST_CASE("camera: the image's centre looks exactly at look_at", "[01][camera]") {
    const auto cam = make_pinhole_camera(settings({1, 2, 3}, {4, 2, -1}, {0, 1, 0}, 50), 64, 48);
    const ray r = cam->primary_ray(32, 24);
    const vector expected = (point(4, 2, -1) - point(1, 2, 3)).unit();
    CHECK((r.direction() - expected).length() < 1e-12);
    CHECK((r.origin() - point(1, 2, 3)).length() < 1e-12);
}

TEST_CASE("camera: rays through the bottom and top edges are fov apart", "[01][camera]") {
    const auto cam = make_pinhole_camera(settings({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 60), 80, 40);
    const vector bottom = cam->primary_ray(40, 0).direction(), top = cam->primary_ray(40, 40).direction();
    CHECK(std::acos(bottom * top) == Approx(pi / 3).epsilon(1e-12));
    CHECK(top.y > 0);
}

TEST_CASE("camera: image position (0, 0) is the lower-left corner", "[01][camera]") {
    const auto cam = make_pinhole_camera(settings({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 90), 100, 100);
    const vector d = cam->primary_ray(0, 0).direction();
    CHECK(d.x == Approx(-1 / std::sqrt(3.0)).epsilon(1e-12));
    CHECK(d.y == Approx(-1 / std::sqrt(3.0)).epsilon(1e-12));
    const vector c = cam->primary_ray(75, 50).direction();
    CHECK(c.x == Approx(0.5 / std::sqrt(1.25)).epsilon(1e-12));
}

TEST_CASE("camera: bad settings are refused", "[01][camera]") {
    CHECK_THROWS_AS(make_pinhole_camera(settings({0, 0, 0}, {0, 0, 0}, {0, 1, 0}, 45), 10, 10), vl::usage_error);
    CHECK_THROWS_AS(make_pinhole_camera(settings({0, 0, 0}, {0, 0, -1}, {0, 0, 1}, 45), 10, 10), vl::usage_error);
    CHECK_THROWS_AS(make_pinhole_camera(settings({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 180), 10, 10), vl::usage_error);
}

// --- samplers -----------------------------------------------------------------------------

TEST_CASE("samplers: grid samples are cell centres, row by row from the bottom", "[01][samplers]") {
    const auto s = make_sampler("grid");
    REQUIRE(s);
    std::vector<sample_offset> out(4);
    s->offsets(out, 1);
    CHECK(out[0].dx == Approx(0.25));
    CHECK(out[0].dy == Approx(0.25));
    CHECK(out[1].dx == Approx(0.75));
    CHECK(out[1].dy == Approx(0.25));
    CHECK(out[2].dx == Approx(0.25));
    CHECK(out[2].dy == Approx(0.75));
}

TEST_CASE("samplers: jittered samples stay in their cells and repeat for a seed", "[01][samplers]") {
    const auto s = make_sampler("jittered");
    REQUIRE(s);
    std::vector<sample_offset> a(9), b(9), c(9);
    s->offsets(a, 42);
    make_sampler("jittered")->offsets(b, 42);
    s->offsets(c, 43);
    bool differs = false;
    for (std::size_t i = 0; i < 9; ++i) {
        CHECK(a[i].dx == b[i].dx);
        CHECK(a[i].dy == b[i].dy);
        CHECK(a[i].dx >= (i % 3) / 3.0);
        CHECK(a[i].dx < (i % 3 + 1) / 3.0);
        CHECK(a[i].dy >= (i / 3) / 3.0);
        CHECK(a[i].dy < (i / 3 + 1) / 3.0);
        differs = differs || a[i].dx != c[i].dx;
    }
    CHECK(differs);
}

TEST_CASE("samplers: unknown names give no sampler", "[01][samplers]") {
    CHECK(make_sampler("Grid") == nullptr);
    CHECK(make_sampler("stratified") == nullptr);
    REQUIRE(make_sampler("center"));
    std::vector<sample_offset> out(3);
    make_sampler("center")->offsets(out, 7);
    for (const auto& o : out) CHECK((o.dx == 0.5 && o.dy == 0.5));
}
