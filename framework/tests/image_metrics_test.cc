// LDR-FLIP and SSIM (vl_metrics): values worked out by hand, and whole images checked
// against a second implementation in this file that shares no code with the library. The
// second one is written the slow, direct way the papers state the method: long double,
// one pixel at a time, full 2-D filter kernels (the library filters separably, in double),
// the sRGB decoding from its formula (the library uses the framework's table).
#include "vl/flip.hh"
#include "vl/image_io.hh"
#include "vl/ssim.hh"

#include "image_test_support.hh"

#include "vl/catch.hh"

#include <array>
#include <filesystem>
#include <cmath>
#include <cstdint>
#include <functional>
#include <vector>

using namespace vl;

namespace {

using rgb8 = std::array<int, 3>;

// A w x h 8-bit RGB image whose pixel (x, y) is f(x, y).
image make_image(int w, int h, const std::function<rgb8(int, int)>& f) {
    image img(w, h, 3, sample_type::u8);
    auto s = img.samples<std::uint8_t>();
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const rgb8 c = f(x, y);
            for (int k = 0; k < 3; ++k)
                s[(static_cast<std::size_t>(y) * w + x) * 3 + k] = static_cast<std::uint8_t>(std::clamp(c[k], 0, 255));
        }
    return img;
}

image uniform(int w, int h, rgb8 c) {
    return make_image(w, h, [c](int, int) { return c; });
}

// A test scene: a colour gradient with a bright square and a thin dark line, so that it
// has flat areas, edges and a point-like feature.
rgb8 scene(int x, int y) {
    rgb8 c{40 + 5 * x, 60 + 3 * y, 150 - 2 * x};
    if (x >= 8 && x < 16 && y >= 6 && y < 14) c = {230, 220, 90};
    if (x == 22) c = {20, 20, 30};
    return c;
}

// A reproducible pseudo-random number in [-1, 1] for pixel (x, y), channel k.
double noise(int x, int y, int k) {
    std::uint32_t h = static_cast<std::uint32_t>(x) * 73856093u ^ static_cast<std::uint32_t>(y) * 19349663u ^
                      static_cast<std::uint32_t>(k + 1) * 83492791u;
    h ^= h >> 13;
    h *= 0x5bd1e995u;
    h ^= h >> 15;
    return (h % 2001u) / 1000.0 - 1.0;
}

// ---------------------------------------------------------------------------------------
// The second implementation of LDR-FLIP (long double, direct 2-D filters, one pixel).

using ld = long double;
using ld3 = std::array<ld, 3>;
const ld pi_l = 3.141592653589793238462643383279502884L;

ld decode_srgb(int code) {
    const ld c = code / 255.0L;
    return c <= 0.04045L ? c / 12.92L : std::pow((c + 0.055L) / 1.055L, 2.4L);
}

const ld m_l[3][3] = {{10135552.0L / 24577794, 8788810.0L / 24577794, 4435075.0L / 24577794},
                      {2613072.0L / 12288897, 8788810.0L / 12288897, 887015.0L / 12288897},
                      {1425312.0L / 73733382, 8788810.0L / 73733382, 70074185.0L / 73733382}};

ld3 to_xyz(const ld3& c) {
    ld3 r{};
    for (int i = 0; i < 3; ++i) r[i] = m_l[i][0] * c[0] + m_l[i][1] * c[1] + m_l[i][2] * c[2];
    return r;
}

const ld3 white_l = to_xyz({1, 1, 1});

// XYZ back to linear RGB by solving the 3 x 3 system with Gaussian elimination.
ld3 to_rgb(const ld3& xyz) {
    ld a[3][4];
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) a[i][j] = m_l[i][j];
        a[i][3] = xyz[i];
    }
    for (int p = 0; p < 3; ++p)
        for (int i = 0; i < 3; ++i)
            if (i != p) {
                const ld f = a[i][p] / a[p][p];
                for (int j = 0; j < 4; ++j) a[i][j] -= f * a[p][j];
            }
    return {a[0][3] / a[0][0], a[1][3] / a[1][1], a[2][3] / a[2][2]};
}

