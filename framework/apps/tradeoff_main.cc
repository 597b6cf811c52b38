// tradeoff: speed against accuracy, as charts (tradeoff_main.hh; `tradeoff --help`).
#include "tradeoff_main.hh"

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <string_view>
#include <tuple>
#include <vector>

#include "vl/chart.hh"
#include "command_line.hh"
#include "vl/error.hh"
#include "vl/flip.hh"
#include "vl/image_io.hh"
#include "vl/render.hh"
#include "vl/rt_base_objects.hh"
#include "vl/scene.hh"
#include "vl/scene_reader.hh"
#include "vl/stats.hh"
#include "vl/vfb.hh"

namespace {

using vl::apps::command_line_error;
using vl::apps::listing;
using vl::apps::to_int;

namespace fs = std::filesystem;

/// Another failure (a file, a scene, a piece): printed as `tradeoff: MESSAGE`, exit status 1.
struct run_error {
    std::string message;
};

std::string usage(const vl::registry& pieces) {
    return "usage: tradeoff SCENE [--out DIR] [--size WxH] [--spp LIST] [--samplers LIST]\n"
           "                [--reference-spp N] [--reference-sampler NAME] [--threads N] [--repeats N] [--against DIR]\n"
           "       tradeoff --structures [--out DIR] [--composites LIST] [--leaf TYPE] [--max-n N]\n"
           "                [--rays N] [--against DIR]\n"
           "\n"
           "SCENE: render at each number of samples per pixel with each sample pattern; each\n"
           "image's mean LDR-FLIP against a converged render, against time, rays and tests.\n"
           "  --out DIR              where the charts go (default tradeoff-out/SCENE_NAME)\n"
           "  --size WxH             image size (default: the scene's; small is quick: 64x48)\n"
           "  --spp LIST             samples per pixel, e.g. 1,4,16 (default 1,2,4,8,16,32,64)\n"
           "  --samplers LIST        the patterns (default all of this build's: " + listing(pieces.sampler_names()) + ")\n"
           "  --reference-spp N      samples per pixel of the converged render (default 1024)\n"
           "  --reference-sampler S  its pattern (default jittered, else the first)\n"
           "  --threads N            worker threads (default one per core)\n"
           "  --repeats N            render each N times and report the fastest time (default 3; the image is the same)\n"
           "--structures: N random spheres in the unit cube (N = 16, 32, ..., --max-n) in each\n"
           "composite; tests per ray against N and against the time to build it.\n"
           "  --composites LIST      composite types (default LIST,BOUNDSPH,BVH, those this build has)\n"
           "  --leaf TYPE            the children's type, read as TYPE { center X Y Z radius R } (default SPHERE)\n"
           "  --max-n N              the largest N (default 16384)\n"
           "  --rays N               rays per structure, through random points of the cube (default 1000)\n"
           "Both:\n"
           "  --against DIR          draw an earlier run's points (DIR/points.tsv) as lines under this run's\n"
           "\n"
           "Writes DIR/points.tsv and each chart as DIR/NAME.tsv, .gp and (with gnuplot) .svg and .png;\n"
           "prints one line per point.\n";
}

std::vector<std::string> split(std::string_view text) {
    std::vector<std::string> out;
    std::string item;
    for (const char c : text) {
        if (c == ',') {
            if (!item.empty()) out.push_back(item);
            item.clear();
        } else {
            item += c;
        }
    }
    if (!item.empty()) out.push_back(item);
    return out;
}

struct options {
    bool structures = false;
    std::string scene, out, against, reference_sampler, leaf = "SPHERE";
    std::optional<std::pair<int, int>> size;
    std::vector<int> spp{1, 2, 4, 8, 16, 32, 64};
    std::vector<std::string> samplers, composites;
    int reference_spp = 1024, threads = 0, max_n = 16384, rays = 1000, repeats = 3;
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
        } else if (a == "--structures") {
            o.structures = true;
        } else if (a == "--out") {
            o.out = value();
        } else if (a == "--against") {
            o.against = value();
        } else if (a == "--size") {
            o.size = vl::apps::to_size(value(), "64x48");
        } else if (a == "--spp") {
            o.spp.clear();
            for (const std::string& s : split(value())) o.spp.push_back(to_int("--spp", s, 1, 4096));
            if (o.spp.empty()) throw command_line_error{"--spp wants numbers of samples per pixel, like 1,4,16"};
        } else if (a == "--samplers") {
            o.samplers = split(value());
        } else if (a == "--reference-spp") {
            o.reference_spp = to_int(a, value(), 1, 65536);
        } else if (a == "--reference-sampler") {
            o.reference_sampler = value();
        } else if (a == "--repeats") {
            o.repeats = to_int(a, value(), 1, 100);
        } else if (a == "--threads") {
            o.threads = to_int(a, value(), 1, 1024);
        } else if (a == "--composites") {
            o.composites = split(value());
        } else if (a == "--leaf") {
            o.leaf = value();
        } else if (a == "--max-n") {
            o.max_n = to_int(a, value(), 16, 1 << 22);
        } else if (a == "--rays") {
            o.rays = to_int(a, value(), 1, 1000000);
        } else if (!a.empty() && a[0] == '-') {
            throw command_line_error{"unknown option '" + std::string(a) + "'"};
        } else if (o.scene.empty()) {
            o.scene = a;
        } else {
            throw command_line_error{"one scene at a time: '" + o.scene + "' and '" + std::string(a) + "'"};
        }
    }
    if (o.structures && !o.scene.empty())
        throw command_line_error{"--structures makes its own scenes: give no scene file ('" + o.scene + "')"};
    if (!o.structures && o.scene.empty()) throw command_line_error{"no scene file given (or --structures)"};
    if (o.out.empty()) o.out = "tradeoff-out/" + (o.structures ? std::string("structures") : fs::path(o.scene).stem().string());
    return o;
}

