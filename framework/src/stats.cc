#include "vl/stats.hh"

#include <ostream>
#include <string>

#include "vl/error.hh"

namespace vl {

void detail::refuse_count(std::uint64_t n, std::uint64_t counted) {
    const std::string why =
        n > most_tests_per_count
            ? "is more tests than any ray makes (a negative number turned unsigned?)"
            : "would take this thread's count past 2^64, where it starts again from 0 (it holds " +
                  std::to_string(counted) + ")";
    throw usage_error("count_bounding_volume_tests(" + std::to_string(n) + "): " + why +
                      "; count each box or sphere test once, as the number of tests made, and nothing else");
}

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
