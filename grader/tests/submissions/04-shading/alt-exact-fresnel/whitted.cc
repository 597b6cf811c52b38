// The Hall/Whitted tracer with the exact Fresnel equations for unpolarised light: the
// reflectance is the mean of the s- and p-polarised reflectances,
//     r_s = (eta1 cos_i - eta2 cos_t) / (eta1 cos_i + eta2 cos_t)
//     r_p = (eta2 cos_i - eta1 cos_t) / (eta2 cos_i + eta1 cos_t)
//     F = (r_s^2 + r_p^2) / 2,
// and F = 1 under total internal reflection. Everything else is stage_04.hh step by step.
#include <algorithm>
#include <cmath>

#include "stage_04.hh"

namespace vl::stage04 {

namespace {

/// The Fresnel reflectance for unpolarised light crossing from index eta1 into eta2.
double fresnel_exact(double eta1, double eta2, double cos_i, double cos_t) {
    const double rs = (eta1 * cos_i - eta2 * cos_t) / (eta1 * cos_i + eta2 * cos_t);
    const double rp = (eta2 * cos_i - eta1 * cos_t) / (eta2 * cos_i + eta1 * cos_t);
    return 0.5 * (rs * rs + rp * rp);
}

class whitted_tracer final : public tracer {
public:
    explicit whitted_tracer(const scene& s) : scene_(s) {}

    color trace(const ray& r, int depth) const override {
        const intersection hit = scene_.root->intersect(r);
        if (!hit.hit()) return scene_.background;

        const rtab_component& o = *hit.object;
        const point p = r.t_point(hit.t);
        const vector d = r.direction();
        const bool inside = o.contains(r.origin());
        vector n = o.normal(p);
        if (inside) n = -n;
        const color c = o.clr();

        // How far off the surface secondary rays start: relative to the coordinates.
        const double scale = std::max({1.0, std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)});
        const double eps = 1e-9 * scale;
        const auto off = [&](const vector& dir) { return ray(p + ((dir * n) > 0 ? eps : -eps) * n, dir); };

        color result = (o.kdr() * scene_.ambient) * c;
        for (const color_point& light : scene_.lights) {
            const vector to_light = light.pnt() - p;
            const vector l = to_light.unit();
            const double ndl = n * l;
            if (ndl <= 0 || std::isnan(ndl)) continue;
            const ray shadow = off(l);
            const double reach = (light.pnt() - shadow.origin()).length();
            const intersection block = scene_.root->intersect(shadow);
            if (block.hit() && block.t < reach) continue;
            const color filtered = c * light.clr();
            const double ndh = n * (l - d).unit();
            result += (o.kdr() * ndl) * filtered;
            result += (o.ksr() * std::pow(ndh > 0 ? ndh : 0.0, o.n())) * filtered;
        }
        if (depth <= 0) return result;

        double reflect_weight = o.ksr();
        double transmit_weight = 0;
        vector t_dir;
        if (o.kst() != 0) {
            const double eta1 = inside ? o.ior() : 1.0, eta2 = inside ? 1.0 : o.ior();
            const double eta = eta1 / eta2;
            const double cos_i = -(d * n);
            const double k = 1 - eta * eta * (1 - cos_i * cos_i);
            if (k < 0) {
                reflect_weight += o.kst();  // totally internally reflected: F = 1
            } else {
                const double cos_t = std::sqrt(k);
                const double f = fresnel_exact(eta1, eta2, cos_i, cos_t);
                reflect_weight += o.kst() * f;
                transmit_weight = o.kst() * (1 - f);
                t_dir = eta * d + (eta * cos_i - cos_t) * n;
            }
        }
        color bounced = BLACK;
        if (reflect_weight != 0) bounced += reflect_weight * trace(off(d - 2 * (d * n) * n), depth - 1);
        if (transmit_weight != 0) bounced += transmit_weight * trace(off(t_dir), depth - 1);
        return result + c * bounced;
    }

private:
    const scene& scene_;
};

}  // namespace

std::unique_ptr<tracer> make_whitted_tracer(const scene& s) { return std::make_unique<whitted_tracer>(s); }

}  // namespace vl::stage04
