// LDR-FLIP (Andersson et al., "FLIP: A Difference Evaluator for Alternating Images", HPG
// 2020). The steps below follow the paper's two pipelines; the comments name the paper's
// sections by title ("colour pipeline", "feature pipeline", "pooling"), and
// docs/image-metrics.md derives the constants. The published tool (NVlabs/flip) was read
// for its constants and its choices where the paper leaves one open (image borders, the
// separable filters); the code here is written for reading, in double precision.
#include "vl/flip.hh"
#include "vl/error.hh"

#include "magma_map.hh"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>

namespace vl {

namespace {

constexpr double pi = std::numbers::pi;

// A colour as three numbers: linear RGB, XYZ, YCxCz or L*a*b* depending on the step.
using triple = std::array<double, 3>;

// A single-channel image of doubles, rows top to bottom.
struct plane {
    int w = 0, h = 0;
    std::vector<double> v;
    plane(int width, int height) : w(width), h(height), v(static_cast<std::size_t>(width) * height, 0.0) {}
    double& at(int x, int y) { return v[static_cast<std::size_t>(y) * w + x]; }
    double at(int x, int y) const { return v[static_cast<std::size_t>(y) * w + x]; }
};

// ---------------------------------------------------------------------------------------
// Colour spaces (the paper's colour pipeline, "perceptually uniform colour space").
//
// Linear sRGB to CIE XYZ for the sRGB primaries and the D65 white point, as exact
// fractions (the published tool uses the same ones). Its rows sum to the XYZ of white,
// (0.9504, 1, 1.0889), which is the reference white of YCxCz and CIELab below.
constexpr double rgb_to_xyz[3][3] = {
    {10135552.0 / 24577794.0, 8788810.0 / 24577794.0, 4435075.0 / 24577794.0},
    {2613072.0 / 12288897.0, 8788810.0 / 12288897.0, 887015.0 / 12288897.0},
    {1425312.0 / 73733382.0, 8788810.0 / 73733382.0, 70074185.0 / 73733382.0},
};

triple multiply(const double m[3][3], const triple& c) {
    return {m[0][0] * c[0] + m[0][1] * c[1] + m[0][2] * c[2], m[1][0] * c[0] + m[1][1] * c[1] + m[1][2] * c[2],
            m[2][0] * c[0] + m[2][1] * c[1] + m[2][2] * c[2]};
}

// The inverse matrix, XYZ to linear sRGB, computed once by Cramer's rule.
struct xyz_to_rgb_matrix {
    double m[3][3];
    xyz_to_rgb_matrix() {
        const auto& a = rgb_to_xyz;
        const double det = a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
                           a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
                           a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) {
                // cofactor of a[j][i] (transposed: the adjugate)
                const int r0 = (j + 1) % 3, r1 = (j + 2) % 3, c0 = (i + 1) % 3, c1 = (i + 2) % 3;
                m[i][j] = (a[r0][c0] * a[r1][c1] - a[r0][c1] * a[r1][c0]) / det;
            }
    }
};
const xyz_to_rgb_matrix xyz_to_rgb;

// The reference white: XYZ of linear RGB (1, 1, 1).
const triple white = multiply(rgb_to_xyz, {1.0, 1.0, 1.0});

// YCxCz (a linear opponent colour space): CIELab's formulas *without* the cube
// root, so it is linear in XYZ and filtering in it is filtering light. Y is 116 y - 16,
// Cx (red-green) 500 (x - y), Cz (blue-yellow) 200 (y - z), with x = X / Xn etc.
triple xyz_to_ycxcz(const triple& xyz) {
    const double x = xyz[0] / white[0], y = xyz[1] / white[1], z = xyz[2] / white[2];
    return {116.0 * y - 16.0, 500.0 * (x - y), 200.0 * (y - z)};
}

triple ycxcz_to_xyz(const triple& c) {
    const double y = (c[0] + 16.0) / 116.0;
    const double x = y + c[1] / 500.0;
    const double z = y - c[2] / 200.0;
    return {x * white[0], y * white[1], z * white[2]};
}

// CIELab (CIE 15:2004), here *with* the cube root: this is where distances are measured.
triple xyz_to_lab(const triple& xyz) {
    constexpr double delta = 6.0 / 29.0;
    const auto f = [](double t) {
        return t > delta * delta * delta ? std::cbrt(t) : t / (3.0 * delta * delta) + 4.0 / 29.0;
    };
    const double fx = f(xyz[0] / white[0]), fy = f(xyz[1] / white[1]), fz = f(xyz[2] / white[2]);
    return {116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz)};
}

