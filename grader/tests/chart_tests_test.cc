// The hidden chart tests ([chart]) of stages 01 and 03, run with the reference (the
// trusted test programs): their points parse, their series and x values are the fixed
// ones the report lines up (never a time), and a second run gives the same points.
#include "vl/catch.hh"

#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <pugixml.hpp>

#include "sweeps.hh"

using namespace vl::grader;

namespace {

/// The Catch2 warnings of `program`'s test `name`, run alone with the XML reporter.
std::vector<std::string> warnings_of(const std::string& program, const std::string& name) {
    std::string spec;  // the exact name: Catch2 reads ',' as "or" ('\\' escapes it)
    for (const char c : name) {
        if (c == ',' || c == '[' || c == ']' || c == '*' || c == '~') spec += "\\";
        spec += c;
    }
    const std::string command = program + " '" + spec + "' -r xml 2>/dev/null";
    FILE* pipe = popen(command.c_str(), "r");
    REQUIRE(pipe);
    std::string xml;
    char buffer[4096];
    while (const std::size_t n = std::fread(buffer, 1, sizeof buffer, pipe)) xml.append(buffer, n);
    REQUIRE(pclose(pipe) == 0);
    pugi::xml_document doc;
    REQUIRE(doc.load_string(xml.c_str()));
    std::vector<std::string> out;
    for (const pugi::xpath_node& w : doc.select_nodes("//Warning")) out.push_back(w.node().text().as_string());
    return out;
}

std::vector<chart_point> points_of(const std::string& program, const std::string& name) {
    const measured_points m = read_points(warnings_of(program, name));
    INFO(m.problem);
    REQUIRE(m.problem.empty());
    return m.chart;
}

void check_chart(const std::vector<chart_point>& points, const std::set<std::string>& series,
                 const std::vector<double>& xs) {
    REQUIRE(points.size() == series.size() * xs.size());
    std::set<std::string> seen;
    for (std::size_t k = 0; k < points.size(); ++k) {
        seen.insert(points[k].series);
        CHECK(points[k].x == xs[k % xs.size()]);
        CHECK(std::isfinite(points[k].y));
        CHECK(points[k].y > 0);
    }
    CHECK(seen == series);
}

}  // namespace

TEST_CASE("the stage 01 chart test reports FLIP at 1 to 64 samples per pixel for each pattern, the same every run", "[charts]") {
    const std::string name = "chart: samplers: LDR-FLIP against the converged picture as samples per pixel grow - per pattern";
    const std::vector<chart_point> points = points_of(VL_TRUSTED_01, name);
    check_chart(points, {"center", "grid", "jittered", "random"}, {1, 2, 4, 8, 16, 32, 64});
    // The reference's jittered pattern converges: 64 samples are far better than 1.
    double first = 0, last = 0;
    for (const chart_point& p : points) {
        if (p.series == "jittered" && p.x == 1) first = p.y;
        if (p.series == "jittered" && p.x == 64) last = p.y;
    }
    CHECK(last < first / 4);
    const std::vector<chart_point> again = points_of(VL_TRUSTED_01, name);
    REQUIRE(again.size() == points.size());
    for (std::size_t k = 0; k < points.size(); ++k) CHECK(again[k].y == points[k].y);
}

TEST_CASE("the stage 03 chart test reports tests per ray at N = 16 to 4096 for each structure, the same every run", "[charts]") {
    const std::string name = "chart: composites: tests per ray against the number of random spheres - per structure";
    const std::vector<chart_point> points = points_of(VL_TRUSTED_03, name);
    REQUIRE(points.size() == 5 * 9);
    std::set<std::string> series;
    std::map<double, double> bvh_all, bvh_children;
    for (std::size_t k = 0; k < points.size(); ++k) {
        series.insert(points[k].series);
        CHECK(points[k].x == 16 * std::pow(2.0, static_cast<double>(k / 5)));
        CHECK(points[k].y > 0);
        // A LIST tests itself and every child.
        if (points[k].series == "list") CHECK(points[k].y == points[k].x + 1);
        if (points[k].series == "bvh") bvh_all[points[k].x] = points[k].y;
        if (points[k].series == "bvh-children") bvh_children[points[k].x] = points[k].y;
    }
    CHECK(series == std::set<std::string>{"list", "bounding-sphere", "bounding-spheres-in-cells", "bvh", "bvh-children"});
    // The children's tests (the leaderboard's series) are a part of all the BVH's tests.
    REQUIRE(bvh_children.size() == 9);
    for (const auto& [n, children] : bvh_children) CHECK(children < bvh_all.at(n));
    const std::vector<chart_point> again = points_of(VL_TRUSTED_03, name);
    REQUIRE(again.size() == points.size());
    for (std::size_t k = 0; k < points.size(); ++k) CHECK(again[k].y == points[k].y);
}
