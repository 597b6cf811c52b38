#include "vl/ray.hh"

#include <ostream>

namespace vl {

std::ostream& operator<<(std::ostream& s, const ray& r) {
    return s << "ray (" << r.origin() << ", " << r.direction() << ')';
}

}  // namespace vl
