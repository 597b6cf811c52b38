// Tests of the tradeoff program (framework/apps/tradeoff_main.cc) with every piece this
// build links: on a tiny scene it writes its files and prints one line per point, and
// the jittered pattern's FLIP falls as samples per pixel grow. No timings are checked:
// only counts (rays, tests), which are the same on every machine.
#include "vl/catch.hh"

#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "../framework/tests/support/run_program.hh"
#include "../framework/tests/support/temp_dir.hh"
#include "vl/chart.hh"

namespace {

using vl::test::run_result;

run_result run_tradeoff(const std::string& args) { return vl::test::run_program(VL_TRADEOFF_PATH, args); }

/// The lines of `text` that start with `prefix`, each as its key=value fields.
std::vector<std::map<std::string, std::string>> point_lines(const std::string& text, const std::string& prefix) {
    std::vector<std::map<std::string, std::string>> out;
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) {
        if (!line.starts_with(prefix)) continue;
        std::map<std::string, std::string> fields;
        std::istringstream words(line);
        std::string w;
        while (words >> w) {
            const auto eq = w.find('=');
            if (eq != std::string::npos) fields[w.substr(0, eq)] = w.substr(eq + 1);
        }
        out.push_back(fields);
    }
    return out;
}

const char* const tiny_scene = R"(camera { eye 0 1.5 6  look_at 0 0.6 0  up 0 1 0  fov 40 }
size 32 24
tracer normals
background 0.05 0.05 0.1
SPHERE { center 0 -1000 0  radius 1000 }
SPHERE { center -1.3 0.6 0  radius 0.6 }
SPHERE { center 0 0.8 -0.6  radius 0.8 }
SPHERE { center 1.3 0.5 0.3  radius 0.5 }
)";

}  // namespace

TEST_CASE("tradeoff SCENE writes points and charts, one line per point, and jittered's FLIP falls with spp", "[tradeoff]") {
    vl::test::temp_dir dir;
    const auto scene = dir.write("tiny.ray_trace", tiny_scene);
    const auto out = dir.path() / "out";
    const run_result r = run_tradeoff(scene.string() + " --out " + out.string() +
                                      " --spp 1,4,16,64 --samplers jittered,center --reference-spp 256 --threads 2");
    INFO(r.output);
    REQUIRE(r.status == 0);
    const auto lines = point_lines(r.output, "sampler=");
    REQUIRE(lines.size() == 8);
    std::vector<double> jittered;
    for (const auto& l : lines) {
        // Rays are pixels times samples: machine-independent.
        CHECK(std::stod(l.at("rays")) == 32.0 * 24 * std::stod(l.at("spp")));
        CHECK(std::stod(l.at("tests")) >= std::stod(l.at("rays")));
        if (l.at("sampler") == "jittered") jittered.push_back(std::stod(l.at("flip_mean")));
    }
    REQUIRE(jittered.size() == 4);
    for (std::size_t k = 1; k < jittered.size(); ++k) CHECK(jittered[k] < jittered[k - 1]);
    CHECK(jittered.back() < jittered.front() / 2);
    for (const char* f : {"points.tsv", "converged.png", "flip-vs-time.tsv", "flip-vs-time.gp", "flip-vs-rays.tsv",
                          "flip-vs-rays.gp", "flip-vs-tests.tsv", "flip-vs-tests.gp"})
        CHECK(std::filesystem::exists(out / f));
    if (vl::gnuplot_available())
        for (const char* f : {"flip-vs-time.svg", "flip-vs-time.png", "flip-vs-rays.svg", "flip-vs-tests.png"})
            CHECK(std::filesystem::exists(out / f));

    // Against itself: the earlier run's series are drawn as lines, this run's as marks.
    const run_result again = run_tradeoff(scene.string() + " --out " + (dir.path() / "again").string() + " --against " +
                                          out.string() + " --spp 1,4 --samplers jittered --reference-spp 64");
    INFO(again.output);
    REQUIRE(again.status == 0);
    std::ifstream tsv(dir.path() / "again" / "flip-vs-rays.tsv");
    const std::string text{std::istreambuf_iterator<char>(tsv), {}};
    CHECK(text.find("out: jittered") != std::string::npos);
    CHECK(text.find("this run: jittered") != std::string::npos);
}

TEST_CASE("tradeoff --structures: tests per ray for each composite and N, a LIST's being N + 1", "[tradeoff]") {
    vl::test::temp_dir dir;
    const auto out = dir.path() / "structures";
    const run_result r = run_tradeoff("--structures --composites LIST --max-n 64 --rays 50 --out " + out.string());
    INFO(r.output);
    REQUIRE(r.status == 0);
    const auto lines = point_lines(r.output, "structure=");
    REQUIRE(lines.size() == 3);
    for (const auto& l : lines) CHECK(std::stod(l.at("tests_per_ray")) == std::stod(l.at("n")) + 1);
    for (const char* f : {"points.tsv", "tests-per-ray-vs-n.tsv", "tests-per-ray-vs-n.gp", "tests-per-ray-vs-build-time.tsv"})
        CHECK(std::filesystem::exists(out / f));
}

TEST_CASE("tradeoff names the file or the option that is wrong", "[tradeoff]") {
    vl::test::temp_dir dir;
    const run_result missing = run_tradeoff((dir.path() / "nowhere.ray_trace").string() + " --out " + dir.path().string());
    CHECK(missing.status == 1);
    CHECK(missing.output.find("nowhere.ray_trace") != std::string::npos);

    const auto scene = dir.write("tiny.ray_trace", tiny_scene);
    const run_result sampler = run_tradeoff(scene.string() + " --samplers sobol --out " + dir.path().string());
    CHECK(sampler.status == 2);
    CHECK(sampler.output.find("sampler 'sobol' is not registered") != std::string::npos);

    const run_result against = run_tradeoff(scene.string() + " --spp 1 --against " + (dir.path() / "empty").string() +
                                            " --out " + (dir.path() / "o").string());
    CHECK(against.status == 1);
    CHECK(against.output.find("empty/points.tsv") != std::string::npos);

    // A structure that cannot be built is left out with the reason; with none left, exit 1.
    const run_result none = run_tradeoff("--structures --composites LIST --leaf LIST --max-n 16 --out " +
                                         (dir.path() / "s").string());
    CHECK(none.status == 1);
    CHECK(none.output.find("left out LIST of 16 LIST") != std::string::npos);
    CHECK(none.output.find("nothing could be measured") != std::string::npos);

    const run_result both = run_tradeoff("--structures " + scene.string());
    CHECK(both.status == 2);
    CHECK(both.output.find("give no scene file") != std::string::npos);
}