/// One measured point: a series (a sampler, a composite type), its parameter (spp, N),
/// what it cost (seconds, rays, tests) and what it gave (FLIP, tests per ray).
struct point_row {
    std::string series;
    double parameter = 0, seconds = 0, rays = 0, tests = 0, value = 0;
};

const char* kind_line(bool structures) {
    return structures ? "# tradeoff --structures: series\tN\tbuild_seconds\trays\ttests\ttests_per_ray"
                      : "# tradeoff SCENE: series\tspp\tseconds\trays\ttests\tflip_mean";
}

void write_points(const fs::path& file, bool structures, const std::vector<point_row>& rows) {
    std::ofstream out(file);
    out.precision(10);
    out << kind_line(structures) << "\n";
    for (const point_row& r : rows)
        out << r.series << "\t" << r.parameter << "\t" << r.seconds << "\t" << r.rays << "\t" << r.tests << "\t" << r.value
            << "\n";
    if (!out) throw run_error{"cannot write " + file.string() + " (choose another --out)"};
}

std::vector<point_row> read_points(const fs::path& dir, bool structures) {
    const fs::path file = dir / "points.tsv";
    std::ifstream in(file);
    if (!in)
        throw run_error{"--against: cannot read " + file.string() + " (give the --out folder of an earlier tradeoff run)"};
    std::string line;
    std::getline(in, line);
    if (line != kind_line(structures))
        throw run_error{"--against: " + file.string() + " holds the points of a " +
                        (line == kind_line(!structures) ? std::string(structures ? "SCENE" : "--structures") + " run"
                                                        : std::string("file that tradeoff did not write")) +
                        ", not of a " + (structures ? "--structures" : "SCENE") + " run like this one"};
    std::vector<point_row> rows;
    int number = 1;
    while (std::getline(in, line)) {
        ++number;
        if (line.empty()) continue;
        std::istringstream s(line);
        point_row r;
        if (!std::getline(s, r.series, '\t') || !(s >> r.parameter >> r.seconds >> r.rays >> r.tests >> r.value))
            throw run_error{"--against: " + file.string() + ":" + std::to_string(number) +
                            ": not a line of points (series, then five numbers, tab-separated)"};
        rows.push_back(r);
    }
    return rows;
}