ld3 hunt_lab(const ld3& rgb) {
    const ld3 x = to_xyz(rgb);
    const ld d = 6.0L / 29;
    const auto f = [d](ld t) { return t > d * d * d ? std::cbrt(t) : t / (3 * d * d) + 4.0L / 29; };
    const ld fx = f(x[0] / white_l[0]), fy = f(x[1] / white_l[1]), fz = f(x[2] / white_l[2]);
    const ld L = 116 * fy - 16;
    return {L, L / 100 * 500 * (fx - fy), L / 100 * 200 * (fy - fz)};
}

ld hyab_l(const ld3& p, const ld3& q) {
    return std::fabs(p[0] - q[0]) + std::sqrt((p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]));
}

struct slow_flip {
    int w, h;
    ld ppd;
    int rc, rf;                          // radii of the CSF and feature kernels
    std::vector<ld3> csf;                // 2-D CSF weights for Y, Cx, Cz, each summing to 1
    std::vector<ld> edge, point;         // 2-D x-derivative kernels (y: transposed)
    std::vector<ld3> ref_c, tst_c;       // YCxCz of every pixel
    std::vector<ld> ref_y, tst_y;        // relative luminance of every pixel

    static std::vector<ld3> linear(const image& img) {
        std::vector<ld3> out;
        const auto s = img.samples<std::uint8_t>();
        for (std::size_t i = 0; i < s.size(); i += 3) out.push_back({decode_srgb(s[i]), decode_srgb(s[i + 1]), decode_srgb(s[i + 2])});
        return out;
    }
    static ld3 ycxcz(const ld3& rgb) {
        const ld3 X = to_xyz(rgb);
        const ld xx = X[0] / white_l[0], yy = X[1] / white_l[1], zz = X[2] / white_l[2];
        return {116 * yy - 16, 500 * (xx - yy), 200 * (yy - zz)};
    }

    slow_flip(const image& a, const image& b, ld pixels_per_degree) : w(a.width()), h(a.height()), ppd(pixels_per_degree) {
        for (const ld3& c : linear(a)) ref_c.push_back(ycxcz(c)), ref_y.push_back(to_xyz(c)[1] / white_l[1]);
        for (const ld3& c : linear(b)) tst_c.push_back(ycxcz(c)), tst_y.push_back(to_xyz(c)[1] / white_l[1]);
        // The CSFs as the paper writes them, sums of a sqrt(pi / b) exp(-pi^2 d^2 / b), d in degrees.
        rc = static_cast<int>(std::ceil(3 * std::sqrt(0.04L / (2 * pi_l * pi_l)) * ppd));
        const auto g = [](ld d2, ld a_, ld b_) { return a_ * std::sqrt(pi_l / b_) * std::exp(-pi_l * pi_l * d2 / b_); };
        ld3 sum{};
        for (int j = -rc; j <= rc; ++j)
            for (int i = -rc; i <= rc; ++i) {
                const ld d2 = (i * i + j * j) / (ppd * ppd);
                csf.push_back({g(d2, 1, 0.0047L), g(d2, 1, 0.0053L), g(d2, 34.1L, 0.04L) + g(d2, 13.5L, 0.025L)});
                for (int k = 0; k < 3; ++k) sum[k] += csf.back()[k];
            }
        for (ld3& c : csf)
            for (int k = 0; k < 3; ++k) c[k] /= sum[k];
        // The feature kernels: x-derivatives of a 2-D Gaussian, positive weights summing to 1
        // and negative ones to -1 over the whole 2-D kernel.
        const ld sd = 0.5L * 0.082L * ppd;
        rf = static_cast<int>(std::ceil(3 * sd));
        ld ep = 0, en = 0, pp = 0, pn = 0;
        for (int j = -rf; j <= rf; ++j)
            for (int i = -rf; i <= rf; ++i) {
                const ld gauss = std::exp(-(i * i + j * j) / (2 * sd * sd));
                edge.push_back(-i * gauss);
                point.push_back((i * i / (sd * sd) - 1) * gauss);
                (edge.back() > 0 ? ep : en) += std::fabs(edge.back());
                (point.back() > 0 ? pp : pn) += std::fabs(point.back());
            }
        for (ld& e : edge) e /= e > 0 ? ep : en;
        for (ld& p : point) p /= p > 0 ? pp : pn;
    }

