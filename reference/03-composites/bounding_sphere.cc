// Reference: the bounding sphere's factory (see assignments/03-composites/stage_03.hh); the
// class is in bounding_sphere.hh, whole, since frac_sphere.cc builds on it.
#include "bounding_sphere.hh"

namespace vl::stage03 {

std::unique_ptr<rtab_composite> make_bounding_sphere() { return std::make_unique<bounding_sphere>(); }

}  // namespace vl::stage03