/// A chart of `rows` (x and y chosen by `x`, `y`), this run's series over `against`'s.
vl::chart chart_of(const std::string& title, const std::string& x_label, const std::string& y_label,
                   const std::vector<point_row>& rows, const std::vector<point_row>& against,
                   const std::string& against_name, double point_row::*x, double point_row::*y) {
    vl::chart c;
    c.title = title;
    c.x_label = x_label;
    c.y_label = y_label;
    c.log_x = true;
    c.log_y = true;
    // This run's series wears the colour of the earlier run's series of that name.
    std::map<std::string, int> colour;
    auto add = [&](const std::vector<point_row>& from, const std::string& prefix, vl::chart_series::style look) {
        std::vector<std::string> order;
        std::map<std::string, vl::chart_series> by;
        for (const point_row& r : from) {
            if (!by.contains(r.series)) {
                order.push_back(r.series);
                by[r.series] = {prefix + r.series, {}, look};
            }
            by[r.series].points.push_back({r.*x, r.*y});
        }
        for (const std::string& name : order) {
            if (const auto known = colour.find(name); known != colour.end()) by[name].colour_of = known->second;
            else colour[name] = static_cast<int>(c.series.size());
            c.series.push_back(by[name]);
        }
    };
    if (!against.empty()) add(against, against_name + ": ", vl::chart_series::style::line);
    add(rows, against.empty() ? "" : "this run: ", against.empty() ? vl::chart_series::style::line_and_marks
                                                                   : vl::chart_series::style::marks);
    if (c.series.size() > 4) c.height = 520;  // the legend goes under the plot
    return c;
}

/// The image of `s` rendered with `sampler` at `spp`, and what it cost.
struct rendered {
    vl::image picture;
    vl::render_stats stats;
};

rendered render_with(vl::scene& s, const vl::registry& pieces, const std::string& sampler, int spp, int threads) {
    s.sampler = sampler;
    s.samples_per_pixel = spp;
    vl::vfb image(s.width - 1, s.height - 1, "rgbf");
    vl::render_options ro;
    ro.threads = threads;
    ro.progress = false;
    rendered r;
    r.stats = vl::render(s, pieces, image, ro);
    r.picture = image.to_image(vl::sample_type::f32);
    return r;
}

std::vector<point_row> sampler_sweep(const options& o, const vl::registry& pieces, const fs::path& out) {
    vl::scene s = vl::read_scene(o.scene, pieces);
    if (o.size) std::tie(s.width, s.height) = *o.size;
    const std::vector<std::string> known = pieces.sampler_names();
    auto check = [&](const std::string& name, const char* flag) {
        if (std::find(known.begin(), known.end(), name) == known.end())
            throw command_line_error{std::string(flag) + ": sampler '" + name + "' is not registered in this build (" +
                                     listing(known) + ")"};
    };
    std::vector<std::string> samplers = o.samplers.empty() ? known : o.samplers;
    for (const std::string& n : samplers) check(n, "--samplers");
    if (samplers.empty()) throw run_error{"this build has no sample patterns (stage 01 registers them)"};
    std::string reference = o.reference_sampler;
    if (reference.empty())
        reference = std::find(known.begin(), known.end(), "jittered") != known.end() ? "jittered" : known.front();
    check(reference, "--reference-sampler");

    std::printf("converged render: %s at %d samples per pixel, %d x %d\n", reference.c_str(), o.reference_spp, s.width,
                s.height);
    std::fflush(stdout);
    rendered converged;
    try {
        converged = render_with(s, pieces, reference, o.reference_spp, o.threads);
    } catch (const std::exception& e) {
        throw run_error{"the converged render (sampler '" + reference + "', --reference-sampler) failed: " + e.what() +
                        " (write that pattern first, or choose another with --reference-sampler)"};
    }
    vl::write_image(out / "converged.png", converged.picture);

    std::vector<point_row> rows;
    std::string last_problem;
    for (const std::string& name : samplers)
        for (const int spp : o.spp) try {
            rendered r = render_with(s, pieces, name, spp, o.threads);
            // The same image every time (seeds are fixed per pixel): only the time varies.
            for (int again = 1; again < o.repeats; ++again)
                r.stats.seconds = std::min(r.stats.seconds, render_with(s, pieces, name, spp, o.threads).stats.seconds);
            point_row p{name, static_cast<double>(spp), r.stats.seconds, static_cast<double>(r.stats.primary_rays),
                        static_cast<double>(r.stats.counts.total_tests()), vl::flip(converged.picture, r.picture).mean};
            std::printf("sampler=%s spp=%d seconds=%.6f rays=%.0f tests=%.0f flip_mean=%.6f\n", name.c_str(), spp,
                        p.seconds, p.rays, p.tests, p.value);
            std::fflush(stdout);
            rows.push_back(p);
        } catch (const std::exception& e) {
            // A pattern that cannot render (a stub not written yet) is left out; the rest go on.
            last_problem = "sampler '" + name + "' at " + std::to_string(spp) + " samples per pixel: " + e.what();
            std::fprintf(stderr, "tradeoff: left out %s\n", last_problem.c_str());
            break;
        }
    if (rows.empty()) throw run_error{"nothing could be measured; the last problem: " + last_problem};
    return rows;
}

