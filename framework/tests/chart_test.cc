// Charts by gnuplot (vl/chart.hh): the numbers file and the script always, the SVG and
// the PNG with gnuplot, which tools/setup installs.
#include "vl/catch.hh"

#include <cmath>
#include <limits>

#include "image_test_support.hh"
#include "vl/chart.hh"
#include "vl/error.hh"
#include "vl/image_io.hh"

namespace {

vl::chart two_series() {
    vl::chart c;
    c.title = "failures against distance / radius";
    c.x_label = "distance / radius";
    c.y_label = "failure rate";
    c.log_x = true;
    c.series.push_back({"reference", {{1, 0}, {1e3, 0}, {1e6, 0.25}}, vl::chart_series::style::line});
    c.series.push_back({"yours (it's 'quoted')", {{1, 0}, {1e3, 0.5}, {1e6, 1}}, vl::chart_series::style::marks});
    c.band = {{1, 1e3}};
    c.band_label = "a correct method is stable here";
    return c;
}

}  // namespace

TEST_CASE("a chart's numbers file holds every series in order, one block each", "[chart]") {
    const vl::test::temp_dir dir;
    const vl::chart_files f = vl::draw_chart(two_series(), dir / "sweep");
    const std::string tsv = vl::test::read_bytes(f.tsv);
    CHECK(tsv.find("# series 0: reference\n1\t0\n1000\t0\n1e+06\t0.25\n") != std::string::npos);
    CHECK(tsv.find("\n\n\n# series 1: yours (it's 'quoted')\n1\t0\n1000\t0.5\n1e+06\t1\n") != std::string::npos);
    const std::string script = vl::test::read_bytes(f.script);
    CHECK(script.find("set logscale x") != std::string::npos);
    CHECK(script.find("'yours (it''s ''quoted'')'") != std::string::npos);  // gnuplot's quoting
}

TEST_CASE("with gnuplot a chart is an SVG and a PNG of the chart's size", "[chart]") {
    INFO("gnuplot is not installed: tools/setup installs gnuplot-nox");
    REQUIRE(vl::gnuplot_available());
    const vl::test::temp_dir dir;
    vl::chart c = two_series();
    c.width = 640;
    c.height = 360;
    const vl::chart_files f = vl::draw_chart(c, dir / "sweep");
    INFO(f.problem);
    REQUIRE(f.problem.empty());
    CHECK(f.svg_text.find("<svg") != std::string::npos);
    CHECK(f.svg_text.find("failures against distance / radius") != std::string::npos);
    CHECK(f.svg_text.find("a correct method is stable here") != std::string::npos);
    const vl::image png = vl::read_image(f.png);
    CHECK(png.width() == 640);
    CHECK(png.height() == 360);
}

TEST_CASE("points a log axis cannot show are left out of the drawing, kept in the numbers", "[chart]") {
    INFO("gnuplot is not installed: tools/setup installs gnuplot-nox");
    REQUIRE(vl::gnuplot_available());
    const vl::test::temp_dir dir;
    vl::chart c;
    c.title = "tests per ray";
    c.log_x = c.log_y = true;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    c.series.push_back({"bvh", {{0, 1}, {10, 0}, {nan, 3}, {100, 7}, {1000, 9}}, vl::chart_series::style::line});
    const vl::chart_files f = vl::draw_chart(c, dir / "log");
    INFO(f.problem);
    CHECK(f.problem.empty());
    CHECK(vl::test::read_bytes(f.tsv).find("0\t1\n10\t0\nnan\t3\n100\t7\n") != std::string::npos);
}

TEST_CASE("a chart that cannot be written names the file", "[chart]") {
    const vl::test::temp_dir dir;
    try {
        vl::draw_chart(two_series(), dir / "no such folder" / "sweep");
        FAIL("no error");
    } catch (const vl::file_error& e) {
        CHECK(std::string(e.what()).find("no such folder/sweep.tsv") != std::string::npos);
    }
}
