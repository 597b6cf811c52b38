// Public tests of the pinhole camera (pinhole_camera.cc). The contract is stage_01.hh; the
// interface is vl::camera in vl/camera.hh.
#include "vl/catch.hh"

#include <cmath>
#include <numbers>

#include "test_support.hh"
#include "vl/error.hh"

using namespace vl;
using namespace vl::stage01;
using vl::test01::degrees_between;
using vl::test01::distance;
using vl::test01::settings;

namespace {

constexpr double tol = 1e-14;

/// The default view: from (0, 0, 5) towards the origin, +y up.
camera_settings straight(double fov) { return settings({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, fov); }

/// Where the ray through (x, y) meets the plane one unit in front of the eye, relative to
/// the eye: the image plane, whatever length the camera gave its directions.
vector on_image_plane(const camera& c, const vector& forward, double x, double y) {
    const vector d = c.primary_ray(x, y).direction();
    return d / (d * forward);
}

}  // namespace

TEST_CASE("camera: every ray starts at the eye and has a unit direction", "[01][camera]") {
    const point eye(1, -2, 3);
    const auto c = make_pinhole_camera(settings(eye, {4, 0, -1}, {0, 0, 1}, 50), 64, 48);
    for (const auto& [x, y] : {std::pair{0.0, 0.0}, {64.0, 48.0}, {10.5, 3.25}, {63.9, 0.1}}) {
        const ray r = c->primary_ray(x, y);
        CAPTURE(x, y, r);
        CHECK(distance(r.origin(), eye) == 0);
        CHECK(r.direction().length() == Approx(1).margin(tol));
    }
}

TEST_CASE("camera: the centre of the image looks exactly at look_at", "[01][camera]") {
    const point eye(3, 4, 5), at(-1, 2, 0);
    const auto c = make_pinhole_camera(settings(eye, at, {0, 1, 0}, 35), 321, 199);  // odd sizes
    CHECK(distance(c->primary_ray(160.5, 99.5).direction(), (at - eye).unit()) < 1e-15);
    // Far away, the direction must still be right to the last digits.
    const point far_eye(1e6, -2e6, 3e6);
    const auto far = make_pinhole_camera(settings(far_eye, at, {0, 1, 0}, 35), 320, 200);
    CHECK(distance(far->primary_ray(160, 100).direction(), (at - far_eye).unit()) < 1e-15);
}

TEST_CASE("camera: image position 0 0 is the lower-left corner of the image as in the vfb", "[01][camera]") {
    const auto c = make_pinhole_camera(straight(60), 40, 30);
    const vector lower_left = c->primary_ray(0, 0).direction();
    const vector upper_right = c->primary_ray(40, 30).direction();
    CHECK(lower_left.x < 0);  // left
    CHECK(lower_left.y < 0);  // and down
    CHECK(upper_right.x > 0);
    CHECK(upper_right.y > 0);
    // Moving up the image (larger y) moves the ray up in the world.
    CHECK(c->primary_ray(20, 20).direction().y > c->primary_ray(20, 10).direction().y);
}

TEST_CASE("camera: the field of view spans the image's height - not its width", "[01][camera]") {
    const double fov = 40;
    const auto c = make_pinhole_camera(straight(fov), 320, 240);
    const double vertical = degrees_between(c->primary_ray(160, 0).direction(), c->primary_ray(160, 240).direction());
    CHECK(vertical == Approx(fov).epsilon(1e-12));
    // The width follows from square pixels: tan(horizontal / 2) = (4 / 3) tan(fov / 2).
    const double horizontal = degrees_between(c->primary_ray(0, 120).direction(), c->primary_ray(320, 120).direction());
    const double expected = 2 * std::atan(320.0 / 240 * std::tan(fov / 2 * std::numbers::pi / 180)) * 180 / std::numbers::pi;
    CHECK(horizontal == Approx(expected).epsilon(1e-12));
    // The same fov on a tall image still spans the height.
    const auto tall = make_pinhole_camera(straight(fov), 100, 400);
    CHECK(degrees_between(tall->primary_ray(50, 0).direction(), tall->primary_ray(50, 400).direction()) ==
          Approx(fov).epsilon(1e-12));
}

TEST_CASE("camera: rays through the four image corners", "[01][camera]") {
    // fov 90 on a 200 x 100 image: the image plane at distance 1 is 2 high and 4 wide.
    const auto c = make_pinhole_camera(straight(90), 200, 100);
    CHECK(distance(c->primary_ray(0, 0).direction(), vector(-2, -1, -1).unit()) < tol);
    CHECK(distance(c->primary_ray(200, 0).direction(), vector(2, -1, -1).unit()) < tol);
    CHECK(distance(c->primary_ray(0, 100).direction(), vector(-2, 1, -1).unit()) < tol);
    CHECK(distance(c->primary_ray(200, 100).direction(), vector(2, 1, -1).unit()) < tol);
}

TEST_CASE("camera: pixels are square and evenly spaced on the image plane", "[01][camera]") {
    const vector forward(0, 0, -1);
    const auto c = make_pinhole_camera(straight(30), 300, 100);
    const vector here = on_image_plane(*c, forward, 37, 81);
    const vector right = on_image_plane(*c, forward, 38, 81) - here;
    const vector up = on_image_plane(*c, forward, 37, 82) - here;
    CHECK(right.length() == Approx(up.length()).epsilon(1e-12));
    CHECK(right * up == Approx(0).margin(1e-15));
    // Ten pixels along is ten times one pixel along.
    CHECK(distance(on_image_plane(*c, forward, 47, 81) - here, right * 10) < 1e-13);
}

TEST_CASE("camera: positions outside the image continue the image plane", "[01][camera]") {
    const vector forward(0, 0, -1);
    const auto c = make_pinhole_camera(straight(45), 100, 80);
    const vector centre = on_image_plane(*c, forward, 50, 40);
    const vector left = on_image_plane(*c, forward, -50, 40) - centre;
    const vector right = on_image_plane(*c, forward, 150, 40) - centre;
    CHECK(distance(left, -right) < tol);
    CHECK(right.x > 0);
}

TEST_CASE("camera: only the part of up perpendicular to the view counts", "[01][camera]") {
    const auto plain = make_pinhole_camera(straight(50), 64, 64);
    const auto tilted = make_pinhole_camera(settings({0, 0, 5}, {0, 0, 0}, {0, 2, 7}, 50), 64, 64);
    for (const auto& [x, y] : {std::pair{0.0, 0.0}, {64.0, 0.0}, {13.0, 51.0}})
        CHECK(distance(plain->primary_ray(x, y).direction(), tilted->primary_ray(x, y).direction()) < tol);
}

TEST_CASE("camera: an up of +x turns the image on its side", "[01][camera]") {
    // Looking down -z with +x up, the image's right is (view direction) % up = -y.
    const auto c = make_pinhole_camera(settings({0, 0, 5}, {0, 0, 0}, {1, 0, 0}, 60), 80, 60);
    const vector top = c->primary_ray(40, 60).direction();
    CHECK(top.x > 0);
    CHECK(std::abs(top.y) < tol);
    const vector right = c->primary_ray(80, 30).direction();
    CHECK(right.y < 0);
    CHECK(std::abs(right.x) < tol);
}

TEST_CASE("camera: looking along any direction - right is level and the frame is right-handed", "[01][camera]") {
    const point eye(3, 4, 5), at(-1, 2, 0);
    const vector up(0, 1, 0), forward = (at - eye).unit();
    const auto c = make_pinhole_camera(settings(eye, at, up, 70), 160, 90);
    const vector right = on_image_plane(*c, forward, 160, 45) - on_image_plane(*c, forward, 0, 45);
    const vector image_up = on_image_plane(*c, forward, 80, 90) - on_image_plane(*c, forward, 80, 0);
    CHECK(right * up == Approx(0).margin(tol));        // the horizon stays level
    CHECK(right * forward == Approx(0).margin(tol));   // the image plane faces the eye
    CHECK(image_up * up > 0);                          // up is up, not down
    CHECK((right % image_up) * forward < 0);           // right x up points back at the eye
}

TEST_CASE("camera: impossible settings throw usage_error", "[01][camera]") {
    CHECK_THROWS_AS(make_pinhole_camera(settings({1, 1, 1}, {1, 1, 1}, {0, 1, 0}, 45), 10, 10), usage_error);
    CHECK_THROWS_AS(make_pinhole_camera(settings({0, 5, 0}, {0, 0, 0}, {0, 1, 0}, 45), 10, 10), usage_error);
    CHECK_THROWS_AS(make_pinhole_camera(settings({0, 0, 5}, {0, 0, 0}, {0, 0, 0}, 45), 10, 10), usage_error);
    CHECK_THROWS_AS(make_pinhole_camera(straight(0), 10, 10), usage_error);
    CHECK_THROWS_AS(make_pinhole_camera(straight(180), 10, 10), usage_error);
    CHECK_THROWS_AS(make_pinhole_camera(straight(45), 0, 10), usage_error);
    CHECK_THROWS_AS(make_pinhole_camera(straight(45), 10, -1), usage_error);
}
