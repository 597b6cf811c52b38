#pragma once
/// \file
/// \brief The plainest composite: a list of objects, each tested in turn.

#include "vl/rt_base_objects.hh"

namespace vl {

/// \brief A composite that tests every child and returns the nearest hit.
///
/// No bounding volume, so it costs one test per child per ray: the baseline every
/// acceleration structure of stage 03 is measured against. In a scene file:
/// `LIST { SPHERE { ... } PLANE { ... } }`.
class object_list : public rtab_composite {
public:
    object_list() = default;
    std::string type_name() const override { return "LIST"; }
    /// Reads `{ OBJECT ... }`: any number of registered objects between braces.
    void read(scene_reader& in) override;

private:
    intersection find_intersection(const ray& r) const override { return nearest_child_hit(r); }
};

}  // namespace vl