// The Hunt effect: colourfulness grows with luminance, so dark colours are less different
// than their a*, b* say. The paper scales a* and b* by 0.01 L*.
triple hunt(const triple& lab) { return {lab[0], 0.01 * lab[0] * lab[1], 0.01 * lab[0] * lab[2]}; }

// HyAB (Abasi et al. 2020): city-block distance in lightness plus Euclidean distance in
// the chroma plane; better than Euclidean Delta E for large differences.
double hyab(const triple& p, const triple& q) {
    return std::abs(p[0] - q[0]) + std::hypot(p[1] - q[1], p[2] - q[2]);
}

triple linear_rgb_to_hunt_lab(const triple& rgb) { return hunt(xyz_to_lab(multiply(rgb_to_xyz, rgb))); }

// The largest distance (raised to qc): between pure green and pure blue, the two most
// different colours of the display's gamut in the Hunt-adjusted space.
double max_distance() {
    return std::pow(hyab(linear_rgb_to_hunt_lab({0, 1, 0}), linear_rgb_to_hunt_lab({0, 0, 1})), flip_constants::qc);
}

// The error redistribution (colour pipeline, last step): the distance raised to qc is
// mapped to [0, 1] piecewise linearly, distances below pc * cmax to [0, pt] and the rest
// to [pt, 1], so that the differences people actually see spread over most of the range.
double redistribute(double distance_qc, double cmax) {
    using namespace flip_constants;
    const double small = pc * cmax;
    if (distance_qc < small) return distance_qc * pt / small;
    return pt + (distance_qc - small) / (cmax - small) * (1.0 - pt);
}

// ---------------------------------------------------------------------------------------
// Filtering: separable convolution, borders clamped to the edge pixel (as the tool does).

std::vector<double> normalised(std::vector<double> k, double sum) {
    for (double& x : k) x /= sum;
    return k;
}

double sum_of(const std::vector<double>& k) {
    double s = 0;
    for (const double x : k) s += x;
    return s;
}

// `in` convolved with `kx` along rows, then with `ky` along columns.
plane convolve(const plane& in, const std::vector<double>& kx, const std::vector<double>& ky) {
    const int rx = static_cast<int>(kx.size() / 2), ry = static_cast<int>(ky.size() / 2);
    plane across(in.w, in.h), out(in.w, in.h);
    for (int y = 0; y < in.h; ++y)
        for (int x = 0; x < in.w; ++x) {
            double s = 0;
            for (int i = -rx; i <= rx; ++i) s += kx[static_cast<std::size_t>(i + rx)] * in.at(std::clamp(x + i, 0, in.w - 1), y);
            across.at(x, y) = s;
        }
    for (int y = 0; y < in.h; ++y)
        for (int x = 0; x < in.w; ++x) {
            double s = 0;
            for (int i = -ry; i <= ry; ++i)
                s += ky[static_cast<std::size_t>(i + ry)] * across.at(x, std::clamp(y + i, 0, in.h - 1));
            out.at(x, y) = s;
        }
    return out;
}

// The contrast sensitivity filters (colour pipeline, "spatial filtering"). Each channel's
// filter is a sum of Gaussians in the spatial domain, g(x) = a sqrt(pi / b) exp(-pi^2 x^2 / b)
// with x in degrees of visual angle; the constants fit the contrast sensitivity of the
// achromatic, red-green and blue-yellow channels (the paper's values, also the published
// tool's):
//   Y   a1 = 1,    b1 = 0.0047, a2 = 0,    b2 = 1e-5 (unused)
//   Cx  a1 = 1,    b1 = 0.0053, a2 = 0,    b2 = 1e-5 (unused)
//   Cz  a1 = 34.1, b1 = 0.04,   a2 = 13.5, b2 = 0.025
// A 2-D Gaussian is the product of two 1-D ones, so Y and Cx filter separably; Cz's sum of
// two Gaussians is two separable filters whose results add. Each 2-D filter sums to 1.
struct csf_filters {
    std::vector<double> y, cx, cz1, cz2;  // 1-D taps, centre in the middle
};

