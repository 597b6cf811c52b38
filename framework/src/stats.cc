#include "vl/stats.hh"

#include <ostream>

namespace vl {

intersection_counts& intersection_counts::operator+=(const intersection_counts& o) {
    primitive_tests += o.primitive_tests;
    composite_tests += o.composite_tests;
    bounding_volume_tests += o.bounding_volume_tests;
    misses += o.misses;
    composite_only += o.composite_only;
    return *this;
}

intersection_counts& intersection_counts::operator-=(const intersection_counts& o) {
    primitive_tests -= o.primitive_tests;
    composite_tests -= o.composite_tests;
    bounding_volume_tests -= o.bounding_volume_tests;
    misses -= o.misses;
    composite_only -= o.composite_only;
    return *this;
}

std::ostream& operator<<(std::ostream& s, const intersection_counts& c) {
    return s << "primitive tests " << c.primitive_tests << ", composite tests " << c.composite_tests
             << ", bounding-volume tests " << c.bounding_volume_tests << ", misses " << c.misses
             << ", composite-only hits " << c.composite_only;
}

}  // namespace vl
