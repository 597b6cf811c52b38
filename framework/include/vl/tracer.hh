#pragma once
/// \file
/// \brief Clients of the component tree: what turns a ray into a colour.
///
/// The framework ships two simple tracers so a scene can be rendered from stage 02 on;
/// stage 04 adds the Hall/Whitted tracer behind the same interface.

#include "vl/ray.hh"
#include "vl/scene.hh"

namespace vl {

/// \brief A ray-tracing algorithm: the *client* of the Composite pattern.
class tracer {
public:
    virtual ~tracer() = default;
    /// The colour seen along `r`; `depth` is how many more bounces are allowed.
    virtual color trace(const ray& r, int depth) const = 0;
};

/// \brief Each object in its own colour (clr()), unlit: shows silhouettes and
/// coverage, and nothing a shading bug could spoil.
class flat_tracer : public tracer {
public:
    /// Traces against `s` (kept by reference: it must outlive the tracer).
    explicit flat_tracer(const scene& s) : scene_(s) {}
    color trace(const ray& r, int depth) const override;

private:
    const scene& scene_;
};

/// \brief The outward unit normal at the hit, shown as a colour: `(N + 1) / 2` maps
/// x, y, z in [-1, 1] to red, green, blue in [0, 1]. A quick check of normal().
class normals_tracer : public tracer {
public:
    /// Traces against `s` (kept by reference: it must outlive the tracer).
    explicit normals_tracer(const scene& s) : scene_(s) {}
    color trace(const ray& r, int depth) const override;

private:
    const scene& scene_;
};

/// \brief The sky seen along each ray, white at the horizon to blue overhead, and each
/// object in its own colour where a ray hits one. With no objects at all it shows that
/// the camera works: which way is up, how wide the view is.
class sky_tracer : public tracer {
public:
    /// Traces against `s` (kept by reference: it must outlive the tracer).
    explicit sky_tracer(const scene& s) : scene_(s) {}
    color trace(const ray& r, int depth) const override;
    /// The sky's colour for a unit direction: a blend from white (down and level) to
    /// light blue (straight up) by the direction's y.
    static color sky(const vector& direction);

private:
    const scene& scene_;
};

}  // namespace vl
