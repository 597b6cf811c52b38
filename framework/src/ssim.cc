// SSIM (Wang et al. 2004): local statistics in a Gaussian window, combined by the paper's
// equation (13),
//
//   SSIM(x, y) = (2 mu_x mu_y + C1) (2 sigma_xy + C2) / ((mu_x^2 + mu_y^2 + C1) (sigma_x^2 + sigma_y^2 + C2))
//
// with the weighted means, variances and covariance of equations (14)-(16).
#include "vl/ssim.hh"
#include "vl/error.hh"

#include <algorithm>
#include <cmath>
#include <string>

#include "vl/pixel.hh"

namespace vl {

namespace {

struct plane {
    int w = 0, h = 0;
    std::vector<double> v;
    plane(int width, int height) : w(width), h(height), v(static_cast<std::size_t>(width) * height, 0.0) {}
    double at(int x, int y) const { return v[static_cast<std::size_t>(y) * w + x]; }
};

// The signal SSIM compares: sRGB-encoded relative luminance in [0, 1] (see ssim.hh).
plane luminance_signal(const image& img) {
    const image lin = convert_channels(convert_samples(img, sample_type::f32), 3);
    const auto s = lin.samples<float>();
    plane p(img.width(), img.height());
    for (std::size_t i = 0; i < p.v.size(); ++i) {
        const double y = std::clamp(luminance(s[3 * i], s[3 * i + 1], s[3 * i + 2]), 0.0, 1.0);
        p.v[i] = linear_to_srgb(y);
    }
    return p;
}

// The 1-D Gaussian whose outer product with itself is the paper's window (sums to 1).
std::vector<double> gaussian_window() {
    using namespace ssim_constants;
    std::vector<double> g;
    double sum = 0;
    for (int i = -window / 2; i <= window / 2; ++i) {
        g.push_back(std::exp(-(i * i) / (2.0 * sigma * sigma)));
        sum += g.back();
    }
    for (double& x : g) x /= sum;
    return g;
}

// The weighted average of `in` in the window around each output pixel. With `valid`, only
// windows wholly inside (output (w - 10) x (h - 10)); otherwise one per pixel, the image's
// edge pixels repeated outside it.
plane window_average(const plane& in, const std::vector<double>& g, bool valid) {
    const int r = static_cast<int>(g.size() / 2);
    const int ow = valid ? in.w - 2 * r : in.w, oh = valid ? in.h - 2 * r : in.h;
    const int off = valid ? r : 0;  // output (x, y) is centred on input (x + off, y + off)
    plane across(ow, in.h), out(ow, oh);
    for (int y = 0; y < in.h; ++y)
        for (int x = 0; x < ow; ++x) {
            double s = 0;
            for (int i = -r; i <= r; ++i) s += g[static_cast<std::size_t>(i + r)] * in.at(std::clamp(x + off + i, 0, in.w - 1), y);
            across.v[static_cast<std::size_t>(y) * ow + x] = s;
        }
    for (int y = 0; y < oh; ++y)
        for (int x = 0; x < ow; ++x) {
            double s = 0;
            for (int i = -r; i <= r; ++i)
                s += g[static_cast<std::size_t>(i + r)] * across.at(x, std::clamp(y + off + i, 0, in.h - 1));
            out.v[static_cast<std::size_t>(y) * ow + x] = s;
        }
    return out;
}

}  // namespace

ssim_result ssim(const image& reference, const image& test) {
    if (reference.width() != test.width() || reference.height() != test.height())
        throw usage_error("SSIM compares images of the same size; the reference is " +
                          std::to_string(reference.width()) + " x " + std::to_string(reference.height()) +
                          " pixels and the test image " + std::to_string(test.width()) + " x " +
                          std::to_string(test.height()));
    using namespace ssim_constants;
    const plane x = luminance_signal(reference), y = luminance_signal(test);
    plane xx(x.w, x.h), yy(x.w, x.h), xy(x.w, x.h);
    for (std::size_t i = 0; i < x.v.size(); ++i) {
        xx.v[i] = x.v[i] * x.v[i];
        yy.v[i] = y.v[i] * y.v[i];
        xy.v[i] = x.v[i] * y.v[i];
    }
    const bool valid = x.w >= window && x.h >= window;
    const auto g = gaussian_window();
    const plane mx = window_average(x, g, valid), my = window_average(y, g, valid);
    const plane mxx = window_average(xx, g, valid), myy = window_average(yy, g, valid), mxy = window_average(xy, g, valid);

    const double c1 = (k1 * range) * (k1 * range), c2 = (k2 * range) * (k2 * range);
    ssim_result r;
    r.width = mx.w;
    r.height = mx.h;
    r.map.resize(mx.v.size());
    double sum = 0;
    for (std::size_t i = 0; i < mx.v.size(); ++i) {
        const double mu_x = mx.v[i], mu_y = my.v[i];
        const double var_x = mxx.v[i] - mu_x * mu_x, var_y = myy.v[i] - mu_y * mu_y, cov = mxy.v[i] - mu_x * mu_y;
        const double s = (2 * mu_x * mu_y + c1) * (2 * cov + c2) / ((mu_x * mu_x + mu_y * mu_y + c1) * (var_x + var_y + c2));
        r.map[i] = static_cast<float>(s);
        sum += s;
    }
    r.mean = r.map.empty() ? 1.0 : sum / static_cast<double>(r.map.size());
    return r;
}

}  // namespace vl
