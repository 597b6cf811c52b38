#include "vl/render.hh"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <mutex>
#include <thread>

#include "vl/camera.hh"
#include "vl/error.hh"
#include "vl/random.hh"

namespace vl {

std::uint64_t pixel_seed(int x, int y, std::uint64_t image_seed) {
    std::uint64_t z = (static_cast<std::uint64_t>(static_cast<std::uint32_t>(x)) << 32) ^
                      static_cast<std::uint32_t>(y);
    // Seed 0 leaves z as it is: the default image does not change.
    return splitmix64_mix(z + splitmix64_gamma * (image_seed + 1));
}

namespace {

using clock_type = std::chrono::steady_clock;

/// Draws `[#####     ]  45%` on stderr, once the render has run for a second.
class progress_bar {
public:
    explicit progress_bar(bool wanted) : enabled_(wanted && isatty(STDERR_FILENO)) {}
    void show(std::size_t done, std::size_t total) {
        if (!enabled_ || clock_type::now() - start_ < std::chrono::seconds(1)) return;
        constexpr int width = 40;
        const int filled = static_cast<int>(width * done / std::max<std::size_t>(total, 1));
        std::fprintf(stderr, "\r[%.*s%*s] %3d%%", filled, "########################################", width - filled,
                     "", static_cast<int>(100 * done / std::max<std::size_t>(total, 1)));
        std::fflush(stderr);
        shown_ = true;
    }
    ~progress_bar() {
        if (shown_) std::fprintf(stderr, "\r%*s\r", 48, "");
    }

private:
    bool enabled_;
    bool shown_ = false;
    clock_type::time_point start_ = clock_type::now();
};

struct tile {
    int x0, y0, x1, y1;
};

}  // namespace

render_stats render(const scene& s, const registry& types, vfb& out, const render_options& options) {
    const int width = out.width(), height = out.height();
    const auto cam = types.make_camera(s.camera, width, height);
    const auto pattern = types.make_sampler(s.sampler);
    const auto client = types.make_tracer(s.tracer, s);
    const int spp = std::max(1, s.samples_per_pixel);

    std::vector<tile> tiles;
    const int ts = std::max(1, options.tile_size);
    for (int y = 0; y < height; y += ts)
        for (int x = 0; x < width; x += ts) tiles.push_back({x, y, std::min(x + ts, width), std::min(y + ts, height)});

    render_stats stats;
    stats.width = width;
    stats.height = height;
    stats.tests_per_pixel.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), 0);
    const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
    stats.threads = static_cast<int>(std::min<std::size_t>(options.threads > 0 ? static_cast<std::size_t>(options.threads) : cores,
                                                           std::max<std::size_t>(tiles.size(), 1)));

    std::atomic<std::size_t> next_tile{0}, tiles_done{0};
    std::mutex mutex;  // guards the summed stats and the first error
    std::condition_variable finished;
    std::exception_ptr error;

    auto work = [&] {
        const intersection_counts start = counts();
        std::uint64_t rays = 0;
        std::vector<sample_offset> offsets(static_cast<std::size_t>(spp));
        try {
            for (std::size_t k; (k = next_tile++) < tiles.size();) {
                if (options.cancel && options.cancel->load()) break;
                const tile& t = tiles[k];
                for (int y = t.y0; y < t.y1; ++y) {
                    for (int x = t.x0; x < t.x1; ++x) {
                        const std::uint64_t before = counts().total_tests();
                        pattern->offsets(offsets, pixel_seed(x, y, options.seed));
                        color sum = BLACK;
                        for (const sample_offset& o : offsets)
                            sum += client->trace(cam->primary_ray(x + o.dx, y + o.dy), s.max_depth);
                        out.put_pixel(x, y, vfb_pixel(sum / spp));
                        const std::uint64_t cost = counts().total_tests() - before;
                        stats.tests_per_pixel[static_cast<std::size_t>(x) + static_cast<std::size_t>(y) * static_cast<std::size_t>(width)] =
                            static_cast<std::uint32_t>(std::min<std::uint64_t>(cost, UINT32_MAX));
                    }
                }
                rays += static_cast<std::uint64_t>(t.x1 - t.x0) * static_cast<std::uint64_t>(t.y1 - t.y0) *
                        static_cast<std::uint64_t>(spp);
                if (options.on_tile) options.on_tile(t.x0, t.y0, t.x1, t.y1);
                // Only the last tile wakes the waiting thread (a wake-up per tile was a system
                // call per tile); it shows the progress on its own every 100 ms. Taking the
                // mutex first means the wake-up cannot fall between its check and its wait.
                if (++tiles_done == tiles.size()) {
                    { const std::lock_guard lock(mutex); }
                    finished.notify_one();
                }
            }
        } catch (...) {
            {
                const std::lock_guard lock(mutex);
                if (!error) error = std::current_exception();
                next_tile = tiles.size();  // stop the others
            }
            finished.notify_one();
        }
        const std::lock_guard lock(mutex);
        stats.counts += counts() - start;
        stats.primary_rays += rays;
    };

    const auto started = clock_type::now();
    {
        std::vector<std::jthread> workers;
        for (int k = 0; k < stats.threads; ++k) workers.emplace_back(work);
        progress_bar bar(options.progress);
        std::unique_lock lock(mutex);
        while (tiles_done < tiles.size()) {
            if (options.cancel && options.cancel->load()) break;
            finished.wait_for(lock, std::chrono::milliseconds(100));
            bar.show(tiles_done, tiles.size());
            if (error) break;
        }
    }  // joins every worker
    stats.seconds = std::chrono::duration<double>(clock_type::now() - started).count();
    if (error) std::rethrow_exception(error);
    stats.cancelled = tiles_done < tiles.size();
    return stats;
}

render_stats render_to_vfb(const std::filesystem::path& file, const registry& types, vfb& out,
                           const render_options& options) {
    if (file.extension() != ".ray_trace")
        throw file_error(file.string() + ": cannot render a '" + file.extension().string() +
                         "' file: render_to_vfb knows .ray_trace (ray trace)");
    const scene s = read_scene(file, types);
    return render(s, types, out, options);
}

}  // namespace vl
