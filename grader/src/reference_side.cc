#include "reference_side.hh"

#include <algorithm>
#include <sstream>

#include <nlohmann/json.hpp>

#include "safe_files.hh"

namespace vl::grader {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

/// Which programs and rubric the cache was measured with: each file's size, change time
/// and inode (a rebuild or an edit changes them), and the limits the tests ran under.
std::string identity(const stage_info& stage, const rubric& r) {
    std::string id;
    for (const fs::path& p : {stage.trusted_tests, stage.tests_on_stubs, r.file})
        id += p.empty() ? " missing;" : file_identity(p);
    id += " test limits " + std::to_string(r.test_limits.wall_seconds) + " " + std::to_string(r.test_limits.memory_bytes);
    return id;
}

json to_json(const reference_side& s, const std::string& id) {
    json tests = json::array();
    for (const test_case_info& t : s.tests)
        tests.push_back({{"name", t.name}, {"tags", t.tags}, {"raw_tags", t.raw_tags}, {"file", t.file}, {"line", t.line}});
    json points = json::object();
    for (const auto& [name, m] : s.points) {
        json sweep = json::array(), chart = json::array();
        for (const sweep_point& p : m.sweep)
            sweep.push_back({{"x", p.x}, {"trials", p.trials}, {"failures", p.failures}, {"example", p.example}});
        for (const chart_point& p : m.chart) chart.push_back({{"series", p.series}, {"x", p.x}, {"y", p.y}});
        points[name] = {{"sweep", sweep}, {"chart", chart}};
    }
    return {{"identity", id}, {"tests", tests}, {"kit_passes", s.kit_passes}, {"points", points}};
}

bool from_json(const json& j, reference_side& s) {
    try {
        for (const auto& t : j.at("tests"))
            s.tests.push_back({t.at("name"), t.at("tags").get<std::vector<std::string>>(), t.at("raw_tags"), t.at("file"),
                               t.at("line")});
        for (const auto& name : j.at("kit_passes")) s.kit_passes.insert(name.get<std::string>());
        for (const auto& [name, m] : j.at("points").items()) {
            measured_points& p = s.points[name];
            for (const auto& q : m.at("sweep")) p.sweep.push_back({q.at("x"), q.at("trials"), q.at("failures"), q.at("example")});
            for (const auto& q : m.at("chart")) p.chart.push_back({q.at("series"), q.at("x"), q.at("y")});
        }
    } catch (const json::exception&) {
        return false;
    }
    return true;
}

/// The points of a [sweep] or [chart] test as the reference measures them. The reference
/// must run it cleanly: otherwise the test or the rubric is wrong, and no student may lose
/// points for it.
measured_points measure(const stage_info& stage, const test_case_info& test, const rubric& r,
                        const sandbox_capabilities& caps) {
    const test_outcome o = run_test_case(stage.trusted_tests, test, r.test_limits, caps);
    if (o.result != item_result::passed)
        throw grader_error("the hidden test '" + test.name + "' " + to_string(o.result) + " with the reference: " +
                           o.message);
    measured_points m = read_points(o.warnings);
    if (!m.problem.empty()) throw grader_error("the hidden test '" + test.name + "' with the reference: " + m.problem);
    return m;
}

}  // namespace

reference_side reference_side_of(const installation& in, const stage_info& stage, const rubric& r, const fs::path& work,
                                 const sandbox_capabilities& caps) {
    reference_side s;
    if (stage.trusted_tests.empty()) return s;  // a stage without hidden tests yet
    const std::string id = identity(stage, r);
    // One file per test time limit, so grades under scaled limits (calibrate --limits-scale)
    // and under the rubric's do not take turns overwriting one another's.
    std::ostringstream limit;
    limit << r.test_limits.wall_seconds;
    const fs::path cache = in.grader_build_dir / "reference-cache" / (stage.name + "-" + limit.str() + "s.json");
    const json cached = json::parse(read_regular_file(cache, std::size_t{64} << 20), nullptr, false);
    if (cached.is_object() && cached.value("identity", "") == id && from_json(cached, s)) {
        s.from_cache = true;
        return s;
    }
    s = {};
    s.tests = list_trusted_tests(stage.trusted_tests, work / "trusted", caps);
    check_rubric(r, s.tests);
    if (!stage.tests_on_stubs.empty()) s.kit_passes = tests_passing_on_stubs(stage.tests_on_stubs, work / "stubs", caps);
    for (const rubric_sweep& w : r.sweeps) s.points[w.test] = measure(stage, named_test(s.tests, w.test), r, caps);
    for (const rubric_chart& c : r.charts) s.points[c.test] = measure(stage, named_test(s.tests, c.test), r, caps);
    keep_cache_file(cache, to_json(s, id).dump() + "\n");
    return s;
}

}  // namespace vl::grader
