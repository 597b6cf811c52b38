// rt: render a scene file to an image, without a window.
//
//   rt SCENE -o OUT.png [--size WxH] [--spp N] [--sampler NAME] [--threads N] [--seed N]
//      [--heatmap HEAT.png] [--stats]
//
// The command line and the render; the pieces come from the caller (rt_main.hh).
#include "rt_main.hh"

#include <malloc.h>

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <iostream>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "command_line.hh"
#include "vl/error.hh"
#include "vl/heat_map.hh"
#include "vl/image_io.hh"
#include "vl/render.hh"
#include "vl/scene.hh"

namespace {

using vl::apps::command_line_error;
using vl::apps::listing;
using vl::apps::to_int;

/// rt --help: the sample patterns are those registered in this build.
std::string usage(const vl::registry& pieces) {
    return "usage: rt SCENE -o OUT [--size WxH] [--spp N] [--sampler NAME] [--threads N] [--seed N]\n"
           "          [--heatmap HEAT.png] [--stats]\n"
           "  SCENE            a .ray_trace file (docs/scene-format.md)\n"
           "  -o OUT           the image to write: .png, .ppm or .pgm (8-bit sRGB), .pfm (linear float)\n"
           "  --size WxH       image size in pixels (default: the scene's size)\n"
           "  --spp N          samples per pixel (default: the scene's samples)\n"
           "  --sampler NAME   one of " + listing(pieces.sampler_names()) + " (default: the scene's sampler)\n"
           "  --threads N      worker threads (default: one per core)\n"
           "  --seed N         another seed for the random samplers: other samples, same image in the limit\n"
           "                   (default 0)\n"
           "  --heatmap FILE   also write the intersection heat map, with its colour scale\n"
           "  --stats          print rays, tests per ray, time and memory\n";
}

struct options {
    std::string scene, output, heatmap, sampler;
    std::optional<std::pair<int, int>> size;
    std::optional<int> spp;
    int threads = 0;
    std::uint64_t seed = 0;
    bool stats = false;
};

options parse(int argc, char** argv, const vl::registry& pieces) {
    options o;
    for (int k = 1; k < argc; ++k) {
        const std::string_view a = argv[k];
        auto value = [&]() -> std::string_view {
            if (k + 1 >= argc) throw command_line_error{std::string(a) + " needs a value"};
            return argv[++k];
        };
        if (a == "-h" || a == "--help") {
            std::cout << usage(pieces);
            std::exit(0);
        } else if (a == "-o") {
            o.output = value();
        } else if (a == "--heatmap") {
            o.heatmap = value();
        } else if (a == "--sampler") {
            o.sampler = value();
        } else if (a == "--spp") {
            o.spp = to_int(a, value(), 1, 4096);
        } else if (a == "--threads") {
            o.threads = to_int(a, value(), 1, 1024);
        } else if (a == "--seed") {
            o.seed = static_cast<std::uint64_t>(to_int(a, value(), 0, 1 << 30));
        } else if (a == "--stats") {
            o.stats = true;
        } else if (a == "--size") {
            o.size = vl::apps::to_size(value(), "640x480");
        } else if (!a.empty() && a[0] == '-') {
            throw command_line_error{"unknown option '" + std::string(a) + "'"};
        } else if (o.scene.empty()) {
            o.scene = a;
        } else {
            throw command_line_error{"one scene at a time: '" + o.scene + "' and '" + std::string(a) + "'"};
        }
    }
    if (o.scene.empty()) throw command_line_error{"no scene file given"};
    if (o.output.empty()) throw command_line_error{"no output image given (-o OUT.png)"};
    return o;
}

/// Bytes allocated with malloc and new, including the large blocks malloc maps on their own.
std::size_t heap_in_use() {
    const struct mallinfo2 m = mallinfo2();
    return m.uordblks + m.hblkhd;
}

}  // namespace