    std::size_t index(int x, int y) const {  // borders clamped to the edge pixel
        return static_cast<std::size_t>(std::clamp(y, 0, h - 1)) * w + static_cast<std::size_t>(std::clamp(x, 0, w - 1));
    }

    // The paper's colour pipeline at one pixel, with the full 2-D CSF kernels.
    ld3 filtered_lab(const std::vector<ld3>& c, int x, int y) const {
        ld3 sum{};
        std::size_t t = 0;
        for (int j = -rc; j <= rc; ++j)
            for (int i = -rc; i <= rc; ++i, ++t)
                for (int k = 0; k < 3; ++k) sum[k] += csf[t][k] * c[index(x + i, y + j)][k];
        const ld Y = (sum[0] + 16) / 116;
        const ld3 xyz{(Y + sum[1] / 500) * white_l[0], Y * white_l[1], (Y - sum[2] / 200) * white_l[2]};
        ld3 rgb = to_rgb(xyz);
        for (ld& v : rgb) v = std::clamp(v, 0.0L, 1.0L);
        return hunt_lab(rgb);
    }

    // Edge and point strengths at one pixel, with the full 2-D derivative kernels.
    std::array<ld, 2> features(const std::vector<ld>& lum, int x, int y) const {
        const int n = 2 * rf + 1;
        ld ex = 0, ey = 0, px = 0, py = 0;
        for (int j = -rf; j <= rf; ++j)
            for (int i = -rf; i <= rf; ++i) {
                const ld l = lum[index(x + i, y + j)];
                const std::size_t at = static_cast<std::size_t>((j + rf) * n + (i + rf));
                const std::size_t transposed = static_cast<std::size_t>((i + rf) * n + (j + rf));
                ex += edge[at] * l;
                ey += edge[transposed] * l;
                px += point[at] * l;
                py += point[transposed] * l;
            }
        return {std::sqrt(ex * ex + ey * ey), std::sqrt(px * px + py * py)};
    }

    ld pixel(int x, int y) const {
        const ld cmax = std::pow(hyab_l(hunt_lab({0, 1, 0}), hunt_lab({0, 0, 1})), 0.7L);
        ld c = std::pow(hyab_l(filtered_lab(ref_c, x, y), filtered_lab(tst_c, x, y)), 0.7L);
        c = c < 0.4L * cmax ? c * 0.95L / (0.4L * cmax) : 0.95L + (c - 0.4L * cmax) / (cmax - 0.4L * cmax) * 0.05L;
        const auto fr = features(ref_y, x, y), ft = features(tst_y, x, y);
        const ld f = std::pow(std::max(std::fabs(fr[0] - ft[0]), std::fabs(fr[1] - ft[1])) / std::sqrt(2.0L), 0.5L);
        return std::pow(c, 1 - f);
    }

    ld mean() const {
        ld s = 0;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) s += pixel(x, y);
        return s / (static_cast<ld>(w) * h);
    }
};