std::vector<point_row> structure_sweep(const options& o, const vl::registry& pieces) {
    std::vector<std::string> composites = o.composites;
    if (composites.empty()) {
        // The composites of the stages, as scene files name them; those this build lacks are left out.
        for (const char* name : {"LIST", "BOUNDSPH", "BVH"})
            if (pieces.contains(name)) composites.push_back(name);
    }
    for (const std::string& name : composites) {
        if (!pieces.contains(name))
            throw command_line_error{"--composites: type '" + name + "' is not registered in this build (" +
                                     listing(pieces.names()) + ")"};
        if (!dynamic_cast<vl::rtab_composite*>(pieces.create(name).get()))
            throw command_line_error{"--composites: type '" + name + "' is not a composite (it cannot hold children)"};
    }
    if (!pieces.contains(o.leaf))
        throw command_line_error{"--leaf: type '" + o.leaf + "' is not registered in this build (" +
                                 listing(pieces.names()) + ")"};
    // Rays from a sphere of radius 2.5 around the cube's centre through random points of it.
    std::mt19937_64 random(20261202);
    std::uniform_real_distribution<double> unit(0, 1);
    std::vector<vl::ray> rays;
    for (int k = 0; k < o.rays; ++k) {
        const double z = 2 * unit(random) - 1, phi = 2 * 3.141592653589793 * unit(random), r = std::sqrt(1 - z * z);
        const vl::point from(0.5 + 2.5 * r * std::cos(phi), 0.5 + 2.5 * r * std::sin(phi), 0.5 + 2.5 * z);
        const vl::point to(unit(random), unit(random), unit(random));
        rays.emplace_back(from, to - from);
    }
    std::vector<point_row> rows;
    std::set<std::string> left_out;
    std::string last_problem;
    for (int n = 16; n <= o.max_n; n *= 2) {
        // N spheres at random in the unit cube, radius 0.15 of their mean spacing.
        std::ostringstream text;
        text.precision(17);
        std::mt19937_64 place(static_cast<std::uint64_t>(n));
        const double radius = 0.15 / std::cbrt(static_cast<double>(n));
        for (int k = 0; k < n; ++k)
            text << o.leaf << " { center " << unit(place) << " " << unit(place) << " " << unit(place) << " radius "
                 << radius << " }\n";
        for (const std::string& name : composites) try {
            if (left_out.contains(name)) continue;
            // Built: every insert() and the first ray (a BVH may build its tree then); the
            // fastest of three builds, since other programs on the machine slow some down.
            std::unique_ptr<vl::rtab_component> made;
            double build = HUGE_VAL;
            for (int attempt = 0; attempt < 3; ++attempt) {
                vl::scene_reader reader(pieces);
                reader.open_text(text.str(), "(" + std::to_string(n) + " random " + o.leaf + ")");
                std::vector<std::unique_ptr<vl::rtab_component>> children;
                while (!reader.at_end()) children.push_back(reader.read_object());
                made = pieces.create(name);
                auto* fresh = dynamic_cast<vl::rtab_composite*>(made.get());
                const auto start = std::chrono::steady_clock::now();
                for (auto& c : children) fresh->insert(std::move(c));
                (void)fresh->intersect(rays.front());
                build = std::min(build, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
            }
            const auto* composite = dynamic_cast<const vl::rtab_composite*>(made.get());
            const vl::intersection_counts before = vl::counts();
            for (const vl::ray& r : rays) (void)composite->intersect(r);
            const double tests = static_cast<double>((vl::counts() - before).total_tests());
            point_row p{name, static_cast<double>(n), build, static_cast<double>(rays.size()), tests,
                        tests / static_cast<double>(rays.size())};
            std::printf("structure=%s n=%d build_seconds=%.6f rays=%.0f tests=%.0f tests_per_ray=%.4f\n", name.c_str(), n,
                        p.seconds, p.rays, p.tests, p.value);
            std::fflush(stdout);
            rows.push_back(p);
        } catch (const std::exception& e) {
            // A composite that cannot be built (a stub not written yet) is left out; the rest go on.
            last_problem = name + " of " + std::to_string(n) + " " + o.leaf + ": " + e.what();
            std::fprintf(stderr, "tradeoff: left out %s\n", last_problem.c_str());
            left_out.insert(name);
        }
    }
    if (rows.empty()) throw run_error{"nothing could be measured; the last problem: " + last_problem};
    return rows;
}

}  // namespace

