// Stage 01: the pixel sample patterns `center`, `grid`, `jittered` and `random`. What
// each must give is in stage_01.hh; the interface is vl::sampler (vl/camera.hh); the
// public tests are in tests/samplers_test.cc.
#include "stage_01.hh"
#include "vl/not_implemented.hh"

namespace vl::stage01 {

// TODO: write one class per pattern (or one class with a switch, where two patterns
//       differ only a little), each deriving from vl::sampler and overriding offsets().
// TODO: offsets() is const and runs on many threads at once: make the random generator
//       a local variable of offsets(), seeded with `seed` alone. It is seeded once per
//       pixel, so take one that is cheap to seed: vl::splitmix64 and vl::uniform01 in
//       vl/random.hh (std::mt19937_64 is correct too, but seeding it costs more than
//       tracing a simple pixel's rays). Make no generator where nothing is drawn.
// TODO: for grid and jittered: find k, the smallest whole number with k * k >= n (you can
//       check your answer with integers), then put sample i in cell (i % k, i / k).
// TODO: every offset must be below 1. Can (cx + u) / k round up to the cell's upper edge
//       when u is the largest double below 1? (<cmath> has std::nextafter.)

std::unique_ptr<sampler> make_sampler([[maybe_unused]] std::string_view name) {
    // TODO: return a new sampler for each of the four names, nullptr for anything else.
    throw not_implemented_error();
}

}  // namespace vl::stage01
