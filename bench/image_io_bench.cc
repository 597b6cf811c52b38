// Saving and loading a frame buffer, against ImageMagick doing the same conversions.
//
// For each size (875 x 700, the thesis's screen-sized render, and 4096 x 4096) and each
// format (PPM, PNG):
//   save     vl::vfb::save     (8-bit RGB storage, the default) to a file
//   load     vl::vfb::load     the same file back
//   convert  `convert in out`  ImageMagick reading that file and writing it again
// Files go to /dev/shm (memory) when it exists, so the disk does not decide the result.
// After the table, the ratios: convert's time over our save + load (goal for PPM: 10x or
// more) and our PPM write speed (goal: 1 GB/s or more).
#include <benchmark/benchmark.h>

#include "vl/vfb.hh"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <string>
#include <unistd.h>

namespace {

namespace fs = std::filesystem;

fs::path scratch() {
    static const fs::path dir = [] {
        const fs::path base = fs::exists("/dev/shm") ? fs::path("/dev/shm") : fs::temp_directory_path();
        const fs::path d = base / ("vl_image_bench_" + std::to_string(::getpid()));
        fs::create_directories(d);
        return d;
    }();
    return dir;
}

// A smooth picture with some detail, so that PNG compresses it as it would a render.
vl::vfb make_picture(vl::vfb_int max_x, vl::vfb_int max_y) {
    vl::vfb v(max_x, max_y);
    for (vl::vfb_int y = 0; y <= max_y; ++y)
        for (vl::vfb_int x = 0; x <= max_x; ++x) {
            const double u = x / double(max_x), w = y / double(max_y);
            v.put_pixel(x, y, vl::vfb_pixel(u, w, 0.5 + 0.5 * std::sin(20 * u * w)));
        }
    return v;
}

// Index 0 is 875 x 700, index 1 is 4096 x 4096; each is made once, on first use.
const vl::vfb& picture(int size_index) {
    static const vl::vfb small = make_picture(874, 699);
    if (size_index == 0) return small;
    static const vl::vfb large = make_picture(4095, 4095);
    return large;
}

const char* size_name(int i) { return i == 0 ? "875x700" : "4096x4096"; }

fs::path file(int size_index, const char* ext) { return scratch() / (std::string("vl_") + size_name(size_index) + ext); }

void save(benchmark::State& state, const char* ext) {
    const int i = static_cast<int>(state.range(0));
    const vl::vfb& v = picture(i);
    for (auto _ : state) v.save(file(i, ext));
    state.SetBytesProcessed(state.iterations() * std::int64_t{v.width()} * v.height() * 3);
    state.SetLabel(size_name(i));
}

void load(benchmark::State& state, const char* ext) {
    const int i = static_cast<int>(state.range(0));
    const vl::vfb& original = picture(i);
    original.save(file(i, ext));
    vl::vfb v(original.max_x(), original.max_y());
    for (auto _ : state) v.load(file(i, ext));
    state.SetBytesProcessed(state.iterations() * std::int64_t{v.width()} * v.height() * 3);
    state.SetLabel(size_name(i));
}

// ImageMagick's convert reading our file and writing it again, as a separate process (how
// students would use it). /usr/bin/convert directly if it is there, to skip any wrapper.
void convert(benchmark::State& state, const char* ext) {
    const int i = static_cast<int>(state.range(0));
    picture(i).save(file(i, ext));
    const std::string program = fs::exists("/usr/bin/convert") ? "/usr/bin/convert" : "convert";
    const std::string command = program + " '" + file(i, ext).string() + "' '" +
                                (scratch() / (std::string("im_") + size_name(i) + ext)).string() + "'";
    if (std::system((program + " -version >/dev/null 2>&1").c_str()) != 0) {
        state.SkipWithError("ImageMagick's convert is not installed");
        return;
    }
    for (auto _ : state)
        if (std::system(command.c_str()) != 0) state.SkipWithError("convert failed");
    state.SetLabel(size_name(i));
}

BENCHMARK_CAPTURE(save, ppm, ".ppm")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(load, ppm, ".ppm")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(convert, ppm, ".ppm")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(save, png, ".png")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(load, png, ".png")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(convert, png, ".png")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

// Remembers each run's real time per iteration, in seconds, for the ratios.
class recording_reporter : public benchmark::ConsoleReporter {
public:
    void ReportRuns(const std::vector<Run>& runs) override {
        for (const auto& r : runs)
            if (!r.error_occurred) seconds[r.benchmark_name()] = r.GetAdjustedRealTime() / 1e3;  // ms -> s
        ConsoleReporter::ReportRuns(runs);
    }
    std::map<std::string, double> seconds;
};

}  // namespace

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    recording_reporter reporter;
    benchmark::RunSpecifiedBenchmarks(&reporter);

    std::printf("\n%-10s %-10s %12s %12s %12s %10s\n", "format", "size", "save+load", "convert", "ratio", "write");
    for (const char* fmt : {"ppm", "png"})
        for (const char* arg : {"0", "1"}) {
            const std::string suffix = std::string(fmt) + "/" + arg + "/real_time";
            const auto get = [&](const char* what) {
                const auto it = reporter.seconds.find(std::string(what) + "/" + suffix);
                return it == reporter.seconds.end() ? -1.0 : it->second;
            };
            const double s = get("save"), l = get("load"), c = get("convert");
            if (s < 0 || l < 0) continue;
            const double pixels = arg[0] == '0' ? 875.0 * 700 : 4096.0 * 4096;
            std::printf("%-10s %-10s %10.2f ms %10.2f ms %11.1fx %7.2f GB/s\n", fmt, arg[0] == '0' ? "875x700" : "4096x4096",
                        (s + l) * 1e3, c * 1e3, c > 0 ? c / (s + l) : 0.0, pixels * 3 / s / 1e9);
        }
    std::error_code ec;
    fs::remove_all(scratch(), ec);
    benchmark::Shutdown();
}