int vl::tradeoff_main(int argc, char** argv, const registry& pieces) {
    try {
        const options o = parse(argc, argv, pieces);
        const fs::path out = o.out;
        std::error_code ec;
        fs::create_directories(out, ec);
        if (ec) throw run_error{"cannot make the folder " + out.string() + ": " + ec.message() + " (choose another --out)"};
        const std::vector<point_row> against = o.against.empty() ? std::vector<point_row>{} : ::read_points(o.against, o.structures);
        const std::string against_name = o.against.empty() ? "" : fs::path(o.against).lexically_normal().filename().string();

        std::vector<point_row> rows = o.structures ? structure_sweep(o, pieces) : sampler_sweep(o, pieces, out);
        write_points(out / "points.tsv", o.structures, rows);
        std::vector<std::pair<std::string, vl::chart>> charts;
        if (o.structures) {
            charts.push_back({"tests-per-ray-vs-n",
                              chart_of("Tests per ray against N random spheres, per structure", "N (spheres in the unit cube)",
                                       "tests per ray (intersect() calls and bound tests)", rows, against, against_name,
                                       &point_row::parameter, &point_row::value)});
            charts.push_back({"tests-per-ray-vs-build-time",
                              chart_of("Tests per ray against the time to build, per structure (N = 16 to " +
                                           std::to_string(o.max_n) + ")",
                                       "seconds to build (every insert() and the first ray; the fastest of 3)",
                                       "tests per ray (intersect() calls and bound tests)", rows, against, against_name,
                                       &point_row::seconds, &point_row::value)});
        } else {
            const std::string scene = fs::path(o.scene).filename().string();
            const std::string y = "mean LDR-FLIP against the converged render";
            charts.push_back({"flip-vs-time", chart_of("Speed against accuracy: " + scene + ", time", "seconds to render (the fastest of --repeats)", y,
                                                       rows, against, against_name, &point_row::seconds, &point_row::value)});
            charts.push_back({"flip-vs-rays", chart_of("Speed against accuracy: " + scene + ", rays traced", "rays traced", y,
                                                       rows, against, against_name, &point_row::rays, &point_row::value)});
            charts.push_back({"flip-vs-tests",
                              chart_of("Speed against accuracy: " + scene + ", intersection tests",
                                       "intersection tests (intersect() calls and bound tests)", y, rows, against,
                                       against_name, &point_row::tests, &point_row::value)});
        }
        std::string problem;
        for (const auto& [name, c] : charts) {
            const vl::chart_files f = vl::draw_chart(c, out / name);
            std::printf("wrote %s%s\n", (out / name).string().c_str(), f.svg.empty() ? ".tsv and .gp" : ".tsv, .gp, .svg and .png");
            if (!f.problem.empty()) problem = f.problem;
        }
        std::printf("wrote %s\n", (out / "points.tsv").string().c_str());
        if (!problem.empty()) std::fprintf(stderr, "tradeoff: no SVG or PNG: %s\n", problem.c_str());
        return 0;
    } catch (const command_line_error& e) {
        std::fprintf(stderr, "tradeoff: %s (tradeoff --help shows the options)\n", e.message.c_str());
        return 2;
    } catch (const run_error& e) {
        std::fprintf(stderr, "tradeoff: %s\n", e.message.c_str());
    } catch (const std::exception& e) {
        std::fprintf(stderr, "tradeoff: %s\n", e.what());
    }
    return 1;
}
