#include "render_job.hh"

#include "vl/error.hh"

namespace vl::tk {

namespace {

// The same choice render_to_vfb makes, made before the thread starts.
scene read_renderable(const std::filesystem::path& file, const registry& types) {
    if (file.extension() != ".ray_trace")
        throw file_error(file.string() + ": cannot render a '" + file.extension().string() +
                         "' file: render knows .ray_trace (ray trace)");
    return read_scene(file, types);
}

}  // namespace

render_job::render_job(const registry& pieces, const std::filesystem::path& file, int width, int height,
                       std::string_view storage)
    : file_(file),
      types_(pieces),
      scene_(read_renderable(file, types_)),
      pixels_(width - 1, height - 1, storage),
      thread_([this] { run(); }) {}

render_job::~render_job() { cancel(); }

void render_job::run() {
    render_options options;
    options.progress = false;
    options.cancel = &cancel_;
    options.on_tile = [this](int x0, int y0, int x1, int y1) {
        pixels_done_ += static_cast<long long>(x1 - x0) * (y1 - y0);
        const std::lock_guard lock(mutex_);
        finished_tiles_.push_back({x0, y0, x1, y1});
    };
    try {
        stats_ = render(scene_, types_, pixels_, options);
    } catch (const std::exception& e) {
        error_ = e.what();
    }
    done_ = true;
}

void render_job::cancel() {
    cancel_ = true;
    if (thread_.joinable()) thread_.join();
}

bool render_job::finished() {
    if (!done_) return false;
    if (thread_.joinable()) thread_.join();
    return true;
}

std::vector<rect> render_job::take_finished_tiles() {
    const std::lock_guard lock(mutex_);
    return std::exchange(finished_tiles_, {});
}

double render_job::fraction() const {
    const double total = static_cast<double>(pixels_.width()) * pixels_.height();
    return static_cast<double>(pixels_done_.load()) / total;
}

}  // namespace vl::tk