csf_filters make_csf_filters(double ppd) {
    constexpr double b_max = 0.04;  // the widest Gaussian sets the radius: 3 standard deviations
    const int radius = static_cast<int>(std::ceil(3.0 * std::sqrt(b_max / (2.0 * pi * pi)) * ppd));
    const auto gaussian = [](double x2, double a, double b) { return a * std::sqrt(pi / b) * std::exp(-pi * pi * x2 / b); };
    csf_filters f;
    for (int i = -radius; i <= radius; ++i) {
        const double x = i / ppd, x2 = x * x;  // degrees
        f.y.push_back(gaussian(x2, 1.0, 0.0047));
        f.cx.push_back(gaussian(x2, 1.0, 0.0053));
        // For a product of two 1-D filters to give a * sqrt(pi / b) exp(...) in 2-D, each
        // carries the square root of the amplitude.
        f.cz1.push_back(std::sqrt(34.1 * std::sqrt(pi / 0.04)) * std::exp(-pi * pi * x2 / 0.04));
        f.cz2.push_back(std::sqrt(13.5 * std::sqrt(pi / 0.025)) * std::exp(-pi * pi * x2 / 0.025));
    }
    f.y = normalised(f.y, sum_of(f.y));
    f.cx = normalised(f.cx, sum_of(f.cx));
    // The 2-D Cz filter sums to S1^2 + S2^2 (S the 1-D sums); divide each 1-D part by its root.
    const double s1 = sum_of(f.cz1), s2 = sum_of(f.cz2), n = std::sqrt(s1 * s1 + s2 * s2);
    f.cz1 = normalised(f.cz1, n);
    f.cz2 = normalised(f.cz2, n);
    return f;
}

// The feature detectors (feature pipeline): a Gaussian of standard deviation
// 0.5 * gw * ppd pixels (gw, in degrees, is the peak-to-trough width of the eye's edge
// detector, so the standard deviation is half of it), its first derivative (edges) and its
// second (points), radius 3 standard deviations. The Gaussian sums to 1; each derivative's
// positive taps sum to 1 and its negative taps to -1, so they answer 0 on flat areas.
struct feature_filters {
    std::vector<double> g, dg, ddg;
};

feature_filters make_feature_filters(double ppd) {
    const double sd = 0.5 * flip_constants::gw * ppd;
    const int radius = static_cast<int>(std::ceil(3.0 * sd));
    feature_filters f;
    double g_sum = 0, dg_pos = 0, dg_neg = 0, ddg_pos = 0, ddg_neg = 0;
    for (int i = -radius; i <= radius; ++i) {
        const double x = i, g = std::exp(-x * x / (2.0 * sd * sd));
        const double dg = -x * g, ddg = (x * x / (sd * sd) - 1.0) * g;
        f.g.push_back(g);
        f.dg.push_back(dg);
        f.ddg.push_back(ddg);
        g_sum += g;
        (dg > 0 ? dg_pos : dg_neg) += std::abs(dg);
        (ddg > 0 ? ddg_pos : ddg_neg) += std::abs(ddg);
    }
    for (std::size_t i = 0; i < f.g.size(); ++i) {
        f.g[i] /= g_sum;
        f.dg[i] /= f.dg[i] > 0 ? dg_pos : dg_neg;
        f.ddg[i] /= f.ddg[i] > 0 ? ddg_pos : ddg_neg;
    }
    return f;
}

// ---------------------------------------------------------------------------------------
// Input: linear RGB in [0, 1], as three planes.

struct rgb_planes {
    plane r, g, b;
    rgb_planes(int w, int h) : r(w, h), g(w, h), b(w, h) {}
};