int vl::rt_main(int argc, char** argv, const registry& types) {
    try {
        const options opt = parse(argc, argv, types);

        const std::size_t heap_before = heap_in_use();
        vl::scene s = vl::read_scene(opt.scene, types);
        const std::size_t scene_bytes = heap_in_use() - heap_before;
        if (opt.size) std::tie(s.width, s.height) = *opt.size;
        if (opt.spp) s.samples_per_pixel = *opt.spp;
        if (!opt.sampler.empty()) {
            const std::vector<std::string> samplers = types.sampler_names();
            if (std::find(samplers.begin(), samplers.end(), opt.sampler) == samplers.end())
                throw command_line_error{"--sampler: sampler '" + opt.sampler + "' is not registered in this build (" +
                                  listing(samplers) + ")"};
            s.sampler = opt.sampler;
        }

        // Model no more than the scene needs: 8-bit sRGB for 8-bit files, float for PFM.
        const bool linear = std::filesystem::path(opt.output).extension() == ".pfm";
        vl::vfb image(s.width - 1, s.height - 1, linear ? "rgbf" : "rgb8");
        vl::render_options ro;
        ro.threads = opt.threads;
        ro.seed = opt.seed;
        const std::size_t heap_at_render = heap_in_use();
        const vl::render_stats st = vl::render(s, types, image, ro);
        // What the render left allocated beyond its statistics: what the scene built on
        // its first ray (a BVH's tree).
        const std::size_t grown = heap_in_use() - heap_at_render;
        const std::size_t stats_bytes = st.tests_per_pixel.capacity() * sizeof(st.tests_per_pixel[0]);
        const std::size_t built_bytes = grown - std::min(stats_bytes, grown);
        image.save(opt.output);

        std::uint32_t most = 0;
        if (!opt.heatmap.empty()) {
            vl::vfb heat(s.width + vl::heat_scale_gap + vl::heat_scale_width - 1, s.height - 1, "rgb8");
            most = vl::draw_heat_map(st.tests_per_pixel, s.width, s.height, heat);
            heat.save(opt.heatmap);
        }
        if (opt.stats) {
            const double rays = static_cast<double>(std::max<std::uint64_t>(st.primary_rays, 1));
            std::printf("scene           %s (%d objects at the top level)\n", opt.scene.c_str(),
                        static_cast<int>(s.root->num_children()));
            std::printf("image           %d x %d, %d samples per pixel (%s), %d threads\n", s.width, s.height,
                        s.samples_per_pixel, s.sampler.c_str(), st.threads);
            std::printf("rays            %llu primary\n", static_cast<unsigned long long>(st.primary_rays));
            std::printf("primitive tests %.2f per ray\n", static_cast<double>(st.counts.primitive_tests) / rays);
            std::printf("composite tests %.2f per ray\n", static_cast<double>(st.counts.composite_tests) / rays);
            std::printf("bounding tests  %.2f per ray\n", static_cast<double>(st.counts.bounding_volume_tests) / rays);
            if (!opt.heatmap.empty()) std::printf("heat map        0 (black) to %u (white) tests per pixel\n", most);
            std::printf("time            %.3f s\n", st.seconds);
            std::printf("wrote           %s%s%s\n", opt.output.c_str(), opt.heatmap.empty() ? "" : " and ",
                        opt.heatmap.c_str());
            std::printf("memory          scene model %.1f KiB, %.1f KiB more after rendering (what the first ray built, such as a BVH's tree), frame buffer %.1f KiB (%s, %zu bytes per pixel)\n",
                        static_cast<double>(scene_bytes) / 1024.0, static_cast<double>(built_bytes) / 1024.0,
                        static_cast<double>(image.bytes_per_pixel()) * s.width * s.height / 1024.0, std::string(image.storage_name()).c_str(),
                        image.bytes_per_pixel());
        }
        return 0;
    } catch (const command_line_error& e) {
        std::fprintf(stderr, "rt: %s (rt --help shows the options)\n", e.message.c_str());
    } catch (const std::exception& e) {
        std::fprintf(stderr, "rt: %s\n", e.what());
    }
    return 1;
}
