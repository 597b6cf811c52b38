// Pixels and their storages: the thesis's vfb_pixel constructors, the approximation rule,
// the z-buffer rule and antialiasing.
#include "vl/pixel.hh"

#include "vl/catch.hh"

#include <cmath>
#include <iomanip>
#include <vector>

using namespace vl;

namespace {
// Stores one pixel in a fresh cell of storage S and reads it back.
template <class S> vfb_pixel through(const vfb_pixel& p) {
    typename S::cell c{};
    S::clear(c);
    S::store(c, p);
    return S::load(c);
}
constexpr double eight_bit = 0.01;  // the worst sRGB 8-bit round trip error in linear light is below this
}  // namespace

TEST_CASE("srgb: the transfer function matches IEC 61966-2-1 at known points", "[pixel][srgb]") {
    CHECK(linear_to_srgb(0.0) == 0.0);
    CHECK(linear_to_srgb(1.0) == Approx(1.0));
    CHECK(linear_to_srgb(0.0031308) == Approx(0.04045).epsilon(1e-3));
    CHECK(linear_to_srgb(0.18) == Approx(0.4614).epsilon(1e-3));  // middle gray
    CHECK(srgb_to_linear(0.5) == Approx(0.2140).epsilon(1e-3));
    CHECK(linear_to_srgb(-1.0) == 0.0);
    CHECK(linear_to_srgb(7.0) == Approx(1.0));
    CHECK(linear_to_srgb(std::nan("")) == 0.0);
}

TEST_CASE("srgb: the 8-bit tables agree with the formula for every code", "[pixel][srgb]") {
    for (int k = 0; k < 256; ++k) {
        const double lin = srgb_to_linear(k / 255.0);
        CHECK(srgb8_to_linear(static_cast<std::uint8_t>(k)) == Approx(lin).margin(1e-7));
        CHECK(linear_to_srgb8(lin) == k);
    }
    for (double x = 0; x <= 1.0; x += 0.0013)
        CHECK(linear_to_srgb8(x) == static_cast<int>(std::lround(255 * linear_to_srgb(x))));
}

TEST_CASE("srgb: linear_to_srgb8 changes code exactly at each decision point, and nowhere else", "[pixel][srgb]") {
    // Code k + 1 starts at the linear value of code k + 0.5. The nearest code of x is the
    // number of those decision points at or below it, counted here one by one.
    std::vector<double> decisions;
    for (int k = 0; k < 255; ++k) decisions.push_back(srgb_to_linear((k + 0.5) / 255.0));
    const auto nearest = [&](double x) {
        int code = 0;
        for (const double d : decisions) code += d <= x;
        return code;
    };
    std::vector<double> probes = {1e-300, 4.9e-324, 0.5, 1.0, 1.0000000000000002, 2.0, 1e300};
    for (const double d : decisions) probes.push_back(d);
    for (int b = 0; b <= 8192; ++b) probes.push_back(b / 8192.0);  // the edges of any table of up to 8192 pieces
    std::size_t mismatches = 0;
    for (const double p : probes) {
        double below = p, above = p;
        for (int step = 0; step < 3; ++step) {
            for (const double x : {below, above})
                if (x >= 0 && linear_to_srgb8(x) != nearest(x)) {
                    ++mismatches;
                    UNSCOPED_INFO("linear_to_srgb8(" << std::setprecision(17) << x << ") = " << int(linear_to_srgb8(x))
                                                     << ", the nearest code is " << nearest(x));
                }
            below = std::nextafter(below, 0.0);
            above = std::nextafter(above, 2.0);
        }
    }
    CHECK(mismatches == 0);
}