// The second implementation of SSIM: direct 2-D windows, long double.
ld slow_ssim(const image& a, const image& b) {
    const int w = a.width(), h = a.height(), r = 5;
    const auto signal = [](const image& img) {
        std::vector<ld> v;
        const auto s = img.samples<std::uint8_t>();
        for (std::size_t i = 0; i < s.size(); i += 3) {
            const ld y = 0.2126L * decode_srgb(s[i]) + 0.7152L * decode_srgb(s[i + 1]) + 0.0722L * decode_srgb(s[i + 2]);
            v.push_back(y <= 0.0031308L ? 12.92L * y : 1.055L * std::pow(y, 1 / 2.4L) - 0.055L);
        }
        return v;
    };
    const std::vector<ld> x = signal(a), y = signal(b);
    const bool valid = w >= 11 && h >= 11;
    const auto px = [&](const std::vector<ld>& v, int i, int j) {
        return v[static_cast<std::size_t>(std::clamp(j, 0, h - 1)) * w + std::clamp(i, 0, w - 1)];
    };
    ld total = 0;
    int n = 0;
    for (int cy = valid ? r : 0; cy < (valid ? h - r : h); ++cy)
        for (int cx = valid ? r : 0; cx < (valid ? w - r : w); ++cx) {
            ld ws = 0, mx = 0, my = 0, sxx = 0, syy = 0, sxy = 0;
            for (int j = -r; j <= r; ++j)
                for (int i = -r; i <= r; ++i) {
                    const ld g = std::exp(-(i * i + j * j) / (2 * 1.5L * 1.5L));
                    const ld p = px(x, cx + i, cy + j), q = px(y, cx + i, cy + j);
                    ws += g;
                    mx += g * p;
                    my += g * q;
                    sxx += g * p * p;
                    syy += g * q * q;
                    sxy += g * p * q;
                }
            mx /= ws, my /= ws, sxx = sxx / ws - mx * mx, syy = syy / ws - my * my, sxy = sxy / ws - mx * my;
            const ld c1 = 0.01L * 0.01L, c2 = 0.03L * 0.03L;
            total += (2 * mx * my + c1) * (2 * sxy + c2) / ((mx * mx + my * my + c1) * (sxx + syy + c2));
            ++n;
        }
    return total / n;
}

}  // namespace

TEST_CASE("FLIP and SSIM: identical images give FLIP 0 and SSIM 1", "[metrics]") {
    const image a = make_image(33, 21, scene);
    const flip_result f = flip(a, a);
    CHECK(f.width == 33);
    CHECK(f.height == 21);
    CHECK(f.mean == 0.0);
    CHECK(f.max == 0.0);
    CHECK(f.weighted_median == 0.0);
    CHECK(ssim(a, a).mean == Approx(1.0).margin(1e-12));
}

TEST_CASE("FLIP: uniform images by hand, black and white, grays, colours", "[metrics]") {
    // Flat images have no features and filter to themselves, so every pixel's FLIP is the
    // redistributed HyAB distance of the two colours (docs/image-metrics.md works these):
    //   cmax = HyAB(Hunt(Lab(green)), Hunt(Lab(blue)))^0.7 = 203.3017^0.7 = 41.27610
    //   black/white: HyAB = 100, 100^0.7 = 25.11886 > 0.4 cmax, so
    //   0.95 + (25.11886 - 16.51044) / (41.27610 - 16.51044) * 0.05 = 0.96738
    CHECK(flip(uniform(16, 12, {0, 0, 0}), uniform(16, 12, {255, 255, 255})).mean == Approx(0.967380).margin(1e-5));
    // Gray 128 against 138: HyAB 3.89274 (lightness only), 3.89274^0.7 * 0.95 / 16.51044 = 0.14899.
    CHECK(flip(uniform(16, 12, {128, 128, 128}), uniform(16, 12, {138, 138, 138})).mean ==
          Approx(0.148985).margin(1e-5));
    // An orange against a redder one: HyAB 6.60300 -> 0.21567.
    CHECK(flip(uniform(16, 12, {200, 60, 30}), uniform(16, 12, {190, 80, 40})).mean == Approx(0.215667).margin(1e-5));
    // One level above black is already visible to FLIP, just: 0.02326.
    CHECK(flip(uniform(16, 12, {0, 0, 0}), uniform(16, 12, {1, 1, 1})).mean == Approx(0.023259).margin(1e-5));
}

TEST_CASE("SSIM: uniform images by hand", "[metrics]") {
    // No variance: SSIM = (2 a b + C1) / (a^2 + b^2 + C1), C1 = 0.0001, a = 128/255, b = 138/255.
    CHECK(ssim(uniform(16, 16, {128, 128, 128}), uniform(16, 16, {138, 138, 138})).mean ==
          Approx(0.9971779).margin(1e-6));
}

