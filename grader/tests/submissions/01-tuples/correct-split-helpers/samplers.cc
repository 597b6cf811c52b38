// Pixel sample patterns. Each random pattern builds its own std::mt19937_64 from the
// seed inside offsets(), so nothing is shared between calls or threads.
#include <cmath>
#include <functional>

#include "random_source.hh"
#include "stage_01.hh"

namespace vl::stage01 {

namespace {

using fill_function = std::function<void(std::span<sample_offset>, std::uint64_t)>;

class function_sampler : public sampler {
public:
    explicit function_sampler(fill_function f) : fill_(std::move(f)) {}
    void offsets(std::span<sample_offset> out, std::uint64_t seed) const override { fill_(out, seed); }

private:
    fill_function fill_;
};

std::size_t ceil_sqrt(std::size_t n) {
    std::size_t k = 0;
    while (k * k < n) ++k;
    return k;
}

double below(double v, double limit) { return v < limit ? v : std::nextafter(limit, 0.0); }

void stratified(std::span<sample_offset> out, std::uint64_t seed, bool jitter) {
    const std::size_t n = out.size(), k = ceil_sqrt(n);
    random_source rng(seed);
    const double side = static_cast<double>(k);
    for (std::size_t i = 0; i < n; ++i) {
        const double cx = static_cast<double>(i % k), cy = static_cast<double>(i / k);
        const double jx = jitter ? rng.next() : 0.5, jy = jitter ? rng.next() : 0.5;
        out[i].dx = below((cx + jx) / side, (cx + 1) / side);
        out[i].dy = below((cy + jy) / side, (cy + 1) / side);
    }
}

}  // namespace

std::unique_ptr<sampler> make_sampler(std::string_view name) {
    if (name == "center")
        return std::make_unique<function_sampler>([](std::span<sample_offset> out, std::uint64_t) {
            for (auto& o : out) o.dx = o.dy = 0.5;
        });
    if (name == "grid")
        return std::make_unique<function_sampler>(
            [](std::span<sample_offset> out, std::uint64_t seed) { stratified(out, seed, false); });
    if (name == "jittered")
        return std::make_unique<function_sampler>(
            [](std::span<sample_offset> out, std::uint64_t seed) { stratified(out, seed, true); });
    if (name == "random")
        return std::make_unique<function_sampler>([](std::span<sample_offset> out, std::uint64_t seed) {
            random_source rng(seed);
            for (auto& o : out) {
                o.dx = rng.next();
                o.dy = rng.next();
            }
        });
    return nullptr;
}

}  // namespace vl::stage01