TEST_CASE("vfb_pixel: each thesis constructor builds the pixel it names", "[pixel]") {
    CHECK(vfb_pixel(0) == vfb_pixel(0.0, 0.0, 0.0));
    CHECK(vfb_pixel(1) == vfb_pixel(1.0, 1.0, 1.0));
    CHECK(vfb_pixel(0.25) == vfb_pixel(0.25, 0.25, 0.25));
    CHECK(vfb_pixel(0.25f).r() == 0.25);  // a float is a gray, not black or white
    const vfb_pixel rgb(0.1, 0.2, 0.3);
    CHECK(rgb.az() == vfb_pixel::no_az);
    CHECK_FALSE(rgb.has_position());
    const vfb_pixel z(5.0, 0.1, 0.2, 0.3);
    CHECK(z.az() == 5.0);
    const vfb_pixel whole(3, 4, 1.0, 0.1, 0.2, 0.3);
    CHECK(whole.has_position());
    CHECK_FALSE(whole.is_sample());
    const vfb_pixel sample(3.75, 4.25, 1.0, 0.1, 0.2, 0.3);
    CHECK(sample.is_sample());
    CHECK(sample.sub_x() == 0.75);
    CHECK(sample.sub_y() == 0.25);
    const vfb_pixel from_point(point(2.5, 1.5, -7.0), color(0.1, 0.2, 0.3));
    CHECK(from_point.is_sample());
    CHECK(from_point.az() == -7.0);
    CHECK(from_point.clr() == color(0.1, 0.2, 0.3));
}

TEST_CASE("storage: every storage states its memory per pixel", "[pixel][storage]") {
    CHECK(bw_storage::bytes_per_pixel == 1);
    CHECK(gray8_storage::bytes_per_pixel == 1);
    CHECK(rgb8_storage::bytes_per_pixel == 3);
    CHECK(rgb_float_storage::bytes_per_pixel == 12);
    CHECK(zbuffer_storage::bytes_per_pixel == 16);
    CHECK(rgba_storage::bytes_per_pixel == 16);
    CHECK(antialiased_storage<4>::bytes_per_pixel == 16 * 16);
    CHECK(antialiased_storage<2, rgb8_storage>::bytes_per_pixel == 4 * 3);
    CHECK(antialiased_storage<3>::name == "aa3");
}

TEST_CASE("storage: gray storage given an RGB pixel keeps its luminance", "[pixel][storage][approximation]") {
    const vfb_pixel p = through<gray8_storage>(vfb_pixel(0.4, 0.1, 0.1));
    const double y = luminance(0.4, 0.1, 0.1);
    CHECK(p.r() == Approx(y).margin(eight_bit));
    CHECK(p.g() == p.r());
    CHECK(p.b() == p.r());
    CHECK(p.az() == vfb_pixel::no_az);  // gray storage has no az
}

TEST_CASE("storage: black and white storage thresholds at middle gray", "[pixel][storage][approximation]") {
    CHECK(through<bw_storage>(vfb_pixel(1)) == vfb_pixel(1));
    CHECK(through<bw_storage>(vfb_pixel(0)) == vfb_pixel(0));
    CHECK(through<bw_storage>(vfb_pixel(0.9, 0.9, 0.9)) == vfb_pixel(1));
    CHECK(through<bw_storage>(vfb_pixel(0.1)) == vfb_pixel(0));
    CHECK(through<bw_storage>(vfb_pixel(srgb_to_linear(0.51))) == vfb_pixel(1));
    CHECK(through<bw_storage>(vfb_pixel(srgb_to_linear(0.49))) == vfb_pixel(0));
}

TEST_CASE("storage: 8-bit RGB clamps and rounds, float RGB keeps HDR values", "[pixel][storage][approximation]") {
    const vfb_pixel p = through<rgb8_storage>(vfb_pixel(9.0, 2.0, -1.0, 0.5));
    CHECK(p.r() == 1.0);
    CHECK(p.g() == 0.0);
    CHECK(p.b() == Approx(0.5).margin(eight_bit));
    CHECK(p.az() == vfb_pixel::no_az);
    const vfb_pixel f = through<rgb_float_storage>(vfb_pixel(2.0, -1.0, 0.5));
    CHECK(f.r() == 2.0);
    CHECK(f.g() == -1.0);
    CHECK(f.b() == 0.5);
}