TEST_CASE("FLIP: every pixel agrees with a direct long-double implementation", "[metrics]") {
    const image ref = make_image(30, 20, scene);
    const image test = make_image(30, 20, [](int x, int y) {
        rgb8 c = scene(x, y);
        if (x == 5 && y == 5) c = {255, 255, 255};  // a firefly
        if (x >= 16 && x < 20 && y >= 6 && y < 14) c = {230, 220, 90};  // the square grown by 4 pixels
        return c;
    });
    const flip_result f = flip(ref, test);
    const slow_flip slow(ref, test, flip_default_pixels_per_degree());
    // Corners and edges test the clamped borders; (5, 5) the firefly; (16, 10) the moved edge.
    for (const auto& [x, y] : {std::pair{0, 0}, {29, 0}, {0, 19}, {29, 19}, {5, 5}, {16, 10}, {12, 2}, {22, 10}})
        CHECK(f.error[static_cast<std::size_t>(y) * 30 + x] == Approx(static_cast<double>(slow.pixel(x, y))).margin(2e-6));
    CHECK(f.mean == Approx(static_cast<double>(slow.mean())).margin(1e-6));
    // The published tool (NVlabs/flip v1.6, `flip -r ref.png -t test.png`) on these two
    // images written as PNG prints Mean: 0.193224.
    CHECK(f.mean == Approx(0.193224).margin(2e-6));
}

TEST_CASE("FLIP and SSIM: a shift, a blur and noise give the expected order and values", "[metrics]") {
    const int w = 32, h = 24;
    const image ref = make_image(w, h, scene);
    const auto shifted = [&](int by) {
        return make_image(w, h, [by](int x, int y) {
            rgb8 c = scene(x, y);
            for (int& v : c) v += by;
            return c;
        });
    };
    const image shift_small = shifted(4), shift_large = shifted(24);
    const image blurred = make_image(w, h, [&](int x, int y) {  // 3 x 3 box blur, edges clamped
        rgb8 s{0, 0, 0};
        for (int j = -1; j <= 1; ++j)
            for (int i = -1; i <= 1; ++i) {
                const rgb8 c = scene(std::clamp(x + i, 0, w - 1), std::clamp(y + j, 0, h - 1));
                for (int k = 0; k < 3; ++k) s[static_cast<std::size_t>(k)] += c[static_cast<std::size_t>(k)];
            }
        for (int& v : s) v = (v + 4) / 9;
        return s;
    });
    const image noisy = make_image(w, h, [](int x, int y) {
        rgb8 c = scene(x, y);
        for (int k = 0; k < 3; ++k) c[static_cast<std::size_t>(k)] += static_cast<int>(std::lround(30 * noise(x, y, k)));
        return c;
    });

    const double f_small = flip(ref, shift_small).mean, f_large = flip(ref, shift_large).mean;
    const double f_blur = flip(ref, blurred).mean, f_noise = flip(ref, noisy).mean;
    // Each mean against the direct implementation (aim: 1e-3; they agree far closer).
    const ld ppd = flip_default_pixels_per_degree();
    CHECK(f_small == Approx(static_cast<double>(slow_flip(ref, shift_small, ppd).mean())).margin(1e-5));
    CHECK(f_large == Approx(static_cast<double>(slow_flip(ref, shift_large, ppd).mean())).margin(1e-5));
    CHECK(f_blur == Approx(static_cast<double>(slow_flip(ref, blurred, ppd).mean())).margin(1e-5));
    CHECK(f_noise == Approx(static_cast<double>(slow_flip(ref, noisy, ppd).mean())).margin(1e-5));
    // The published tool (NVlabs/flip v1.6) on the same images written as PNG prints the
    // means 0.102375, 0.366437, 0.091511 and 0.137471.
    CHECK(f_small == Approx(0.102375).margin(2e-6));
    CHECK(f_large == Approx(0.366437).margin(2e-6));
    CHECK(f_blur == Approx(0.091511).margin(2e-6));
    CHECK(f_noise == Approx(0.137471).margin(2e-6));
    // A larger shift is a larger error; all are clearly non-zero and below 1.
    CHECK(0.0 < f_small);
    CHECK(f_small < f_large);
    CHECK(f_large < 1.0);
    CHECK(f_blur > 0.0);
    CHECK(f_noise > f_small);

    const double s_small = ssim(ref, shift_small).mean, s_large = ssim(ref, shift_large).mean;
    const double s_blur = ssim(ref, blurred).mean, s_noise = ssim(ref, noisy).mean;
    CHECK(s_small == Approx(static_cast<double>(slow_ssim(ref, shift_small))).margin(1e-7));
    CHECK(s_large == Approx(static_cast<double>(slow_ssim(ref, shift_large))).margin(1e-7));
    CHECK(s_blur == Approx(static_cast<double>(slow_ssim(ref, blurred))).margin(1e-7));
    CHECK(s_noise == Approx(static_cast<double>(slow_ssim(ref, noisy))).margin(1e-7));
    // SSIM barely notices a brightness shift (only its luminance term changes), but
    // structure lost to blur or noise lowers it clearly.
    CHECK(s_large < s_small);
    CHECK(s_small > 0.99);
    CHECK(s_noise < s_small);
    CHECK(s_blur < s_small);
    CHECK(s_noise < 0.9);
}