rgb_planes linear_rgb(const image& img) {
    // Integer samples are sRGB-encoded and become linear here (convert_samples); gray is
    // copied to R, G and B and alpha dropped (convert_channels).
    const image lin = convert_channels(convert_samples(img, sample_type::f32), 3);
    rgb_planes p(img.width(), img.height());
    const auto s = lin.samples<float>();
    for (std::size_t i = 0; i < p.r.v.size(); ++i) {
        // LDR-FLIP is defined for displayable colours: clamp HDR or negative floats.
        p.r.v[i] = std::clamp(static_cast<double>(s[3 * i]), 0.0, 1.0);
        p.g.v[i] = std::clamp(static_cast<double>(s[3 * i + 1]), 0.0, 1.0);
        p.b.v[i] = std::clamp(static_cast<double>(s[3 * i + 2]), 0.0, 1.0);
    }
    return p;
}

// One image's part of the colour pipeline: to YCxCz, filtered by the contrast sensitivity
// filters, back to linear RGB and clamped to [0, 1] (the filters can overshoot, and only
// displayable colours go on), then to Hunt-adjusted CIELab.
struct filtered_lab {
    plane l, a, b;
    filtered_lab(int w, int h) : l(w, h), a(w, h), b(w, h) {}
};

filtered_lab colour_pipeline(const rgb_planes& rgb, const csf_filters& f) {
    const int w = rgb.r.w, h = rgb.r.h;
    plane y(w, h), cx(w, h), cz(w, h);
    for (std::size_t i = 0; i < y.v.size(); ++i) {
        const triple c = xyz_to_ycxcz(multiply(rgb_to_xyz, {rgb.r.v[i], rgb.g.v[i], rgb.b.v[i]}));
        y.v[i] = c[0];
        cx.v[i] = c[1];
        cz.v[i] = c[2];
    }
    const plane fy = convolve(y, f.y, f.y), fcx = convolve(cx, f.cx, f.cx);
    const plane fcz1 = convolve(cz, f.cz1, f.cz1), fcz2 = convolve(cz, f.cz2, f.cz2);
    filtered_lab out(w, h);
    for (std::size_t i = 0; i < y.v.size(); ++i) {
        triple c = multiply(xyz_to_rgb.m, ycxcz_to_xyz({fy.v[i], fcx.v[i], fcz1.v[i] + fcz2.v[i]}));
        for (double& v : c) v = std::clamp(v, 0.0, 1.0);
        const triple lab = linear_rgb_to_hunt_lab(c);
        out.l.v[i] = lab[0];
        out.a.v[i] = lab[1];
        out.b.v[i] = lab[2];
    }
    return out;
}

// One image's part of the feature pipeline: the edge and point strengths of its luminance.
// The luminance is YCxCz's Y mapped back to [0, 1], (Y + 16) / 116, which is the relative
// luminance Y / Yn of the *unfiltered* image (features the CSF would blur are still seen).
struct features {
    plane edge, point;
    features(int w, int h) : edge(w, h), point(w, h) {}
};

features feature_pipeline(const rgb_planes& rgb, const feature_filters& f) {
    const int w = rgb.r.w, h = rgb.r.h;
    plane lum(w, h);
    for (std::size_t i = 0; i < lum.v.size(); ++i)
        lum.v[i] = (xyz_to_ycxcz(multiply(rgb_to_xyz, {rgb.r.v[i], rgb.g.v[i], rgb.b.v[i]}))[0] + 16.0) / 116.0;
    // A derivative along x is the 1-D derivative across rows and the Gaussian down columns.
    const plane ex = convolve(lum, f.dg, f.g), ey = convolve(lum, f.g, f.dg);
    const plane px = convolve(lum, f.ddg, f.g), py = convolve(lum, f.g, f.ddg);
    features out(w, h);
    for (std::size_t i = 0; i < lum.v.size(); ++i) {
        out.edge.v[i] = std::hypot(ex.v[i], ey.v[i]);
        out.point.v[i] = std::hypot(px.v[i], py.v[i]);
    }
    return out;
}

}  // namespace

double flip_pixels_per_degree(double distance, double resolution_x, double monitor_width) {
    return distance * (resolution_x / monitor_width) * (pi / 180.0);
}

