#include "results_json.hh"

#include "safe_files.hh"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>

#include <nlohmann/json.hpp>

namespace vl::grader {

namespace {

/// Scores are shown with at most 4 decimals (a third of a point stays 0.3333).
double tidy(double x) { return std::round(x * 1e4) / 1e4; }

/// How late a visibility shows an entry to the student (Gradescope's four).
int lateness(const std::string& visibility) {
    return visibility == "visible" ? 0 : visibility == "after_due_date" ? 1 : visibility == "after_published" ? 2 : 3;
}

/// What the student reads in place of a hidden test's message until `details` lets it show.
std::string details_later(const std::string& details) {
    const std::string when = details == "after_due_date"    ? "after the due date"
                             : details == "after_published" ? "once grades are published"
                                                            : "to the course staff only";
    return "What this hidden test asked, expected and got is shown " + when + ".";
}

std::string summary_text(const graded_submission& g) {
    std::string s = g.title + ": " + std::to_string(static_cast<int>(std::lround(g.score))) + " of " +
                    std::to_string(static_cast<int>(std::lround(g.max_score))) + " points.\n";
    if (!g.built && !g.items.empty() && g.items.front().result == item_result::refused)
        s += "Your code was refused, so none of it ran: see the test \"builds\" for what it may not do.\n";
    else if (!g.built)
        s += "Your code did not build: see the test \"builds\" for the compiler's first errors.\n";
    for (const category_total& c : g.categories)
        s += "  " + c.title + ": " + std::to_string(c.passed) + " of " + std::to_string(c.items) + " passed\n";
    for (const std::string& n : g.notes) s += "Note: " + n + "\n";
    return s;
}

}  // namespace

std::string results_json(const graded_submission& g) {
    using nlohmann::json;
    json tests = json::array();
    std::map<std::string, int> number_in_category;
    std::map<std::string, int> category_number;
    for (std::size_t k = 0; k < g.categories.size(); ++k) category_number[g.categories[k].name] = static_cast<int>(k) + 1;
    for (const graded_item& i : g.items) {
        json t;
        t["name"] = i.name;
        t["number"] = i.what == graded_item::kind::build
                          ? std::string("0")
                          : std::to_string(category_number[i.category]) + "." +
                                std::to_string(++number_in_category[i.category]);
        t["score"] = tidy(i.score);
        t["max_score"] = tidy(i.max_score);
        t["status"] = i.passed() ? "passed" : "failed";
        json tags = json::array({i.category});
        for (const std::string& tag : i.tags)
            if (std::find(tags.begin(), tags.end(), tag) == tags.end()) tags.push_back(tag);
        t["tags"] = tags;
        t["visibility"] = i.visibility;
        t["output"] = i.passed() ? i.message : to_string(i.result) + (i.message.empty() ? "" : ": " + i.message);
        t["extra_data"] = {{"category", i.category}, {"result", to_string(i.result)}, {"seconds", tidy(i.seconds)}};
        if (i.what == graded_item::kind::sweep) {
            auto curve = [](const std::vector<sweep_point>& ps) {
                json a = json::array();
                for (const sweep_point& p : ps) a.push_back({{"x", p.x}, {"trials", p.trials}, {"failures", p.failures}});
                return a;
            };
            t["extra_data"]["sweep"] = {{"test", i.test.name}, {"submission", curve(i.sweep)},
                                        {"reference", curve(i.reference_sweep)}};
        }
        if (i.what == graded_item::kind::scene && i.flip_mean >= 0)
            t["extra_data"]["scene"] = {{"id", i.tags.size() > 1 ? i.tags[1] : std::string()}, {"flip_mean", i.flip_mean}};
        // A hidden test's message states its inputs and expected values: the item shows its
        // name, pass or fail and points, and the message goes in an entry of no points that
        // shows as late as its category's `details` says.
        const bool hold_details = i.what == graded_item::kind::test && !i.details_visibility.empty() &&
                                  !i.message.empty() && lateness(i.details_visibility) > lateness(i.visibility);
        if (hold_details) {
            json details = t;
            t["output"] = (i.passed() ? std::string("passed") : to_string(i.result)) + ". " +
                          details_later(i.details_visibility);
            details["name"] = i.name + " (details)";
            details["number"] = t["number"].get<std::string>() + ".d";
            details["score"] = 0;
            details["max_score"] = 0;
            details["visibility"] = i.details_visibility;
            details["extra_data"] = {{"category", i.category}, {"result", to_string(i.result)}, {"details_of", i.name}};
            tests.push_back(t);
            tests.push_back(details);
            continue;
        }
        tests.push_back(t);
    }
    json categories = json::array();
    for (const category_total& c : g.categories)
        categories.push_back({{"name", c.name}, {"title", c.title}, {"score", tidy(c.score)},
                              {"max_score", tidy(c.max_score)}, {"passed", c.passed}, {"items", c.items}});
    json charts = json::array();
    for (const graded_chart& c : g.charts) {
        auto curve = [](const std::vector<chart_point>& ps) {
            json a = json::array();
            for (const chart_point& p : ps) a.push_back({{"series", p.series}, {"x", p.x}, {"y", p.y}});
            return a;
        };
        charts.push_back({{"title", c.title}, {"test", c.test}, {"message", c.message},
                          {"submission", curve(c.mine)}, {"reference", curve(c.reference)}});
    }
    json r;
    r["score"] = tidy(g.score);
    r["execution_time"] = static_cast<int>(std::ceil(g.seconds));
    r["output"] = summary_text(g);
    r["stdout_visibility"] = "hidden";
    r["tests"] = tests;
    if (!g.leaderboard.empty()) {
        json board = json::array();
        for (const leaderboard_value& v : g.leaderboard) board.push_back({{"name", v.name}, {"value", v.value}, {"order", v.order}});
        r["leaderboard"] = board;
    }
    r["extra_data"] = {{"assignment", g.assignment}, {"max_score", tidy(g.max_score)}, {"built", g.built},
                       {"categories", categories}, {"charts", charts}, {"sandbox", g.sandbox}, {"submission", g.submission},
                       {"graded_at", g.started_at}};
    // Messages come from compilers and student code: bytes that are not UTF-8 become U+FFFD.
    return r.dump(2, ' ', false, json::error_handler_t::replace) + "\n";
}

void write_results_json(const graded_submission& g, const std::filesystem::path& file) { replace_file(file, results_json(g)); }

std::vector<std::string> gradescope_format_problems(const nlohmann::json& r) {
    std::vector<std::string> problems;
    auto need = [&](const nlohmann::json& j, const char* key, auto is_type, const char* type, const std::string& where) {
        if (!j.contains(key) || !is_type(j[key])) problems.push_back(where + "\"" + key + "\" must be " + type);
    };
    const auto number = [](const nlohmann::json& j) { return j.is_number(); };
    const auto string = [](const nlohmann::json& j) { return j.is_string(); };
    const auto visibility = [](const nlohmann::json& j) {
        return j.is_string() && (j == "hidden" || j == "after_due_date" || j == "after_published" || j == "visible");
    };
    need(r, "score", number, "a number", "");
    need(r, "execution_time", number, "a number", "");
    need(r, "output", string, "a string", "");
    need(r, "stdout_visibility", visibility, "a visibility", "");
    if (r.contains("leaderboard")) {
        if (!r["leaderboard"].is_array()) problems.push_back("\"leaderboard\" must be an array");
        else
            for (const auto& v : r["leaderboard"])
                if (!v.is_object() || !v.contains("name") || !v["name"].is_string() || !v.contains("value") ||
                    !(v["value"].is_number() || v["value"].is_string()) ||
                    (v.contains("order") && v["order"] != "asc" && v["order"] != "desc"))
                    problems.push_back("a leaderboard entry needs a name, a value (number or text) and order asc or desc");
    }
    if (!r.contains("tests") || !r["tests"].is_array()) {
        problems.push_back("\"tests\" must be an array");
        return problems;
    }
    for (const auto& t : r["tests"]) {
        const std::string where = "test " + (t.contains("name") ? t["name"].dump() : std::string("?")) + ": ";
        need(t, "name", string, "a string", where);
        need(t, "number", string, "a string", where);
        need(t, "score", number, "a number", where);
        need(t, "max_score", number, "a number", where);
        need(t, "output", string, "a string", where);
        need(t, "visibility", visibility, "a visibility", where);
        need(t, "status", [](const nlohmann::json& j) { return j == "passed" || j == "failed"; }, "passed or failed",
             where);
        need(t, "tags", [](const nlohmann::json& j) { return j.is_array(); }, "an array", where);
        if (t.contains("score") && t.contains("max_score") && t["score"].is_number() && t["max_score"].is_number() &&
            (t["score"].get<double>() < 0 || t["score"].get<double>() > t["max_score"].get<double>() + 1e-9))
            problems.push_back(where + "score outside 0..max_score");
    }
    return problems;
}

}  // namespace vl::grader