TEST_CASE("FLIP and SSIM: non-square images, also narrower than the SSIM window", "[metrics]") {
    for (const auto& [w, h] : {std::pair{41, 13}, {9, 27}, {1, 7}}) {
        const image ref = make_image(w, h, scene);
        const image test = make_image(w, h, [](int x, int y) { return rgb8{scene(x, y)[0], 255 - scene(x, y)[1], 90}; });
        const flip_result f = flip(ref, test);
        REQUIRE(f.error.size() == static_cast<std::size_t>(w) * h);
        const slow_flip slow(ref, test, flip_default_pixels_per_degree());
        CHECK(f.error.back() == Approx(static_cast<double>(slow.pixel(w - 1, h - 1))).margin(2e-6));
        CHECK(f.error.front() == Approx(static_cast<double>(slow.pixel(0, 0))).margin(2e-6));
        const ssim_result s = ssim(ref, test);
        CHECK(s.mean == Approx(static_cast<double>(slow_ssim(ref, test))).margin(1e-7));
        CHECK(s.width == (w >= 11 && h >= 11 ? w - 10 : w));
        CHECK(s.height == (w >= 11 && h >= 11 ? h - 10 : h));
    }
}

TEST_CASE("FLIP and SSIM: alpha is dropped, gray is spread to RGB, 16-bit reads alike", "[metrics]") {
    const image rgb = make_image(20, 14, scene);
    image rgba(20, 14, 4, sample_type::u8);
    const auto s = rgb.samples<std::uint8_t>();
    auto d = rgba.samples<std::uint8_t>();
    for (std::size_t p = 0; p < 20 * 14; ++p) {
        for (int k = 0; k < 3; ++k) d[4 * p + k] = s[3 * p + k];
        d[4 * p + 3] = static_cast<std::uint8_t>(p * 7);  // any alpha at all
    }
    CHECK(flip(rgb, rgba).max == 0.0);
    CHECK(ssim(rgb, rgba).mean == Approx(1.0).margin(1e-12));
    CHECK(flip(rgb, convert_samples(rgb, sample_type::u16)).max < 1e-4);

    const image gray = convert_channels(rgb, 1);
    CHECK(flip(gray, convert_channels(gray, 3)).max == 0.0);
}

TEST_CASE("FLIP and SSIM: images of different sizes are refused, naming both sizes", "[metrics]") {
    const image a(10, 8, 3, sample_type::u8), b(8, 10, 3, sample_type::u8);
    CHECK_THROWS_WITH(flip(a, b), Catch::Contains("10 x 8") && Catch::Contains("8 x 10"));
    CHECK_THROWS_AS(ssim(a, b), usage_error);
    flip_options o;
    o.pixels_per_degree = 0;
    CHECK_THROWS_AS(flip(a, a, o), usage_error);
}

