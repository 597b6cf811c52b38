// Sweeps: reading a sweep test's points, and judging them against the rubric's stable range.
#include "vl/catch.hh"

#include "sweeps.hh"

using namespace vl::grader;

namespace {

rubric_sweep far_spheres() {
    rubric_sweep s;
    s.test = "sweep: far spheres";
    s.title = "far spheres";
    s.x_label = "distance / radius";
    s.stable_from = 1;
    s.stable_through = 1e6;
    s.max_failure_rate = 0.01;
    return s;
}

std::vector<sweep_point> curve(std::initializer_list<long long> failures) {
    std::vector<sweep_point> out;
    double x = 1;
    for (const long long f : failures) {
        out.push_back({x, 200, f, ""});
        x *= 1000;
    }
    return out;
}

}  // namespace

TEST_CASE("sweep points are read from the warnings a sweep test wrote, other warnings ignored", "[sweeps]") {
    const measured_points m = read_points({"  vl-sweep x=1e-05 trials=256 failures=3 example=the ray from (0, 0, 5) missed ",
                                           "something else", "vl-chart series=bvh x=1000 y=12.5",
                                           "vl-sweep x=infinity trials=1 failures=0"});
    REQUIRE(m.problem.empty());
    REQUIRE(m.sweep.size() == 2);
    CHECK(m.sweep[0].x == 1e-5);
    CHECK(m.sweep[0].trials == 256);
    CHECK(m.sweep[0].failures == 3);
    CHECK(m.sweep[0].example == "the ray from (0, 0, 5) missed");
    CHECK(std::isinf(m.sweep[1].x));
    REQUIRE(m.chart.size() == 1);
    CHECK(m.chart[0].series == "bvh");
    CHECK(m.chart[0].y == 12.5);
}

TEST_CASE("a point that cannot be read is a problem, never a point", "[sweeps]") {
    for (const char* bad : {"vl-sweep x=1 trials=10", "vl-sweep x=one trials=10 failures=0",
                            "vl-sweep x=1 trials=10 failures=11", "vl-sweep x=1 trials=-1 failures=0",
                            "vl-chart x=1 y=2", "vl-chart series=a x=1 y=2e"}) {
        INFO(bad);
        CHECK_FALSE(read_points({bad}).problem.empty());
    }
}

TEST_CASE("a sweep passes when no value of the stable range fails more than allowed", "[sweeps]") {
    const rubric_sweep s = far_spheres();
    const auto ref = curve({0, 0, 0, 50});  // x = 1, 1e3, 1e6, 1e9: fails only beyond the range
    const sweep_verdict ok = judge_sweep(s, curve({0, 2, 0, 200}), ref);
    CHECK(ok.passed);
    CHECK(ok.message.find("stable at all 3 values") != std::string::npos);
    CHECK(ok.message.find("first fails at distance / radius = 1e+09") != std::string::npos);
    const sweep_verdict bad = judge_sweep(s, curve({0, 3, 0, 0}), ref);  // 3 of 200 > 1%
    CHECK_FALSE(bad.passed);
    CHECK(bad.message.find("at distance / radius = 1000, 3 of 200 trials failed") != std::string::npos);
}

TEST_CASE("a sweep whose values or trials differ from the reference's fails as not matching", "[sweeps]") {
    const rubric_sweep s = far_spheres();
    const auto ref = curve({0, 0, 0, 0});
    CHECK_FALSE(judge_sweep(s, curve({0, 0, 0}), ref).passed);  // a value left out
    auto more_trials = curve({0, 0, 0, 0});
    more_trials[1].trials = 10;
    const sweep_verdict v = judge_sweep(s, more_trials, ref);
    CHECK_FALSE(v.passed);
    CHECK(v.message.find("does not match") != std::string::npos);
    auto moved = curve({0, 0, 0, 0});
    moved[2].x = 5;  // a forged value inside the range
    CHECK_FALSE(judge_sweep(s, moved, ref).passed);
}

TEST_CASE("a sweep's chart shades the stable range and draws the submission over the reference", "[sweeps]") {
    const vl::chart c = sweep_chart(far_spheres(), curve({0, 1, 2, 3}), curve({0, 0, 0, 1}), "this submission");
    REQUIRE(c.series.size() == 2);
    CHECK(c.series[0].name == "reference");
    CHECK(c.series[1].look == vl::chart_series::style::marks);
    CHECK(c.series[1].points[3].second == 3.0 / 200);
    REQUIRE(c.band);
    CHECK(c.band->second == 1e6);
    CHECK(sweep_chart(far_spheres(), {}, curve({0, 0, 0, 1}), "").series.size() == 1);
}
