// The Hall/Whitted tracer assembled from the terms in shading_terms.hh. The sum is built
// from the far end: what the mirror and the refraction bring back first, then the lights
// in reverse order, then the ambient light.
#include "shading_terms.hh"
#include "stage_04.hh"

namespace vl::stage04 {

namespace {

class whitted_tracer final : public tracer {
public:
    explicit whitted_tracer(const scene& s) : scene_(s) {}

    color trace(const ray& r, int depth) const override {
        const std::optional<terms::hit_record> found = terms::find_hit(scene_, r);
        if (!found) return scene_.background;
        const terms::hit_record& h = *found;

        color total = depth > 0 ? h.object->clr() * secondary(h, depth - 1) : BLACK;
        for (auto light = scene_.lights.rbegin(); light != scene_.lights.rend(); ++light) {
            const color direct = terms::diffuse_term(h, *light) + terms::highlight_term(h, *light);
            if (direct == BLACK) continue;  // behind the surface, or a surface that sends none back
            if (terms::light_visible(scene_, h, light->pnt())) total += direct;
        }
        return total + terms::ambient_term(scene_, h);
    }

private:
    /// w_r times the reflected ray's colour plus w_t times the transmitted ray's.
    color secondary(const terms::hit_record& h, int depth) const {
        const double ksr = h.object->ksr(), kst = h.object->kst();
        color sum = BLACK;
        if (kst == 0) {
            if (ksr != 0) sum += ksr * trace(terms::departing(h, terms::mirror(h)), depth);
            return sum;
        }
        const terms::fresnel_split f = terms::split(h);
        if (f.transmitted) {
            const double w_t = kst * (1 - f.reflectance);
            if (w_t != 0) sum += w_t * trace(terms::departing(h, *f.transmitted), depth);
        }
        const double w_r = ksr + kst * f.reflectance;
        if (w_r != 0) sum += w_r * trace(terms::departing(h, terms::mirror(h)), depth);
        return sum;
    }

    const scene& scene_;
};

}  // namespace

std::unique_ptr<tracer> make_whitted_tracer(const scene& s) { return std::make_unique<whitted_tracer>(s); }

}  // namespace vl::stage04