TEST_CASE("FLIP: the weighted percentile weights each error by itself", "[metrics]") {
    // Sum 1.0: running sums 0.1, 0.3, 0.6, 1.0. The median is the first value at which the
    // running sum passes 0.5, the first quartile the first past 0.25.
    const std::vector<float> v{0.4f, 0.1f, 0.3f, 0.2f};
    CHECK(flip_weighted_percentile(v, 0.5) == Approx(0.3));
    CHECK(flip_weighted_percentile(v, 0.25) == Approx(0.2));
    CHECK(flip_weighted_percentile(v, 0.75) == Approx(0.4));
    CHECK(flip_weighted_percentile(std::vector<float>{0, 0, 0}, 0.5) == 0.0);
    CHECK(flip_weighted_percentile(std::vector<float>{}, 0.5) == 0.0);
}

TEST_CASE("FLIP: the pixels per degree follow the paper's viewing formula", "[metrics]") {
    CHECK(flip_default_pixels_per_degree() == Approx(67.0206432766).epsilon(1e-10));
    CHECK(flip_pixels_per_degree(0.5, 1920, 0.6) == Approx(0.5 * 3200 * 3.14159265358979 / 180));
    // Farther away (more pixels per degree) hides more of a fine pattern.
    const image ref = make_image(24, 24, [](int x, int y) { return (x + y) % 2 ? rgb8{200, 200, 200} : rgb8{60, 60, 60}; });
    const image flat = uniform(24, 24, {140, 140, 140});
    flip_options near, far;
    near.pixels_per_degree = 10;
    far.pixels_per_degree = 100;
    CHECK(flip(ref, flat, far).mean < flip(ref, flat, near).mean);
}

TEST_CASE("FLIP: the error map is a magma-coloured image of the inputs' size", "[metrics]") {
    test::temp_dir dir;
    const image ref = make_image(37, 19, scene);
    const flip_result f = flip(ref, make_image(37, 19, [](int x, int y) { return x > 20 ? rgb8{0, 0, 0} : scene(x, y); }));
    write_image(dir / "map.png", flip_error_map(f));
    const image back = read_image(dir / "map.png");
    CHECK(back.width() == 37);
    CHECK(back.height() == 19);
    CHECK(back.channels() == 3);
    // Error 0 is magma's first colour, (0.001462, 0.000466, 0.013866) -> (0, 0, 4); error 1
    // its last, (0.987053, 0.991438, 0.749504) -> (252, 253, 191).
    const auto s = back.samples<std::uint8_t>();
    CHECK((s[0] == 0 && s[1] == 0 && s[2] == 4));
    double c[3];
    flip_magma(1.0, c);
    CHECK(std::lround(255 * c[0]) == 252);
    CHECK(std::lround(255 * c[2]) == 191);
    // The map shows the error: the changed right-hand part is brighter than the untouched left.
    CHECK(s[3 * (10 * 37 + 30)] > s[3 * (10 * 37 + 2)]);
}

TEST_CASE("SSIM: gray images agree with scikit-image's structural_similarity to 1e-5", "[metrics]") {
    // Independent values: scikit-image 0.19.3 (Debian 12's python3-skimage),
    // structural_similarity(a, b, gaussian_weights=True, sigma=1.5,
    // use_sample_covariance=False, data_range=1.0) on the 8-bit gray values / 255, which is
    // the paper's MATLAB code (11 x 11 Gaussian window, K1 0.01, K2 0.03, 'valid' windows).
    // The images (data/metrics): a 64 x 48 sine pattern and a copy 10 levels brighter, with
    // Gaussian noise (sigma 12 levels) and box-blurred (5 x 5); a 50 x 30 pattern and a
    // noisy copy (sigma 20).
    const std::filesystem::path dir = VL_TEST_METRICS;
    struct pair {
        const char *reference, *test;
        double ssim;
    };
    for (const pair& p : {pair{"ref.png", "shift.png", 0.996754}, pair{"ref.png", "noise.png", 0.646226},
                          pair{"ref.png", "blur.png", 0.997824}, pair{"ns_ref.png", "ns_noise.png", 0.575116}}) {
        const vl::image a = vl::read_image(dir / p.reference), b = vl::read_image(dir / p.test);
        INFO(p.reference << " against " << p.test);
        CHECK(vl::ssim(a, b).mean == Approx(p.ssim).margin(1e-5));
    }
}