double flip_default_pixels_per_degree() { return flip_pixels_per_degree(0.7, 3840.0, 0.7); }

flip_result flip(const image& reference, const image& test, const flip_options& options) {
    if (reference.width() != test.width() || reference.height() != test.height())
        throw usage_error("FLIP compares images of the same size; the reference is " +
                          std::to_string(reference.width()) + " x " + std::to_string(reference.height()) +
                          " pixels and the test image " + std::to_string(test.width()) + " x " +
                          std::to_string(test.height()));
    if (!(options.pixels_per_degree > 0) || !std::isfinite(options.pixels_per_degree))
        throw usage_error("FLIP: pixels per degree must be a positive number");
    const double ppd = options.pixels_per_degree;
    const rgb_planes ref = linear_rgb(reference), tst = linear_rgb(test);

    // Colour pipeline: the distance of the filtered, Hunt-adjusted colours, redistributed.
    const csf_filters csf = make_csf_filters(ppd);
    const filtered_lab ref_lab = colour_pipeline(ref, csf), tst_lab = colour_pipeline(tst, csf);
    // Feature pipeline: how much the edges and points differ.
    const feature_filters ff = make_feature_filters(ppd);
    const features ref_f = feature_pipeline(ref, ff), tst_f = feature_pipeline(tst, ff);

    const double cmax = max_distance();
    flip_result r;
    r.width = reference.width();
    r.height = reference.height();
    r.error.resize(ref_lab.l.v.size());
    double sum = 0;
    for (std::size_t i = 0; i < r.error.size(); ++i) {
        const double distance = hyab({ref_lab.l.v[i], ref_lab.a.v[i], ref_lab.b.v[i]},
                                     {tst_lab.l.v[i], tst_lab.a.v[i], tst_lab.b.v[i]});
        const double colour = redistribute(std::pow(distance, flip_constants::qc), cmax);
        // Edges and points each give a difference in [0, sqrt 2]; the larger one counts.
        const double edge = std::abs(ref_f.edge.v[i] - tst_f.edge.v[i]);
        const double point = std::abs(ref_f.point.v[i] - tst_f.point.v[i]);
        const double feature = std::pow(std::max(edge, point) / std::sqrt(2.0), flip_constants::qf);
        // Final difference map: a feature difference lowers the exponent of the colour
        // error, raising it (colour errors are in [0, 1]).
        const double e = std::clamp(std::pow(colour, 1.0 - feature), 0.0, 1.0);
        r.error[i] = static_cast<float>(e);
        sum += e;
        r.max = std::max(r.max, e);
    }
    r.mean = r.error.empty() ? 0 : sum / static_cast<double>(r.error.size());
    r.weighted_median = flip_weighted_percentile(r.error, 0.5);
    r.weighted_quartile_1 = flip_weighted_percentile(r.error, 0.25);
    r.weighted_quartile_3 = flip_weighted_percentile(r.error, 0.75);
    return r;
}

double flip_weighted_percentile(std::span<const float> values, double p) {
    std::vector<float> sorted(values.begin(), values.end());
    std::sort(sorted.begin(), sorted.end());
    double total = 0;
    for (const float v : sorted) total += v;
    double running = 0;
    for (const float v : sorted) {
        running += v;
        if (running > p * total) return v;
    }
    return 0;  // every value is 0 (or there are none)
}

void flip_magma(double error, double rgb[3]) {
    const double e = std::isnan(error) ? 0.0 : std::clamp(error, 0.0, 1.0);
    const auto* c = detail::magma_map[static_cast<int>(e * 255.0 + 0.5)];
    for (int k = 0; k < 3; ++k) rgb[k] = c[k];
}

image flip_error_map(const flip_result& result) {
    image out(result.width, result.height, 3, sample_type::u8);
    auto s = out.samples<std::uint8_t>();
    for (std::size_t i = 0; i < result.error.size(); ++i) {
        double c[3];
        flip_magma(result.error[i], c);
        for (int k = 0; k < 3; ++k) s[3 * i + static_cast<std::size_t>(k)] = static_cast<std::uint8_t>(std::lround(255.0 * c[k]));
    }
    return out;
}

}  // namespace vl