TEST_CASE("storage: a z-buffered write lands only if its az is at least the stored one", "[pixel][storage][zbuffer]") {
    zbuffer_storage::cell c;
    zbuffer_storage::clear(c);
    zbuffer_storage::store(c, vfb_pixel(-5.0, 1.0, 0.0, 0.0));  // first write lands on a cleared pixel
    CHECK(zbuffer_storage::load(c) == vfb_pixel(-5.0, 1.0, 0.0, 0.0));
    zbuffer_storage::store(c, vfb_pixel(-9.0, 0.0, 1.0, 0.0));  // farther: ignored
    CHECK(zbuffer_storage::load(c).r() == 1.0);
    zbuffer_storage::store(c, vfb_pixel(-5.0, 0.0, 0.0, 1.0));  // equal: lands (>=)
    CHECK(zbuffer_storage::load(c).b() == 1.0);
    zbuffer_storage::store(c, vfb_pixel(-1.0, 0.5, 0.5, 0.5));  // nearer: lands
    CHECK(zbuffer_storage::load(c) == vfb_pixel(-1.0, 0.5, 0.5, 0.5));
    zbuffer_storage::store(c, vfb_pixel(0.2, 0.2, 0.2));  // no az (-infinity): cannot beat a depth
    CHECK(zbuffer_storage::load(c).az() == -1.0);
}

TEST_CASE("storage: the alpha storage keeps az as opacity and makes plain colours opaque", "[pixel][storage]") {
    CHECK(through<rgba_storage>(vfb_pixel(0.25, 1.0, 0.0, 0.0)).az() == 0.25);
    CHECK(through<rgba_storage>(vfb_pixel(1.0, 0.0, 0.0)).az() == 1.0);
    rgba_storage::cell c;
    rgba_storage::clear(c);
    CHECK(rgba_storage::load(c).az() == 0.0);  // cleared: transparent
}

TEST_CASE("storage: antialiased sub-pixels are averaged on read", "[pixel][storage][antialias]") {
    using aa = antialiased_storage<2>;
    aa::cell c;
    aa::clear(c);
    // Four samples in pixel (7, 3), one in each quarter.
    aa::store(c, vfb_pixel(7.25, 3.25, 1.0, 1.0, 0.0, 0.0));
    aa::store(c, vfb_pixel(7.75, 3.25, 1.0, 0.0, 1.0, 0.0));
    aa::store(c, vfb_pixel(7.25, 3.75, 1.0, 0.0, 0.0, 1.0));
    aa::store(c, vfb_pixel(7.75, 3.75, 3.0, 1.0, 1.0, 1.0));
    const vfb_pixel p = aa::load(c);
    CHECK(p.r() == Approx(0.5));
    CHECK(p.g() == Approx(0.5));
    CHECK(p.b() == Approx(0.5));
    CHECK(p.az() == Approx(1.5));  // the thesis's choice: the average az
    // Each sub-pixel is z-buffered on its own.
    aa::store(c, vfb_pixel(7.3, 3.3, 0.5, 0.0, 1.0, 1.0));
    CHECK(aa::load(c).r() == Approx(0.5));
}

TEST_CASE("storage: a whole pixel fills every sub-pixel, one sample only its own", "[pixel][storage][antialias]") {
    using aa = antialiased_storage<4>;
    CHECK(through<aa>(vfb_pixel(2, 2, 0.0, 1.0, 1.0, 1.0)).r() == Approx(1.0));
    CHECK(through<aa>(vfb_pixel(1.0, 1.0, 1.0)).g() == Approx(1.0));
    CHECK(through<aa>(vfb_pixel(point(2.99999999999, 2.0, 0.0), WHITE)).r() == Approx(1.0 / 16));
}

TEST_CASE("storage: storages without sub-pixels keep the last sample", "[pixel][storage][approximation]") {
    rgb_float_storage::cell c;
    rgb_float_storage::store(c, vfb_pixel(0.25, 0.25, 1.0, 1.0, 0.0, 0.0));
    rgb_float_storage::store(c, vfb_pixel(0.75, 0.75, 1.0, 0.0, 1.0, 0.0));
    CHECK(rgb_float_storage::load(c) == vfb_pixel(0.0, 1.0, 0.0));
}
