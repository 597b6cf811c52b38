// Tests of the rt program and the render driver it runs, with every piece this build links
// (labelled framework: they test the framework's rt_main and render driver).
#include "vl/catch.hh"

#include <cstdio>
#include <fstream>
#include <sstream>

#include "../framework/tests/support/run_program.hh"
#include "../framework/tests/support/temp_dir.hh"
#include "all_pieces.hh"
#include "image_compare.hh"
#include "vl/heat_map.hh"
#include "vl/image_io.hh"
#include "vl/render.hh"

using namespace vl;

namespace {

using vl::test::run_result;

run_result run_rt(const std::string& args) { return vl::test::run_program(VL_RT_PATH, args); }

std::string file_bytes(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

}  // namespace

TEST_CASE("rt: renders the sample scene to a PNG of the requested size", "[rt]") {
    test::temp_dir dir;
    const auto out = dir.path() / "sample.png";
    const run_result r = run_rt("scenes/sample.ray_trace -o " + out.string() + " --size 80x60 --spp 1");
    INFO(r.output);
    REQUIRE(r.status == 0);
    const image img = read_image(out);
    CHECK(img.width() == 80);
    CHECK(img.height() == 60);
    // ImageMagick reads it too, with the same size (tools/setup installs it).
    if (std::system("command -v identify >/dev/null 2>&1") == 0) {
        FILE* pipe = popen(("identify -format '%w %h %m' " + out.string()).c_str(), "r");
        REQUIRE(pipe);
        char text[64] = {};
        const std::size_t n = std::fread(text, 1, sizeof text - 1, pipe);
        pclose(pipe);
        CHECK(std::string(text, n) == "80 60 PNG");
    }
}

TEST_CASE("rt: writes a heat map with its colour scale along the right edge", "[rt]") {
    test::temp_dir dir;
    const auto heat = dir.path() / "heat.png";
    const run_result r = run_rt("scenes/sample.ray_trace -o " + (dir.path() / "a.png").string() +
                                " --size 40x30 --heatmap " + heat.string() + " --stats");
    INFO(r.output);
    REQUIRE(r.status == 0);
    const image img = read_image(heat);
    CHECK(img.width() == 40 + heat_scale_gap + heat_scale_width);
    CHECK(img.height() == 30);
    CHECK(r.output.find("primitive tests") != std::string::npos);
    CHECK(r.output.find("memory") != std::string::npos);
}

TEST_CASE("rt: 1 and 2 threads give identical bytes", "[rt]") {
    test::temp_dir dir;
    const auto one = dir.path() / "one.ppm", two = dir.path() / "two.ppm";
    REQUIRE(run_rt("scenes/sample.ray_trace -o " + one.string() + " --size 64x48 --spp 4 --threads 1").status == 0);
    REQUIRE(run_rt("scenes/sample.ray_trace -o " + two.string() + " --size 64x48 --spp 4 --threads 2").status == 0);
    CHECK(file_bytes(one) == file_bytes(two));
    CHECK(file_bytes(one).size() > 64 * 48 * 3);
}

TEST_CASE("rt: a malformed scene prints FILE:LINE:COL and exits non-zero", "[rt]") {
    test::temp_dir dir;
    const auto bad = dir.write("bad.ray_trace", "size 10 10\nSPHERE { radius -1 }\n");
    const run_result r = run_rt(bad.string() + " -o " + (dir.path() / "x.png").string());
    CHECK(r.status != 0);
    CHECK_THAT(r.output, Catch::Contains("bad.ray_trace:2:17: radius of SPHERE must be greater than 0, found -1"));
    CHECK(std::count(r.output.begin(), r.output.end(), '\n') == 1);  // one clear line
}

TEST_CASE("rt: a tracer the build does not register is a FILE:LINE:COL error listing those it does", "[rt]") {
    test::temp_dir dir;
    const auto scene = dir.write("t.ray_trace", "size 8 8\ntracer phong\nSPHERE { }\n");
    const run_result r = run_rt(scene.string() + " -o " + (dir.path() / "x.png").string());
    CHECK(r.status != 0);
    CHECK_THAT(r.output, Catch::Contains("t.ray_trace:2:8: tracer 'phong' is not registered in this build; choose one of: ") &&
                             Catch::Contains("flat, normals, sky"));
}

TEST_CASE("rt: bad flags and unwritable outputs are one clear line and a non-zero exit", "[rt]") {
    CHECK_THAT(run_rt("scenes/sample.ray_trace").output, Catch::Contains("rt: no output image given"));
    CHECK(run_rt("scenes/sample.ray_trace").status != 0);
    CHECK_THAT(run_rt("scenes/sample.ray_trace -o x.png --spp zero").output,
               Catch::Contains("--spp wants a whole number from 1 to 4096, not 'zero'"));
    CHECK_THAT(run_rt("scenes/sample.ray_trace -o x.png --bogus").output, Catch::Contains("unknown option '--bogus'"));
    CHECK_THAT(run_rt("scenes/sample.ray_trace -o x.png --size 10by10").output, Catch::Contains("--size wants WIDTHxHEIGHT"));
    // Sample patterns are checked against the registry: the message lists this build's.
    const std::string sampler = run_rt("scenes/sample.ray_trace -o x.png --sampler bogus").output;
    CHECK_THAT(sampler, Catch::Contains("rt: --sampler: sampler 'bogus' is not registered in this build (") &&
                            Catch::Contains("jittered"));
    const run_result r = run_rt("scenes/sample.ray_trace -o /nonexistent-dir/out.png --size 8x8");
    CHECK(r.status != 0);
    CHECK_THAT(r.output, Catch::Contains("/nonexistent-dir/out.png"));
}

TEST_CASE("render: counts every test per pixel and in total", "[rt][render]") {
    registry types;
    register_all_pieces(types);
    const scene s = parse_scene("size 8 6\nSPHERE { }\nSPHERE { center 3 0 0 }\nSPHERE { center -3 0 0 }", "t", types);
    vfb out(7, 5, "rgbf");
    render_options o;
    o.threads = 2;
    o.progress = false;
    const render_stats st = render(s, types, out, o);
    CHECK(st.primary_rays == 48);
    // One LIST test and three sphere tests per ray: the root list has no bound.
    CHECK(st.counts.composite_tests == 48);
    CHECK(st.counts.primitive_tests == 3 * 48);
    std::uint64_t sum = 0;
    for (const auto t : st.tests_per_pixel) {
        CHECK(t == 4);
        sum += t;
    }
    CHECK(sum == st.counts.total_tests());
}

TEST_CASE("render: cancelling stops the workers and says so", "[rt][render]") {
    registry types;
    register_all_pieces(types);
    const scene s = parse_scene("size 64 64\nSPHERE { }", "t", types);
    vfb out(63, 63, "rgb8");
    const std::atomic<bool> cancel{true};
    render_options o;
    o.cancel = &cancel;
    o.progress = false;
    const render_stats st = render(s, types, out, o);
    CHECK(st.cancelled);
    CHECK(st.primary_rays == 0);
}

TEST_CASE("render_to_vfb: picks the ray tracer by the .ray_trace extension", "[rt][render]") {
    registry types;
    register_all_pieces(types);
    test::temp_dir dir;
    const auto f = dir.write("s.ray_trace", "tracer flat\nbackground 0 0 1\nSPHERE { color 1 0 0 }");
    vfb out(31, 31, "rgbf");
    render_options o;
    o.progress = false;
    render_to_vfb(f, types, out, o);
    const vfb_pixel centre = out.get_pixel(16, 16), corner = out.get_pixel(0, 0);
    CHECK(centre.r() == Approx(1));
    CHECK(centre.b() == Approx(0));
    CHECK(corner.b() == Approx(1));
    const auto other = dir.write("s.txt", "SPHERE { }");
    CHECK_THROWS_WITH(render_to_vfb(other, types, out), Catch::Contains("s.txt: cannot render a '.txt' file"));
}

TEST_CASE("image compare: identical images match, a changed one does not", "[rt][compare]") {
    image a(20, 10, 3, sample_type::u8);
    for (auto& v : a.samples<std::uint8_t>()) v = 100;
    image b = a;
    image_difference d = compare_images(a, b);
    CHECK(d.same_size);
    CHECK(d.max_abs == 0);
    CHECK(renders_match(d));
    for (int x = 0; x < 20; ++x) b.row<std::uint8_t>(3)[static_cast<std::size_t>(3 * x)] = 200;  // one red row
    d = compare_images(a, b);
    CHECK(d.max_abs == 100);
    CHECK(d.fraction_over == Approx(0.1));
    CHECK_FALSE(renders_match(d));
    CHECK_FALSE(compare_images(a, image(10, 10, 3, sample_type::u8)).same_size);
}
