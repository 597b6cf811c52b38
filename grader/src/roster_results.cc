#include "roster_results.hh"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>

#include <nlohmann/json.hpp>

#include "install.hh"
#include "item_result.hh"
#include "safe_files.hh"

namespace vl::grader {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

/// A record is a few kilobytes; anything larger in results/ is not one of ours.
constexpr std::size_t record_cap = std::size_t{1} << 20;
/// A grade's results.json: every test's message, each capped by the grader.
constexpr std::size_t results_cap = std::size_t{64} << 20;

/// A number as the CSV shows it: at most 4 decimals, no trailing zeros.
std::string number(double x) {
    char text[64];
    std::snprintf(text, sizeof text, "%.4f", std::round(x * 1e4) / 1e4);
    std::string s = text;
    s.erase(s.find_last_not_of('0') + 1);
    if (!s.empty() && s.back() == '.') s.pop_back();
    return s == "-0" ? "0" : s;
}

/// Whether a spreadsheet would read a field starting with `c` as a formula (or, for a
/// tab or a carriage return, strip what hides one).
bool starts_formula(char c) { return c == '=' || c == '+' || c == '-' || c == '@' || c == '\t' || c == '\r'; }

/// One text cell of a CSV (RFC 4180), safe in any spreadsheet and any locale: always in
/// double quotes (so a reader that separates with `;`, a tab or `|` still sees one
/// field), quotes doubled, and an apostrophe before every place a field could start with
/// a formula: the cell's start and, for readers that ignore the quotes, after every
/// separator any locale uses (`,` `;` tab `|` line break), spaces skipped.
std::string cell(const std::string& s) {
    std::string q = "\"";
    bool field_start = true;
    for (const char c : s) {
        if (field_start && starts_formula(c)) q += '\'';
        if (c != ' ') field_start = c == ',' || c == ';' || c == '\t' || c == '|' || c == '\n' || c == '\r';
        q += c == '"' ? std::string("\"\"") : std::string(1, c);
    }
    return q + "\"";
}

std::string row(const std::vector<std::string>& cells) {
    std::string line;
    for (std::size_t k = 0; k < cells.size(); ++k) line += (k ? "," : "") + cells[k];
    return line + "\r\n";
}

json to_json(const roster_record& r) {
    json categories = json::array();
    for (const auto& c : r.categories) categories.push_back({{"name", c.name}, {"score", c.score}, {"max_score", c.max_score}});
    json board = json::array();
    for (const auto& v : r.leaderboard) board.push_back({{"name", v.name}, {"value", v.value}, {"order", v.order}});
    return {{"student", r.student}, {"submission", r.submission}, {"hash", r.hash}, {"assignment", r.assignment},
            {"setup", r.setup},
            {"status", r.status}, {"grade", r.grade}, {"verdict", r.verdict}, {"message", r.message},
            {"score", r.score}, {"max_score", r.max_score}, {"seconds", r.seconds}, {"built", r.built},
            {"categories", categories},
            {"counts", {{"passed", r.passed}, {"failed", r.failed}, {"crashed", r.crashed}, {"timed_out", r.timed_out},
                        {"refused", r.refused}, {"not_run", r.not_run}}},
            {"leaderboard", board}};
}

roster_record from_json(const json& j) {
    roster_record r;
    r.student = j.at("student");
    r.submission = j.at("submission");
    r.hash = j.at("hash");
    r.assignment = j.value("assignment", "");
    r.setup = j.value("setup", "");
    r.status = j.at("status");
    r.grade = j.value("grade", "");
    r.verdict = j.value("verdict", "");
    r.message = j.value("message", "");
    r.score = j.value("score", 0.0);
    r.max_score = j.value("max_score", 0.0);
    r.seconds = j.value("seconds", 0.0);
    r.built = j.value("built", false);
    for (const auto& c : j.value("categories", json::array()))
        r.categories.push_back({c.at("name"), c.at("score"), c.at("max_score")});
    const json counts = j.value("counts", json::object());
    r.passed = counts.value("passed", 0);
    r.failed = counts.value("failed", 0);
    r.crashed = counts.value("crashed", 0);
    r.timed_out = counts.value("timed_out", 0);
    r.refused = counts.value("refused", 0);
    r.not_run = counts.value("not_run", 0);
    for (const auto& v : j.value("leaderboard", json::array())) r.leaderboard.push_back({v.at("name"), v.at("order"), v.at("value")});
    return r;
}

}  // namespace

