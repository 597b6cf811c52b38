// The Hall/Whitted tracer: the thesis's scene::trace made correct and complete. Every step
// is numbered as in stage_04.hh, which says what each must do.
#include <algorithm>
#include <cmath>

#include "stage_04.hh"

namespace vl::stage04 {

namespace {

/// What the optics of one surface needs: where, which way it faces, which way the ray came.
struct surface_point {
    point p;      // the hit point
    vector n;     // unit normal, facing the side the ray came from (step 2)
    vector d;     // unit direction of the incoming ray
    bool inside;  // the ray started inside the object: it is leaving it
};

/// Step 5's refraction at a surface: the Fresnel reflectance, and the transmitted
/// direction when there is one (`total` is total internal reflection).
struct refraction {
    double reflectance = 1;
    bool total = true;
    vector transmitted;
};

/// How far a secondary ray starts off the surface: above the round-off of P's coordinates.
double offset(const point& p) {
    return 1e-9 * std::max({1.0, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
}

/// A ray from `s.p` along `dir` that starts on the side of the surface it travels to.
ray leaving(const surface_point& s, const vector& dir) {
    const double delta = offset(s.p);
    return ray(s.p + (dir * s.n > 0 ? delta : -delta) * s.n, dir);
}

/// Snell's law and Schlick's reflectance, for an object of index `ior`.
refraction refract(const surface_point& s, double ior) {
    const double eta1 = s.inside ? ior : 1.0;
    const double eta2 = s.inside ? 1.0 : ior;
    const double eta = eta1 / eta2;
    const double cos_i = -(s.d * s.n);
    const double k = 1 - eta * eta * (1 - cos_i * cos_i);
    refraction out;
    if (k < 0) return out;  // total internal reflection: F = 1, nothing transmitted
    const double cos_t = std::sqrt(k);
    out.total = false;
    out.transmitted = eta * s.d + (eta * cos_i - cos_t) * s.n;
    const double r0 = ((eta1 - eta2) / (eta1 + eta2)) * ((eta1 - eta2) / (eta1 + eta2));
    const double cos = eta1 <= eta2 ? cos_i : cos_t;  // the cosine on the side of the lower index
    out.reflectance = r0 + (1 - r0) * std::pow(1 - cos, 5);
    return out;
}

class whitted_tracer final : public tracer {
public:
    explicit whitted_tracer(const scene& s) : scene_(s) {}

    color trace(const ray& r, int depth) const override {
        // 1. Nothing hit: the background.
        const intersection hit = scene_.root->intersect(r);
        if (!hit.hit()) return scene_.background;

        // 2. The surface, its normal facing the side the ray came from.
        const rtab_component& object = *hit.object;
        surface_point s;
        s.p = r.t_point(hit.t);
        s.d = r.direction();
        s.n = object.normal(s.p);
        s.inside = object.contains(r.origin());
        if (s.inside) s.n = -s.n;

        // 3. and 4. The local light: ambient, and each light the point can see.
        const color c = object.clr();
        color sum = scene_.ambient * c * object.kdr();
        for (const color_point& light : scene_.lights) sum += direct(object, s, light);

        // 5. Reflection and refraction, while the depth lasts.
        if (depth > 0) sum += c * bounced(object, s, depth - 1);
        return sum;  // 6. not clamped
    }

private:
    /// Diffuse and highlight from one light, or black when the light is behind the
    /// surface or something lies between.
    color direct(const rtab_component& object, const surface_point& s, const color_point& light) const {
        const vector to_light = light.pnt() - s.p;
        const vector L = to_light.unit();
        const double n_dot_l = s.n * L;
        if (!(n_dot_l > 0)) return BLACK;  // behind the surface (or a light on the surface)
        const ray shadow = leaving(s, L);
        const intersection blocker = scene_.root->intersect(shadow);
        if (blocker.hit() && blocker.t < (light.pnt() - shadow.origin()).length()) return BLACK;

        const vector H = (L - s.d).unit();
        const double n_dot_h = std::max(0.0, s.n * H);
        const double weight = object.kdr() * n_dot_l + object.ksr() * std::pow(n_dot_h, object.n());
        return weight * (object.clr() * light.clr());
    }

    /// What the mirror and the refraction bring back (before the surface colour filters it).
    color bounced(const rtab_component& object, const surface_point& s, int depth) const {
        const double ksr = object.ksr(), kst = object.kst();
        double w_r = ksr, w_t = 0;
        refraction t;
        if (kst != 0) {
            t = refract(s, object.ior());
            w_r += kst * t.reflectance;
            w_t = t.total ? 0 : kst * (1 - t.reflectance);
        }
        color sum = BLACK;
        if (w_r != 0) {
            const vector R = s.d - 2 * (s.d * s.n) * s.n;
            sum += w_r * trace(leaving(s, R), depth);
        }
        if (w_t != 0) sum += w_t * trace(leaving(s, t.transmitted), depth);
        return sum;
    }

    const scene& scene_;
};

}  // namespace

std::unique_ptr<tracer> make_whitted_tracer(const scene& s) { return std::make_unique<whitted_tracer>(s); }

}  // namespace vl::stage04
