// What Gradescope shows a student (results_json.hh): a hidden test's name, pass or fail and
// points at once; what it asked, expected and got only when its category's `details` says.
#include "vl/catch.hh"

#include <nlohmann/json.hpp>

#include "results_json.hh"

using namespace vl::grader;
using nlohmann::json;

namespace {

graded_item test_item(const std::string& name, vl::grader::item_result result, const std::string& message,
                      const std::string& details) {
    graded_item i;
    i.what = graded_item::kind::test;
    i.name = name;
    i.category = "sphere";
    i.visibility = "visible";
    i.details_visibility = details;
    i.result = result;
    i.message = message;
    i.max_score = 2;
    i.score = result == vl::grader::item_result::passed ? 2 : 0;
    return i;
}

graded_submission submission(std::vector<graded_item> items) {
    graded_submission g;
    g.assignment = "02-sphere";
    g.title = "Stage 02";
    g.built = true;
    g.items = std::move(items);
    g.categories = {{"sphere", "Sphere", 2, 8, 1, 4}};
    g.score = 2;
    g.max_score = 8;
    return g;
}

const json* entry(const json& r, const std::string& name) {
    for (const json& t : r["tests"])
        if (t["name"] == name) return &t;
    return nullptr;
}

}  // namespace

TEST_CASE("results.json: a hidden test's message shows only when its category's details say, its verdict at once") {
    const std::string expected = "asked for the hit of ray (0, 0, 5) -> (0, 0, -1): expected t = 4 +- 1e-9, got 6";
    const json r = json::parse(results_json(submission({
        test_item("hidden fails", vl::grader::item_result::failed, expected, "after_published"),
        test_item("hidden passes", vl::grader::item_result::passed, "", "after_published"),
        test_item("public fails", vl::grader::item_result::failed, expected, ""),
        test_item("shown fails", vl::grader::item_result::failed, expected, "visible"),
    })));
    CHECK(gradescope_format_problems(r).empty());

    // The item: its name, points and verdict, visible; not a word of its inputs.
    const json* item = entry(r, "hidden fails");
    REQUIRE(item);
    CHECK((*item)["visibility"] == "visible");
    CHECK((*item)["status"] == "failed");
    CHECK((*item)["max_score"] == 2);
    CHECK((*item)["output"].get<std::string>().find("(0, 0, 5)") == std::string::npos);
    CHECK((*item)["output"].get<std::string>().find("t = 4") == std::string::npos);
    CHECK((*item)["output"].get<std::string>().find("once grades are published") != std::string::npos);
    // Its message, whole, in an entry of no points shown after publication.
    const json* details = entry(r, "hidden fails (details)");
    REQUIRE(details);
    CHECK((*details)["visibility"] == "after_published");
    CHECK((*details)["output"].get<std::string>().find(expected) != std::string::npos);
    CHECK((*details)["max_score"] == 0);
    CHECK((*details)["extra_data"]["details_of"] == "hidden fails");

    // Nothing to hold back: a pass without a message, a public test, a category that shows it.
    CHECK(!entry(r, "hidden passes (details)"));
    CHECK(!entry(r, "public fails (details)"));
    CHECK((*entry(r, "public fails"))["output"].get<std::string>().find(expected) != std::string::npos);
    CHECK(!entry(r, "shown fails (details)"));
    CHECK((*entry(r, "shown fails"))["output"].get<std::string>().find(expected) != std::string::npos);
}

TEST_CASE("results.json: an item already shown after the due date keeps a message shown after publication apart") {
    graded_item i = test_item("late item", vl::grader::item_result::failed, "expected 4, got 6", "after_published");
    i.visibility = "after_due_date";
    const json r = json::parse(results_json(submission({i})));
    REQUIRE(entry(r, "late item (details)"));
    CHECK((*entry(r, "late item (details)"))["visibility"] == "after_published");
    i.visibility = "after_published";  // shown no earlier than its details: nothing to split
    const json same = json::parse(results_json(submission({i})));
    CHECK(!entry(same, "late item (details)"));
    CHECK((*entry(same, "late item"))["output"].get<std::string>().find("expected 4, got 6") != std::string::npos);
}
