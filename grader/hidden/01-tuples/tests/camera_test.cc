// Hidden tests of stage 01's pinhole camera (grader only; students never see this file).
// Each TEST_CASE is one graded item; its tags name the rubric category. The answer key is
// a long-double pinhole model written here (hidden_support.hh), never the submission's
// look_at_matrix.
#include "vl/catch.hh"

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "hidden_support.hh"

using namespace vl;
using namespace vl::stage01;
using namespace vl::stage01::hidden;

namespace {

struct shot {
    camera_settings s;
    int width = 0, height = 0;
};

/// Random cameras: eyes and targets anywhere, ups at least 10 degrees off the view and
/// seldom perpendicular to it, fields of view from 5 to 150 degrees, square, wide and tall
/// images of odd and even sizes.
std::vector<shot> random_shots(std::uint64_t seed, int count) {
    inputs in(seed);
    std::vector<shot> v;
    while (static_cast<int>(v.size()) < count) {
        const double scale = in.log_uniform(-1, 2.5);
        shot c;
        c.s = settings(in.point_in_box(scale), in.point_in_box(scale), in.direction() * in.log_uniform(-1, 1),
                       in.uniform(5, 150));
        if ((c.s.look_at - c.s.eye).length() < 1e-2 * scale) continue;
        if (sine_up_view(c.s.eye, c.s.look_at, c.s.up) < 0.17) continue;
        const int shape = in.integer(0, 2);
        const int a = in.integer(1, 400), b = in.integer(1, 400);
        c.width = shape == 0 ? a : shape == 1 ? std::max(a, b) : std::min(a, b);
        c.height = shape == 0 ? a : shape == 1 ? std::min(a, b) : std::max(a, b);
        v.push_back(c);
    }
    // The common cases: +y up, looking along the axes.
    v.push_back({settings({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 45), 320, 240});
    v.push_back({settings({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 60), 97, 61});
    v.push_back({settings({3, 2, 7}, {-0.5, 0.4, 0}, {0.2, 1, 0}, 38), 96, 64});
    v.push_back({settings({0, 10, 0}, {0, 0, 0}, {0, 0, -1}, 90), 33, 100});
    v.push_back({settings({-4, 1, 0}, {0, 1, 0}, {0, -1, 0}, 20), 1, 1});
    return v;
}

std::string at(double x, double y) { return "(" + num(x) + ", " + num(y) + ")"; }

/// The camera's ray through (x, y) against the model's, within `tolerance` (unit vectors).
bool ray_matches(const ray& r, const pinhole& model, const point& eye, double x, double y, ld tolerance) {
    const vec3 want = model.direction(x, y);
    return r.origin() == eye && distance(of(r.direction()), want) <= tolerance;
}

/// Directions of unit vectors, to about 1e-13 (a camera computes a handful of products).
constexpr ld direction_tol = 1e-13L;

}  // namespace

namespace {

/// The centre rays of many cameras against the direction from the eye to look_at.
void check_centre_rays(std::uint64_t seed, ld tolerance, double max_fov) {
    tally t;
    for (const shot& c : random_shots(seed, 300)) {
        if (c.s.fov_degrees > max_fov) continue;
        const auto cam = make_pinhole_camera(c.s, c.width, c.height);
        const double x = c.width / 2.0, y = c.height / 2.0;
        const vector d = cam->primary_ray(x, y).direction();
        const vec3 want = unit(of(c.s.look_at) - of(c.s.eye));
        VL_CHECK_EACH(t, distance(of(d), want) <= tolerance,
                      describe(c.s, c.width, c.height) << ": the ray through the centre " << at(x, y)
                                                       << " should point at look_at, along " << show(want) << " ± "
                                                       << num(static_cast<double>(tolerance)) << "; yours points along "
                                                       << show(d));
    }
    t.finish("cameras");
}

}  // namespace

TEST_CASE("camera: the ray through the image's centre points at look_at", "[01][camera][essential]") {
    check_centre_rays(301, direction_tol, 180);
}

TEST_CASE("camera: every ray starts exactly at the eye with a unit direction", "[01][camera][essential]") {
    inputs in(302);
    tally t;
    for (const shot& c : random_shots(303, 100)) {
        const auto cam = make_pinhole_camera(c.s, c.width, c.height);
        for (int k = 0; k < 5; ++k) {
            const double x = in.uniform(-0.5, 1.5) * c.width, y = in.uniform(-0.5, 1.5) * c.height;
            const ray r = cam->primary_ray(x, y);
            VL_CHECK_EACH(t, r.origin() == c.s.eye && std::fabs(r.direction().length() - 1) <= 4 * u,
                          describe(c.s, c.width, c.height) << ": the ray through " << at(x, y) << " should start at the eye "
                                                           << show(c.s.eye) << " with a unit direction; yours is "
                                                           << show(r));
        }
    }
    t.finish("rays");
}

TEST_CASE("camera: the vertical field of view spans the height of square - wide and tall images",
          "[01][camera][essential]") {
    tally t;
    for (const shot& c : random_shots(304, 300)) {
        const auto cam = make_pinhole_camera(c.s, c.width, c.height);
        const double x = c.width / 2.0;
        const vector bottom = cam->primary_ray(x, 0).direction(), top = cam->primary_ray(x, c.height).direction();
        const ld angle = angle_between(of(bottom), of(top)) * 180 / pi_l;
        const ld tol = 1e-11L * c.s.fov_degrees;
        VL_CHECK_EACH(t, std::fabs(angle - c.s.fov_degrees) <= tol,
                      describe(c.s, c.width, c.height)
                          << ": the rays through " << at(x, 0) << " and " << at(x, c.height) << " should be "
                          << num(c.s.fov_degrees) << " degrees apart ± " << num(static_cast<double>(tol))
                          << " (the fov spans the height); yours are " << num(static_cast<double>(angle))
                          << " degrees apart");
    }
    t.finish("cameras");
}

TEST_CASE("camera: image position 0 0 is the lower-left corner - x grows right and y grows up",
          "[01][camera][essential]") {
    tally t;
    for (const shot& c : random_shots(305, 200)) {
        const auto cam = make_pinhole_camera(c.s, c.width, c.height);
        const frame f = eye_frame(c.s.eye, c.s.look_at, c.s.up);
        const struct {
            double x, y;
            int right, up;  // the expected signs along the image's right and up
            const char* name;
        } corners[] = {{0, 0, -1, -1, "lower-left"},
                       {static_cast<double>(c.width), 0, 1, -1, "lower-right"},
                       {0, static_cast<double>(c.height), -1, 1, "upper-left"},
                       {static_cast<double>(c.width), static_cast<double>(c.height), 1, 1, "upper-right"}};
        for (const auto& k : corners) {
            const vec3 d = of(cam->primary_ray(k.x, k.y).direction());
            const ld r = dot(d, f.right), up = dot(d, f.up);
            VL_CHECK_EACH(t, r * k.right > 0 && up * k.up > 0,
                          describe(c.s, c.width, c.height)
                              << ": image position " << at(k.x, k.y) << " is the " << k.name
                              << " corner, so its ray should point " << (k.right > 0 ? "right" : "left") << " and "
                              << (k.up > 0 ? "up" : "down") << " of the view (right " << show(f.right) << ", up "
                              << show(f.up) << "); yours points along " << show(d));
        }
    }
    t.finish("corners");
}

TEST_CASE("camera: primary rays match an independent pinhole model at pixel centres and corners",
          "[01][camera][essential]") {
    inputs in(306);
    tally t;
    for (const shot& c : random_shots(307, 150)) {
        const auto cam = make_pinhole_camera(c.s, c.width, c.height);
        const pinhole model(c.s, c.width, c.height);
        for (int k = 0; k < 6; ++k) {
            const double x = in.integer(0, c.width) + (k % 2 ? 0.5 : 0.0);
            const double y = in.integer(0, c.height) + (k % 3 ? 0.5 : 0.0);
            const ray r = cam->primary_ray(x, y);
            VL_CHECK_EACH(t, ray_matches(r, model, c.s.eye, x, y, direction_tol),
                          describe(c.s, c.width, c.height)
                              << ": the ray through " << at(x, y) << " should start at " << show(c.s.eye)
                              << " and point along " << show(model.direction(x, y)) << " ± "
                              << num(static_cast<double>(direction_tol)) << "; yours is " << show(r));
        }
    }
    t.finish("rays");
}

TEST_CASE("camera: the image's right is (view direction) % up - for any up", "[01][camera][essential]") {
    // Ups along every axis and between them, perpendicular to the view or not, upside down.
    const point eye(1, 2, 3), look(1, 2, -2);
    const vector ups[] = {{0, 1, 0}, {0, -1, 0}, {1, 0, 0}, {-1, 0, 0}, {1, 1, 0}, {0.3, 1, 4},
                          {-2, 0.5, -3}, {0, 1e-3, 1}, {5, -5, 1}};
    inputs in(308);
    tally t;
    std::vector<shot> shots;
    for (const vector& up : ups) shots.push_back({settings(eye, look, up, 50), 80, 60});
    for (const shot& c : random_shots(309, 100)) shots.push_back(c);
    for (const shot& c : shots) {
        const auto cam = make_pinhole_camera(c.s, c.width, c.height);
        const frame f = eye_frame(c.s.eye, c.s.look_at, c.s.up);
        const double h = c.height / 2.0, w = c.width / 2.0;
        const vec3 right = on_plane(cam->primary_ray(c.width, h), f.forward) - on_plane(cam->primary_ray(0, h), f.forward);
        const vec3 up = on_plane(cam->primary_ray(w, c.height), f.forward) - on_plane(cam->primary_ray(w, 0), f.forward);
        const vec3 ru = unit(right), uu = unit(up);
        const ld tol = 1e-12L;
        VL_CHECK_EACH(t, distance(ru, f.right) <= tol && distance(uu, f.up) <= tol,
                      describe(c.s, c.width, c.height)
                          << ": along the image, right should be (view direction) % up = " << show(f.right)
                          << " and up should be " << show(f.up) << " (the part of up perpendicular to the view), ± "
                          << num(static_cast<double>(tol)) << "; yours are " << show(ru) << " and " << show(uu));
    }
    t.finish("cameras");
}

TEST_CASE("camera: pixels are square and evenly spaced on a plane facing the eye", "[01][camera]") {
    inputs in(310);
    tally t;
    for (const shot& c : random_shots(311, 150)) {
        const auto cam = make_pinhole_camera(c.s, c.width, c.height);
        const pinhole model(c.s, c.width, c.height);
        const double x = in.integer(0, c.width - 1) + 0.5, y = in.integer(0, c.height - 1) + 0.5;
        const vec3 here = on_plane(cam->primary_ray(x, y), model.f.forward);
        const vec3 dx = on_plane(cam->primary_ray(x + 1, y), model.f.forward) - here;
        const vec3 dy = on_plane(cam->primary_ray(x, y + 1), model.f.forward) - here;
        const vec3 ten = on_plane(cam->primary_ray(x + 10, y + 7), model.f.forward) - here;
        const ld side = model.pixel;
        const ld tol = 1e-10L * side;
        const bool square = std::fabs(length(dx) - side) <= tol && std::fabs(length(dy) - side) <= tol &&
                            std::fabs(dot(dx, dy)) <= tol * side;
        const bool even = distance(ten, 10 * dx + 7 * dy) <= 20 * tol;
        VL_CHECK_EACH(t, square && even,
                      describe(c.s, c.width, c.height)
                          << ": on the plane one unit in front of the eye, one pixel should be "
                          << num(static_cast<double>(side)) << " wide and as high (2 tan(fov / 2) / height), "
                          << "neighbours evenly spaced; at " << at(x, y) << " yours is "
                          << num(static_cast<double>(length(dx))) << " wide and " << num(static_cast<double>(length(dy)))
                          << " high, and 10 right and 7 up is " << show(ten) << " instead of "
                          << show(10 * dx + 7 * dy));
    }
    t.finish("cameras");
}

TEST_CASE("camera: odd and even image sizes - down to 1 x 1 - are centred on the image's middle", "[01][camera]") {
    const int sizes[][2] = {{1, 1}, {2, 2}, {1, 7}, {7, 1}, {97, 61}, {96, 64}, {3, 400}, {401, 2}, {64, 65}};
    tally t;
    for (const auto& wh : sizes) {
        const int w = wh[0], h = wh[1];
        const camera_settings s = settings({2, -1, 4}, {-1, 0.5, -3}, {0.1, 1, 0.2}, 55);
        const auto cam = make_pinhole_camera(s, w, h);
        const pinhole model(s, w, h);
        // The middle pixel's centre (odd sizes) or the corner between the four middle pixels.
        const double x = w / 2.0, y = h / 2.0;
        VL_CHECK_EACH(t, ray_matches(cam->primary_ray(x, y), model, s.eye, x, y, direction_tol),
                      describe(s, w, h) << ": the ray through the middle " << at(x, y) << " should point along "
                                        << show(model.direction(x, y)) << "; yours is " << show(cam->primary_ray(x, y)));
        // The first and the last pixel's centres.
        for (const auto& [px, py] : {std::pair{0.5, 0.5}, std::pair{w - 0.5, h - 0.5}, std::pair{0.5, h - 0.5}}) {
            const ray r = cam->primary_ray(px, py);
            VL_CHECK_EACH(t, ray_matches(r, model, s.eye, px, py, direction_tol),
                          describe(s, w, h) << ": the ray through pixel centre " << at(px, py) << " should point along "
                                            << show(model.direction(px, py)) << " ± "
                                            << num(static_cast<double>(direction_tol)) << "; yours is " << show(r));
        }
    }
    t.finish("rays");
}

TEST_CASE("camera: positions far outside the image - on every side - continue the image plane", "[01][camera]") {
    inputs in(312);
    tally t;
    for (const shot& c : random_shots(313, 100)) {
        if (c.s.fov_degrees > 120) continue;
        const auto cam = make_pinhole_camera(c.s, c.width, c.height);
        const pinhole model(c.s, c.width, c.height);
        for (int k = 0; k < 4; ++k) {
            const double x = k % 2 ? -in.uniform(0.1, 2) * c.width : in.uniform(1.1, 3) * c.width;
            const double y = k / 2 ? -in.uniform(0.1, 2) * c.height : in.uniform(1.1, 3) * c.height;
            const ray r = cam->primary_ray(x, y);
            VL_CHECK_EACH(t, ray_matches(r, model, c.s.eye, x, y, direction_tol),
                          describe(c.s, c.width, c.height)
                              << ": the ray through " << at(x, y) << " (outside the image) should point along "
                              << show(model.direction(x, y)) << " ± " << num(static_cast<double>(direction_tol))
                              << "; yours is " << show(r));
        }
    }
    t.finish("rays");
}

TEST_CASE("camera: only the part of up perpendicular to the view counts - and not its length", "[01][camera]") {
    inputs in(314);
    tally t;
    for (const shot& c : random_shots(315, 100)) {
        const vector view = (c.s.look_at - c.s.eye).unit();
        camera_settings other = c.s;
        other.up = c.s.up * in.log_uniform(-3, 3) + view * in.uniform(-5, 5) * c.s.up.length();
        if (sine_up_view(other.eye, other.look_at, other.up) < 0.05) continue;
        const auto a = make_pinhole_camera(c.s, c.width, c.height), b = make_pinhole_camera(other, c.width, c.height);
        const double x = in.uniform(0, c.width), y = in.uniform(0, c.height);
        const vector da = a->primary_ray(x, y).direction(), db = b->primary_ray(x, y).direction();
        const ld tol = 1e-12L;
        VL_CHECK_EACH(t, distance(of(da), of(db)) <= tol,
                      describe(c.s, c.width, c.height) << " and the same camera with up " << show(other.up)
                                                       << " (plus a part along the view, times a factor) should see "
                                                       << at(x, y) << " along the same ray ± "
                                                       << num(static_cast<double>(tol)) << "; yours give " << show(da)
                                                       << " and " << show(db));
    }
    t.finish("cameras");
}

TEST_CASE("camera: fields of view near 0 and near 180 degrees still span the height", "[01][camera]") {
    tally t;
    for (const double fov : {1e-3, 0.1, 1.0, 10.0, 90.0, 120.0, 170.0, 179.0, 179.9}) {
        const camera_settings s = settings({1, 1, 1}, {2, 3, -4}, {0, 1, 0}, fov);
        for (const auto& wh : {std::pair{64, 48}, std::pair{48, 64}, std::pair{101, 101}}) {
            const auto cam = make_pinhole_camera(s, wh.first, wh.second);
            const double x = wh.first / 2.0;
            const vector bottom = cam->primary_ray(x, 0).direction(), top = cam->primary_ray(x, wh.second).direction();
            const ld angle = angle_between(of(bottom), of(top)) * 180 / pi_l;
            const ld tol = 1e-10L * fov;
            VL_CHECK_EACH(t, std::fabs(angle - fov) <= tol,
                          describe(s, wh.first, wh.second)
                              << ": the rays through " << at(x, 0) << " and " << at(x, wh.second) << " should be "
                              << num(fov) << " degrees apart ± " << num(static_cast<double>(tol)) << "; yours are "
                              << num(static_cast<double>(angle)) << " degrees apart");
        }
    }
    t.finish("cameras");
}

TEST_CASE("camera: far from the origin and far from look_at - the rays still aim right", "[01][camera]") {
    tally t;
    for (const double far : {1e3, 1e6, 1e9, 1e12}) {
        const camera_settings s = settings({far, -0.5 * far, 0.25 * far}, {1, 2, 3}, {0, 0, 1}, 40);
        const auto cam = make_pinhole_camera(s, 120, 80);
        const pinhole model(s, 120, 80);
        for (const auto& [x, y] : {std::pair{60.0, 40.0}, std::pair{0.0, 0.0}, std::pair{119.5, 0.5}}) {
            const ray r = cam->primary_ray(x, y);
            VL_CHECK_EACH(t, ray_matches(r, model, s.eye, x, y, direction_tol),
                          describe(s, 120, 80) << ": the ray through " << at(x, y) << " should start at the eye and point along "
                                               << show(model.direction(x, y)) << " ± "
                                               << num(static_cast<double>(direction_tol)) << "; yours is " << show(r));
        }
    }
    t.finish("rays");
}

namespace {

/// "throws usage_error" or what happened instead, for a camera that must be refused.
bool refused(const camera_settings& s, int width, int height, std::string& instead) {
    try {
        const auto cam = make_pinhole_camera(s, width, height);
        instead = "yours made a camera";
        if (cam) {
            const ray r = cam->primary_ray(width / 2.0, height / 2.0);
            instead += " whose centre ray is " + show(r);
        }
    } catch (const usage_error&) {
        return true;
    } catch (const std::exception& e) {
        instead = std::string("yours threw another exception: ") + e.what();
    }
    return false;
}

/// A valid camera first, so that a camera refusing everything does not pass a refusal
/// test: it must be made and give a ray with a finite unit direction (where the ray goes
/// is for the other tests to say).
bool makes_a_camera(const camera_settings& s, int width, int height, std::string& why) {
    try {
        const auto cam = make_pinhole_camera(s, width, height);
        if (!cam) {
            why = "yours returned nullptr";
            return false;
        }
        const vector d = cam->primary_ray(width / 2.0, height / 2.0).direction();
        if (!(std::isfinite(d.x) && std::isfinite(d.y) && std::isfinite(d.z))) {
            why = "its centre ray points along " + show(d);
            return false;
        }
        return true;
    } catch (const std::exception& e) {
        why = std::string("yours threw: ") + e.what();
    }
    return false;
}

void expect_valid_camera_works() {
    const camera_settings s = settings({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 90);
    std::string why;
    VL_EXPECT(makes_a_camera(s, 10, 10, why), describe(s, 10, 10) << " is a valid camera; " << why);
}

}  // namespace

TEST_CASE("camera: eye == look_at is refused with usage_error", "[01][camera][detail]") {
    expect_valid_camera_works();
    for (const point& p : {point(0, 0, 0), point(1, 2, 3), point(-1e6, 5, 0.5)}) {
        std::string instead;
        VL_EXPECT(refused(settings(p, p, {0, 1, 0}, 45), 10, 10, instead),
                  describe(settings(p, p, {0, 1, 0}, 45), 10, 10)
                      << " looks nowhere (eye == look_at), so it should throw vl::usage_error; " << instead);
    }
}

TEST_CASE("camera: a zero up - or an up along or against the view - is refused with usage_error",
          "[01][camera][detail]") {
    expect_valid_camera_works();
    const camera_settings bad[] = {
        settings({0, 0, 5}, {0, 0, 0}, {0, 0, 0}, 45),    settings({0, 0, 5}, {0, 0, 0}, {0, 0, -1}, 45),
        settings({0, 0, 5}, {0, 0, 0}, {0, 0, 3}, 45),    settings({0, 5, 0}, {0, 0, 0}, {0, 1, 0}, 45),
        settings({0, -5, 0}, {0, 0, 0}, {0, 1, 0}, 45),   settings({1, 1, 1}, {3, 5, 7}, {-1, -2, -3}, 45),
        settings({1, 1, 1}, {2, 2, 2}, {4, 4, 4}, 45),
    };
    for (const camera_settings& s : bad) {
        std::string instead;
        VL_EXPECT(refused(s, 10, 10, instead),
                  describe(s, 10, 10) << " has no direction for up (zero or parallel to the view), so it should throw "
                                         "vl::usage_error; "
                                      << instead);
    }
}

TEST_CASE("camera: a field of view of 0 or less - or of 180 or more - is refused with usage_error",
          "[01][camera][detail]") {
    expect_valid_camera_works();
    for (const double fov : {0.0, -0.0, -10.0, 180.0, 180.5, 360.0, 1e300, std::numeric_limits<double>::infinity()}) {
        const camera_settings s = settings({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, fov);
        std::string instead;
        VL_EXPECT(refused(s, 10, 10, instead),
                  describe(s, 10, 10) << ": the fov must be strictly between 0 and 180 degrees, so it should throw "
                                         "vl::usage_error; "
                                      << instead);
    }
    // Just inside the range is fine.
    for (const double fov : {1e-6, 179.999}) {
        const camera_settings s = settings({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, fov);
        std::string why;
        VL_EXPECT(makes_a_camera(s, 10, 10, why), describe(s, 10, 10) << " is a valid camera; " << why);
    }
}

TEST_CASE("camera: a field of view that is NaN is refused with usage_error (it is not between 0 and 180)",
          "[01][camera][detail]") {
    expect_valid_camera_works();
    const camera_settings s = settings({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, std::numeric_limits<double>::quiet_NaN());
    std::string instead;
    VL_EXPECT(refused(s, 10, 10, instead),
              describe(s, 10, 10) << ": NaN is not strictly between 0 and 180, so it should throw vl::usage_error; "
                                  << instead);
}

TEST_CASE("camera: an image less than 1 pixel wide or high is refused with usage_error", "[01][camera][detail]") {
    expect_valid_camera_works();
    const camera_settings s = settings({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 45);
    for (const auto& [w, h] : {std::pair{0, 10}, std::pair{10, 0}, std::pair{-1, 10}, std::pair{10, -3},
                               std::pair{0, 0}, std::pair{-5, -5}}) {
        std::string instead;
        VL_EXPECT(refused(s, w, h, instead), describe(s, w, h) << " has no pixels, so it should throw vl::usage_error; "
                                                               << instead);
    }
    for (const auto& [w, h] : {std::pair{1, 1}, std::pair{1, 50}, std::pair{50, 1}}) {
        std::string why;
        VL_EXPECT(makes_a_camera(s, w, h, why), describe(s, w, h) << " is a valid camera; " << why);
    }
}
