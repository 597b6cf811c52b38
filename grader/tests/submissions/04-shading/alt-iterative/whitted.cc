// The Hall/Whitted tracer without recursion: every ray still to be followed waits on a
// stack with the colour that scales what it brings back (the product of the filters and
// weights on its way from the eye). The colour of the primary ray is the sum, over every
// ray followed, of that factor times the ray's local light; a ray that escapes adds the
// factor times the background. This is the recursive sum of stage_04.hh written out.
#include <algorithm>
#include <cmath>
#include <vector>

#include "stage_04.hh"

namespace vl::stage04 {

namespace {

/// A ray waiting to be followed: how many more bounces it may make, and what its colour
/// is multiplied by before it is added to the pixel.
struct pending_ray {
    ray r;
    int depth;
    color factor;
};

/// The largest absolute coordinate of `p`, but at least 1: the scale of its round-off.
double magnitude(const point& p) {
    double m = 1;
    for (double v : {p.x, p.y, p.z}) m = std::max(m, std::fabs(v));
    return m;
}

class whitted_tracer final : public tracer {
public:
    explicit whitted_tracer(const scene& s) : scene_(s) {}

    color trace(const ray& r, int depth) const override {
        color total = BLACK;
        std::vector<pending_ray> todo;
        todo.push_back({r, depth, color(1, 1, 1, 1)});
        while (!todo.empty()) {
            const pending_ray job = todo.back();
            todo.pop_back();
            follow(job, total, todo);
        }
        return total;
    }

private:
    /// Adds what `job` sees locally to `total` and pushes the rays it spawns.
    void follow(const pending_ray& job, color& total, std::vector<pending_ray>& todo) const {
        const intersection found = scene_.root->intersect(job.r);
        if (!found.hit()) {
            total += job.factor * scene_.background;
            return;
        }
        const rtab_component& obj = *found.object;
        const point p = job.r.t_point(found.t);
        const vector d = job.r.direction();
        const bool leaving = obj.contains(job.r.origin());
        const vector nrm = leaving ? -obj.normal(p) : obj.normal(p);
        const color surface = obj.clr();
        const double lift = 1e-9 * magnitude(p);

        // Local light: ambient, then every light in view.
        color local = obj.kdr() * (scene_.ambient * surface);
        for (const color_point& lamp : scene_.lights) {
            const vector towards = lamp.pnt() - p;
            const vector l = towards / towards.length();
            const double cos_l = nrm * l;
            if (!(cos_l > 0)) continue;  // the light is on the other side of the surface
            const ray feeler(p + lift * nrm, l);  // l leaves on the normal's side
            const intersection block = scene_.root->intersect(feeler);
            if (block.hit() && block.t < (lamp.pnt() - feeler.origin()).length()) continue;
            const vector half = (l - d).unit();
            const double spec = std::pow(std::max(0.0, nrm * half), obj.n());
            local += (obj.kdr() * cos_l + obj.ksr() * spec) * (surface * lamp.clr());
        }
        total += job.factor * local;

        if (job.depth <= 0) return;

        // The mirror and the refraction: new rays, their factors carrying the filter c.
        double w_mirror = obj.ksr();
        double w_through = 0;
        vector through;
        if (obj.kst() != 0) {
            const double n_from = leaving ? obj.ior() : 1.0;
            const double n_to = leaving ? 1.0 : obj.ior();
            const double ratio = n_from / n_to;
            const double ci = -(d * nrm);
            const double k = 1 - ratio * ratio * (1 - ci * ci);
            double fresnel = 1;
            if (k >= 0) {
                const double ct = std::sqrt(k);
                const double r0 = std::pow((n_from - n_to) / (n_from + n_to), 2);
                const double c_low = n_from > n_to ? ct : ci;
                fresnel = r0 + (1 - r0) * std::pow(1 - c_low, 5);
                through = ratio * d + (ratio * ci - ct) * nrm;
                w_through = obj.kst() * (1 - fresnel);
            }
            w_mirror += obj.kst() * fresnel;
        }
        const color carried = job.factor * surface;
        if (w_mirror != 0) {
            const vector m = d - 2 * (d * nrm) * nrm;
            todo.push_back({ray(p + (m * nrm > 0 ? lift : -lift) * nrm, m), job.depth - 1, w_mirror * carried});
        }
        if (w_through != 0)
            todo.push_back({ray(p + (through * nrm > 0 ? lift : -lift) * nrm, through), job.depth - 1, w_through * carried});
    }

    const scene& scene_;
};

}  // namespace

std::unique_ptr<tracer> make_whitted_tracer(const scene& s) { return std::make_unique<whitted_tracer>(s); }

}  // namespace vl::stage04
