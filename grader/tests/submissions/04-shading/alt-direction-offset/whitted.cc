// The Hall/Whitted tracer of stage_04.hh. Secondary rays avoid their own surface by
// starting a little way along their own direction: a ray that leaves a surface towards
// one side is already on that side after a step of 1e-8 times the size of P's largest
// coordinate (at least 1), far above the round-off of P, which is about 1e-16 of it.
#include <algorithm>
#include <cmath>

#include "stage_04.hh"

namespace vl::stage04 {

namespace {

constexpr double relative_step = 1e-8;

/// A ray from `p` along the unit vector `dir`, started one step along `dir`.
ray step_off(const point& p, const vector& dir) {
    const double size = std::max(std::max(1.0, std::abs(p.x)), std::max(std::abs(p.y), std::abs(p.z)));
    return ray(p + (relative_step * size) * dir, dir);
}

/// Schlick's reflectance, the cosine taken on the side of the lower index.
double schlick(double eta1, double eta2, double cos_low) {
    const double r0 = (eta1 - eta2) * (eta1 - eta2) / ((eta1 + eta2) * (eta1 + eta2));
    const double m = 1 - cos_low;
    return r0 + (1 - r0) * m * m * m * m * m;
}

class whitted_tracer final : public tracer {
public:
    explicit whitted_tracer(const scene& s) : scene_(s) {}

    color trace(const ray& r, int depth) const override {
        const intersection i = scene_.root->intersect(r);
        if (!i.hit()) return scene_.background;
        const rtab_component& obj = *i.object;
        const point p = r.t_point(i.t);
        const vector d = r.direction();
        const bool from_inside = obj.contains(r.origin());
        const vector n = from_inside ? -obj.normal(p) : obj.normal(p);
        color out = local(obj, p, n, d);
        if (depth > 0) out += obj.clr() * scattered(obj, p, n, d, from_inside, depth - 1);
        return out;
    }

private:
    /// Ambient, plus diffuse and highlight from each light that `p` sees.
    color local(const rtab_component& obj, const point& p, const vector& n, const vector& d) const {
        const color c = obj.clr();
        color sum = scene_.ambient * c * obj.kdr();
        for (const color_point& light : scene_.lights) {
            const vector l = (light.pnt() - p).unit();
            const double cos_l = n * l;
            if (!(cos_l > 0)) continue;
            if (blocked(p, l, light.pnt())) continue;
            const double cos_h = n * (l - d).unit();
            const double highlight = cos_h > 0 ? std::pow(cos_h, obj.n()) : 0.0;
            sum += (obj.kdr() * cos_l) * (c * light.clr()) + (obj.ksr() * highlight) * (c * light.clr());
        }
        return sum;
    }

    /// True when something lies between `p` and the light at `light_pos`.
    bool blocked(const point& p, const vector& l, const point& light_pos) const {
        const ray shadow = step_off(p, l);
        const intersection b = scene_.root->intersect(shadow);
        return b.hit() && b.t < (light_pos - shadow.origin()).length();
    }

    /// w_r times the mirror ray's colour plus w_t times the transmitted ray's.
    color scattered(const rtab_component& obj, const point& p, const vector& n, const vector& d, bool from_inside,
                    int depth) const {
        double w_r = obj.ksr(), w_t = 0;
        vector t_dir;
        if (obj.kst() != 0) {
            const double eta1 = from_inside ? obj.ior() : 1;
            const double eta2 = from_inside ? 1 : obj.ior();
            const double eta = eta1 / eta2;
            const double cos_i = -(d * n);
            const double k = 1 - eta * eta * (1 - cos_i * cos_i);
            double f = 1;  // total internal reflection unless k >= 0
            if (!(k < 0)) {
                const double cos_t = std::sqrt(k);
                f = schlick(eta1, eta2, eta1 <= eta2 ? cos_i : cos_t);
                w_t = obj.kst() * (1 - f);
                t_dir = eta * d + (eta * cos_i - cos_t) * n;
            }
            w_r += obj.kst() * f;
        }
        color sum = BLACK;
        if (w_r != 0) sum += w_r * trace(step_off(p, d - 2 * (d * n) * n), depth);
        if (w_t != 0) sum += w_t * trace(step_off(p, t_dir), depth);
        return sum;
    }

    const scene& scene_;
};

}  // namespace

std::unique_ptr<tracer> make_whitted_tracer(const scene& s) { return std::make_unique<whitted_tracer>(s); }

}  // namespace vl::stage04
