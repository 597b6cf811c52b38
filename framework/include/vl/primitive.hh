#pragma once
/// \file
/// \brief A leaf with a surface: what spheres, planes and polygons derive from.

#include <iosfwd>
#include <string>
#include <vector>

#include "vl/rt_base_objects.hh"
#include "vl/scene_reader.hh"

namespace vl {

/// \brief The Hall surface-physics values of one object, with "absent" defaults
/// (see rtab_component's surface-physics members).
struct surface {
    color clr = WHITE;        ///< surface colour
    double kdr = 0;           ///< diffuse reflection
    double ksr = 0;           ///< specular reflection
    double kdt = 0;           ///< diffuse transmission
    double kst = 0;           ///< specular transmission
    double n = 1;             ///< specular (Phong) exponent
    double ior = 1;           ///< index of refraction
    double zero_t = rtab_component::default_zero_t;  ///< see rtab_component::zero_t()
};

/// Adds the surface keys (`color`, `kdr`, `ksr`, `kdt`, `kst`, `n`, `ior`, `zero_t`) to
/// `properties`, each reading into `s` through `in`; `owner` names the object in messages.
/// For composites that pass one surface on to their parts (stage 03's BOX, FRACSPH).
void add_surface_properties(std::vector<scene_reader::property>& properties, scene_reader& in, surface& s,
                            const std::string& owner);
/// Writes the surface keys of `s` that differ from the defaults (` kdr 0.5 ...`).
void write_surface(std::ostream& out, const surface& s);

/// \brief A leaf (primitive) object that stores a vl::surface and reads it from a scene.
///
/// A concrete primitive defines type_name(), its geometry and find_intersection(), and
/// reads its own properties with read_with_surface(), which adds the surface keys:
/// `color`, `kdr`, `ksr`, `kdt`, `kst`, `n`, `ior`, `zero_t`.
class primitive : public rtab_component {
public:
    color clr() const override { return surface_->clr; }
    double kdr() const override { return surface_->kdr; }
    double ksr() const override { return surface_->ksr; }
    double kdt() const override { return surface_->kdt; }
    double kst() const override { return surface_->kst; }
    double n() const override { return surface_->n; }
    double ior() const override { return surface_->ior; }
    double zero_t() const override { return surface_->zero_t; }

    /// The surface, to read or change.
    const surface& surf() const { return *surface_; }
    /// Replaces the surface.
    void set_surface(const surface& s) { surface_ = shared_surface(s); }

protected:
    primitive() : surface_(default_surface()) {}
    /// Reads `{ ... }` with the object's own `properties` and the surface keys.
    void read_with_surface(scene_reader& in, std::vector<scene_reader::property> properties);
    /// Writes the surface keys that differ from the defaults, for write().
    void write_surface(std::ostream& s) const;

private:
    /// The one stored copy of the surface equal to `s`, bit for bit. Primitives share their
    /// surfaces (a scene of a million spheres usually has a handful of surfaces), which
    /// saves 80 bytes per primitive; copies live as long as the program.
    static const surface* shared_surface(const surface& s);
    /// shared_surface(surface{}), looked up once.
    static const surface* default_surface();

    const surface* surface_;  // never null
};

}  // namespace vl