std::string fnv1a64::hex() const {
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(h));
    return text;
}

std::string roster_file_stem(const std::string& name) {
    if (name.size() <= 200) return name;
    fnv1a64 h;
    h.add(name.data(), name.size());
    return name.substr(0, 180) + "~" + h.hex();
}

roster_record record_from_results(const fs::path& results_json, const std::string& student, const std::string& submission,
                                  const std::string& hash, const std::string& grade) {
    const std::string text = read_regular_file(results_json, results_cap);
    const json j = json::parse(text, nullptr, false);
    if (j.is_discarded() || !j.is_object() || !j.contains("extra_data"))
        throw grader_error(results_json.string() + ": not a results.json the grader wrote");
    roster_record r;
    r.student = student;
    r.submission = submission;
    r.hash = hash;
    r.grade = grade;
    r.status = "graded";
    const json& extra = j["extra_data"];
    r.assignment = extra.value("assignment", "");
    r.score = j.value("score", 0.0);
    r.max_score = extra.value("max_score", 0.0);
    r.seconds = j.value("execution_time", 0.0);
    r.built = extra.value("built", false);
    for (const auto& c : extra.value("categories", json::array()))
        r.categories.push_back({c.value("name", ""), c.value("score", 0.0), c.value("max_score", 0.0)});
    std::string build_result;
    for (const auto& t : j.value("tests", json::array())) {
        if (t.value("extra_data", json::object()).contains("details_of")) continue;  // a hidden test's message, not an item
        const std::string result = t.value("extra_data", json::object()).value("result", "");
        if (t.value("number", "") == "0") build_result = result;
        switch (from_string(result).value_or(item_result::not_run)) {
            case item_result::passed: ++r.passed; break;
            case item_result::failed: ++r.failed; break;
            case item_result::crashed: ++r.crashed; break;
            case item_result::timed_out: ++r.timed_out; break;
            case item_result::refused: ++r.refused; break;
            case item_result::not_run: ++r.not_run; break;
        }
    }
    r.verdict = r.built ? "graded" : from_string(build_result) == item_result::refused ? "refused" : "did not build";
    for (const auto& v : j.value("leaderboard", json::array()))
        if (v.contains("value") && v["value"].is_number())
            r.leaderboard.push_back({v.value("name", ""), v.value("order", "desc"), v["value"].get<double>()});
    return r;
}

void write_record(const fs::path& out, const roster_record& r) {
    replace_file(out / "results" / (roster_file_stem(r.student) + ".json"), to_json(r).dump(2) + "\n");
}

bool read_record(const fs::path& out, const std::string& student, roster_record& r) {
    const std::string text = read_regular_file(out / "results" / (roster_file_stem(student) + ".json"), record_cap);
    const json j = json::parse(text, nullptr, false);
    if (j.is_discarded() || !j.is_object()) return false;
    try {
        r = from_json(j);
    } catch (const json::exception&) {
        return false;
    }
    return r.student == student;
}

std::vector<roster_record> read_records(const fs::path& out) {
    std::vector<roster_record> records;
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(out / "results", ec)) {
        if (e.path().extension() != ".json") continue;
        const json j = json::parse(read_regular_file(e.path(), record_cap), nullptr, false);
        if (j.is_discarded() || !j.is_object()) continue;
        try {
            records.push_back(from_json(j));
        } catch (const json::exception&) {
        }
    }
    std::sort(records.begin(), records.end(), [](const auto& a, const auto& b) { return a.student < b.student; });
    return records;
}

