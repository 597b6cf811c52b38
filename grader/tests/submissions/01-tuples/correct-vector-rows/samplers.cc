// Pixel sample patterns with the standard library: a std::mt19937_64 seeded with the
// pixel's seed and std::uniform_real_distribution, both local to offsets(). Rounding can
// carry a draw to the top of its range, so every coordinate is kept below its limit.
#include <cmath>
#include <random>

#include "stage_01.hh"

namespace vl::stage01 {

namespace {

double strictly_below(double v, double limit) { return v < limit ? v : std::nextafter(limit, 0.0); }

class standard_sampler : public sampler {
public:
    enum class mode { center, grid, jittered, random };
    explicit standard_sampler(mode m) : mode_(m) {}

    void offsets(std::span<sample_offset> out, std::uint64_t seed) const override {
        std::mt19937_64 engine(seed);
        std::uniform_real_distribution<double> unit(0.0, 1.0);
        const std::size_t n = out.size();
        std::size_t k = static_cast<std::size_t>(std::ceil(std::sqrt(static_cast<double>(n))));
        while (k * k < n) ++k;
        while (k > 0 && (k - 1) * (k - 1) >= n) --k;
        for (std::size_t i = 0; i < n; ++i) {
            if (mode_ == mode::center) {
                out[i] = {0.5, 0.5};
            } else if (mode_ == mode::random) {
                const double x = unit(engine);
                out[i] = {strictly_below(x, 1.0), strictly_below(unit(engine), 1.0)};
            } else {
                const double side = static_cast<double>(k);
                const double cx = static_cast<double>(i % k), cy = static_cast<double>(i / k);
                const double jx = mode_ == mode::grid ? 0.5 : unit(engine);
                const double jy = mode_ == mode::grid ? 0.5 : unit(engine);
                out[i] = {strictly_below((cx + jx) / side, (cx + 1) / side),
                          strictly_below((cy + jy) / side, (cy + 1) / side)};
            }
        }
    }

private:
    mode mode_;
};

}  // namespace

std::unique_ptr<sampler> make_sampler(std::string_view name) {
    using m = standard_sampler::mode;
    if (name == "center") return std::make_unique<standard_sampler>(m::center);
    if (name == "grid") return std::make_unique<standard_sampler>(m::grid);
    if (name == "jittered") return std::make_unique<standard_sampler>(m::jittered);
    if (name == "random") return std::make_unique<standard_sampler>(m::random);
    return nullptr;
}

}  // namespace vl::stage01
