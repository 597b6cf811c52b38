// The Hall/Whitted tracer: see stage_04.hh for what trace() must return, step by step,
// and README.md for hints and the classic bugs. The class and its factory are done; the
// TODOs are yours. Keep to the object's rtab_component interface: never ask what you hit.
#include <algorithm>
#include <cmath>

#include "stage_04.hh"
#include "vl/not_implemented.hh"

namespace vl::stage04 {

namespace {

class whitted_tracer final : public tracer {
public:
    explicit whitted_tracer(const scene& s) : scene_(s) {}

    color trace([[maybe_unused]] const ray& r, [[maybe_unused]] int depth) const override {
        // TODO, in the order of stage_04.hh:
        //  1. hit = scene_.root->intersect(r); no hit(): scene_.background.
        //  2. P, N = normal(P), negated when the object contains(r.origin()).
        //  3. ambient * c * kdr, plus direct() for each light in scene_.lights.
        //  5. when depth > 0: c * (what the mirror and the refraction bring back),
        //     traced with depth - 1.
        throw not_implemented_error();
    }

private:
    // Suggested helpers (yours to shape: change them, add others).

    /// Steps 3 and 4 for one light: diffuse and highlight, or black when the light is
    /// behind the surface or a shadow ray from just off the surface hits something
    /// before the light.
    color direct([[maybe_unused]] const point& p, [[maybe_unused]] const vector& n, [[maybe_unused]] const vector& d,
                 [[maybe_unused]] const rtab_component& object, [[maybe_unused]] const color_point& light) const {
        // TODO
        throw not_implemented_error();
    }

    /// Step 5's optics: the ray along `dir` that leaves `p` on the side `dir` goes to,
    /// starting delta off the surface so it cannot hit it again through round-off.
    static ray leaving([[maybe_unused]] const point& p, [[maybe_unused]] const vector& n,
                       [[maybe_unused]] const vector& dir) {
        // TODO
        throw not_implemented_error();
    }

    const scene& scene_;
};

}  // namespace

std::unique_ptr<tracer> make_whitted_tracer(const scene& s) { return std::make_unique<whitted_tracer>(s); }

}  // namespace vl::stage04