std::string roster_csv(const std::vector<roster_record>& records, const std::vector<std::string>& missing) {
    // The categories in rubric order, as the first graded record lists them.
    std::vector<std::string> categories;
    for (const roster_record& r : records)
        for (const auto& c : r.categories)
            if (std::find(categories.begin(), categories.end(), c.name) == categories.end()) categories.push_back(c.name);
    std::vector<std::string> head = {"student", "verdict", "score", "max_score", "percent"};
    head.insert(head.end(), categories.begin(), categories.end());
    for (const char* h : {"passed", "failed", "crashed", "timed_out", "refused", "not_run", "hash", "report", "message"})
        head.push_back(h);
    for (std::string& h : head) h = cell(h);
    std::string csv = row(head);
    std::vector<std::pair<std::string, std::vector<std::string>>> lines;
    for (const roster_record& r : records) {
        const bool graded = r.status == "graded";
        std::vector<std::string> cells = {cell(r.student), cell(graded ? r.verdict : r.status)};
        if (graded) {
            cells.push_back(number(r.score));
            cells.push_back(number(r.max_score));
            cells.push_back(r.max_score > 0 ? number(100 * r.score / r.max_score) : "");
        } else {
            cells.insert(cells.end(), {"", "", ""});
        }
        for (const std::string& name : categories) {
            const auto c = std::find_if(r.categories.begin(), r.categories.end(), [&](const auto& x) { return x.name == name; });
            cells.push_back(graded && c != r.categories.end() ? number(c->score) : "");
        }
        for (const int n : {r.passed, r.failed, r.crashed, r.timed_out, r.refused, r.not_run})
            cells.push_back(graded ? std::to_string(n) : "");
        cells.push_back(cell(r.hash));
        cells.push_back(graded ? cell(r.grade + "/report.html") : "");
        cells.push_back(cell(r.message));
        lines.emplace_back(r.student, cells);
    }
    for (const std::string& name : missing) {
        std::vector<std::string> cells = {cell(name), cell("not graded")};
        cells.resize(head.size());
        cells.back() = cell("no grade yet: grade it with the roster again");
        lines.emplace_back(name, cells);
    }
    std::sort(lines.begin(), lines.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    for (const auto& l : lines) csv += row(l.second);
    return csv;
}

std::string leaderboard_csv(const std::vector<roster_record>& records) {
    std::vector<std::string> names, orders;
    for (const roster_record& r : records)
        for (const leaderboard_value& v : r.leaderboard)
            if (std::find(names.begin(), names.end(), v.name) == names.end()) {
                names.push_back(v.name);
                orders.push_back(v.order);
            }
    if (names.empty()) return {};
    struct entry {
        const roster_record* r;
        std::vector<double> values;  // NaN where missing
        bool ranked;
    };
    std::vector<entry> entries;
    for (const roster_record& r : records) {
        if (r.status != "graded") continue;
        entry e{&r, std::vector<double>(names.size(), std::nan("")), false};
        for (const leaderboard_value& v : r.leaderboard) {
            const auto at = std::find(names.begin(), names.end(), v.name) - names.begin();
            e.values[static_cast<std::size_t>(at)] = v.value;
        }
        e.ranked = !std::isnan(e.values[0]);
        entries.push_back(e);
    }
    auto better = [&](const entry& a, const entry& b) {
        if (a.ranked != b.ranked) return a.ranked;
        for (std::size_t k = 0; k < names.size(); ++k) {
            const double x = a.values[k], y = b.values[k];
            if (std::isnan(x) != std::isnan(y)) return !std::isnan(x);
            if (std::isnan(x) || x == y) continue;
            return orders[k] == "asc" ? x < y : x > y;
        }
        return a.r->student < b.r->student;
    };
    std::sort(entries.begin(), entries.end(), better);
    std::vector<std::string> head = {cell("rank"), cell("student")};
    for (std::size_t k = 0; k < names.size(); ++k)
        head.push_back(cell(names[k] + (orders[k] == "asc" ? " (lower is better)" : " (higher is better)")));
    head.push_back(cell("score"));
    std::string csv = row(head);
    int rank = 0;
    for (std::size_t k = 0; k < entries.size(); ++k) {
        const entry& e = entries[k];
        // Equal values share a rank (1, 2, 2, 4).
        if (e.ranked && (k == 0 || entries[k - 1].values != e.values)) rank = static_cast<int>(k) + 1;
        std::vector<std::string> cells = {e.ranked ? std::to_string(rank) : "", cell(e.r->student)};
        for (const double v : e.values) cells.push_back(std::isnan(v) ? "" : number(v));
        cells.push_back(number(e.r->score));
        csv += row(cells);
    }
    return csv;
}

}  // namespace vl::grader
