#include "rubric.hh"

#include <algorithm>
#include <cmath>
#include <set>

#include <toml++/toml.h>

#include "install.hh"
#include "vl/registry.hh"

namespace vl::grader {

namespace fs = std::filesystem;

namespace {

const std::set<std::string> visibilities = {"visible", "hidden", "after_due_date", "after_published"};

std::string place(const fs::path& file, const toml::node& n) {
    const toml::source_position p = n.source().begin;
    return file.string() + ":" + std::to_string(p.line) + ":" + std::to_string(p.column);
}

std::vector<std::string> strings(const fs::path& file, const toml::table& t, const char* key) {
    std::vector<std::string> out;
    if (const toml::node* n = t.get(key)) {
        const toml::array* a = n->as_array();
        if (!a) throw grader_error(place(file, *n) + ": '" + key + "' must be a list of strings");
        for (const toml::node& e : *a) {
            if (!e.is_string()) throw grader_error(place(file, e) + ": '" + key + "' must hold strings");
            out.push_back(*e.value<std::string>());
        }
    }
    return out;
}

/// The Gradescope visibility `t[key]`, or `fallback` when there is none.
std::string visibility(const fs::path& file, const toml::table& t, const std::string& fallback,
                       const char* key = "visibility") {
    const std::string v = t[key].value_or(fallback);
    if (!visibilities.contains(v))
        throw grader_error(place(file, t.get(key) ? *t.get(key) : static_cast<const toml::node&>(t)) + ": " + key + " '" +
                           v + "': use visible, hidden, after_due_date or after_published");
    return v;
}

double number(const fs::path& file, const toml::table& t, const char* key, double fallback) {
    const toml::node* n = t.get(key);
    if (!n) return fallback;
    const auto v = n->value<double>();
    if (!v || *v < 0) throw grader_error(place(file, *n) + ": '" + key + "' must be a number, 0 or more");
    return *v;
}

/// Refuses keys a table may not have (a typo would otherwise be silently ignored).
void only_keys(const fs::path& file, const toml::table& t, const char* what, const std::set<std::string>& keys) {
    for (const auto& [key, value] : t)
        if (!keys.contains(std::string(key.str()))) {
            std::string known;
            for (const std::string& k : keys) known += (known.empty() ? "" : ", ") + k;
            throw grader_error(place(file, value) + ": a " + what + " has no key '" + std::string(key.str()) +
                               "' (it may have: " + known + ")");
        }
}

std::string text(const fs::path& file, const toml::table& t, const char* key, bool required, const char* what) {
    const toml::node* n = t.get(key);
    if (!n) {
        if (required) throw grader_error(place(file, t) + ": a " + what + " needs '" + key + "'");
        return {};
    }
    if (!n->is_string() || n->value<std::string>()->empty())
        throw grader_error(place(file, *n) + ": '" + key + "' must be a non-empty string");
    return *n->value<std::string>();
}

bool flag(const fs::path& file, const toml::table& t, const char* key) {
    const toml::node* n = t.get(key);
    if (!n) return false;
    if (!n->is_boolean()) throw grader_error(place(file, *n) + ": '" + key + "' must be true or false");
    return *n->value<bool>();
}

void read_measurements(const fs::path& file, const toml::table& t, const std::set<std::string>& categories, rubric& r) {
    std::set<std::string> tests;
    if (const toml::node* n = t.get("sweep")) {
        const toml::array* a = n->as_array();
        if (!a || !a->is_array_of_tables()) throw grader_error(place(file, *n) + ": write each sweep as [[sweep]]");
        for (const toml::node& e : *a) {
            const toml::table& s = *e.as_table();
            only_keys(file, s, "[[sweep]]",
                      {"test", "title", "category", "points", "x_label", "log_x", "stable_from", "stable_through",
                       "max_failure_rate", "visibility"});
            rubric_sweep w;
            w.test = text(file, s, "test", true, "[[sweep]]");
            if (!tests.insert(w.test).second) throw grader_error(place(file, e) + ": test '" + w.test + "' is graded twice");
            w.title = text(file, s, "title", false, "[[sweep]]");
            if (w.title.empty()) w.title = w.test;
            w.category = text(file, s, "category", true, "[[sweep]]");
            if (!categories.contains(w.category))
                throw grader_error(place(file, e) + ": sweep's category '" + w.category + "' is not a [[category]]");
            w.points = number(file, s, "points", 0);
            w.x_label = text(file, s, "x_label", true, "[[sweep]]");
            w.log_x = flag(file, s, "log_x");
            if (!s.get("stable_from") || !s.get("stable_through"))
                throw grader_error(place(file, e) + ": a [[sweep]] needs stable_from and stable_through: the values "
                                                    "over which a correct method must not fail");
            w.stable_from = number(file, s, "stable_from", 0);
            w.stable_through = number(file, s, "stable_through", 0);
            if (w.stable_from > w.stable_through)
                throw grader_error(place(file, e) + ": stable_from is above stable_through");
            w.max_failure_rate = number(file, s, "max_failure_rate", 0);
            if (w.max_failure_rate >= 1)
                throw grader_error(place(file, e) + ": max_failure_rate must be below 1 (a share of the trials)");
            const auto cat = std::find_if(r.categories.begin(), r.categories.end(),
                                          [&](const rubric_category& c) { return c.name == w.category; });
            w.visibility = visibility(file, s, cat->visibility);
            r.sweeps.push_back(w);
        }
    }
    if (const toml::node* n = t.get("chart")) {
        const toml::array* a = n->as_array();
        if (!a || !a->is_array_of_tables()) throw grader_error(place(file, *n) + ": write each chart as [[chart]]");
        for (const toml::node& e : *a) {
            const toml::table& s = *e.as_table();
            only_keys(file, s, "[[chart]]", {"test", "title", "x_label", "y_label", "log_x", "log_y"});
            rubric_chart c;
            c.test = text(file, s, "test", true, "[[chart]]");
            if (!tests.insert(c.test).second) throw grader_error(place(file, e) + ": test '" + c.test + "' is named twice");
            c.title = text(file, s, "title", false, "[[chart]]");
            if (c.title.empty()) c.title = c.test;
            c.x_label = text(file, s, "x_label", true, "[[chart]]");
            c.y_label = text(file, s, "y_label", true, "[[chart]]");
            c.log_x = flag(file, s, "log_x");
            c.log_y = flag(file, s, "log_y");
            r.charts.push_back(c);
        }
    }
    if (const toml::node* n = t.get("leaderboard")) {
        const toml::array* a = n->as_array();
        if (!a || !a->is_array_of_tables())
            throw grader_error(place(file, *n) + ": write each value of the leaderboard as [[leaderboard]]");
        for (const toml::node& e : *a) {
            const toml::table& s = *e.as_table();
            only_keys(file, s, "[[leaderboard]]", {"name", "chart", "series", "x", "order", "category"});
            rubric_leaderboard l;
            l.name = text(file, s, "name", true, "[[leaderboard]]");
            l.chart = text(file, s, "chart", true, "[[leaderboard]]");
            if (std::none_of(r.charts.begin(), r.charts.end(), [&](const rubric_chart& c) { return c.test == l.chart; }))
                throw grader_error(place(file, e) + ": chart '" + l.chart + "' is no [[chart]]'s test (a [[leaderboard]] "
                                                    "takes its value from a chart)");
            l.series = text(file, s, "series", true, "[[leaderboard]]");
            if (!s.get("x")) throw grader_error(place(file, e) + ": a [[leaderboard]] needs x, the point of the series");
            l.x = number(file, s, "x", 0);
            l.order = text(file, s, "order", false, "[[leaderboard]]");
            if (l.order.empty()) l.order = "asc";
            if (l.order != "asc" && l.order != "desc")
                throw grader_error(place(file, e) + ": order must be \"asc\" (smaller is better) or \"desc\", not \"" +
                                   l.order + "\"");
            l.category = text(file, s, "category", true, "[[leaderboard]]");
            if (std::none_of(r.categories.begin(), r.categories.end(),
                             [&](const rubric_category& c) { return c.name == l.category; }))
                throw grader_error(place(file, e) + ": category '" + l.category + "' is not a [[category]]");
            r.leaderboard.push_back(l);
        }
    }
}

}  // namespace

double rubric_category::weight_of(const test_case_info& t) const {
    if (const auto by_name = weights.find(t.name); by_name != weights.end()) return by_name->second;
    double w = -1;
    for (const std::string& tag : t.tags)
        if (const auto by_tag = weights.find(tag); by_tag != weights.end()) w = std::max(w, by_tag->second);
    return w < 0 ? 1 : w;
}

bool is_measurement(const test_case_info& t) {
    return std::find(t.tags.begin(), t.tags.end(), "sweep") != t.tags.end() ||
           std::find(t.tags.begin(), t.tags.end(), "chart") != t.tags.end();
}

const rubric_category* rubric::category_of(const test_case_info& t) const {
    if (is_measurement(t)) return nullptr;
    for (const rubric_category& c : categories) {
        if (std::find(c.tests.begin(), c.tests.end(), t.name) != c.tests.end()) return &c;
        for (const std::string& tag : c.tags)
            if (std::find(t.tags.begin(), t.tags.end(), tag) != t.tags.end()) return &c;
    }
    return nullptr;
}

rubric load_rubric(const fs::path& file, const fs::path& public_scenes, bool sanitized) {
    if (!fs::exists(file)) throw grader_error(file.string() + " is missing: every graded assignment needs a rubric");
    toml::table t;
    try {
        t = toml::parse_file(file.string());
    } catch (const toml::parse_error& e) {
        throw grader_error(file.string() + ":" + std::to_string(e.source().begin.line) + ":" +
                           std::to_string(e.source().begin.column) + ": " + std::string(e.description()));
    }
    rubric r;
    r.file = file;
    r.assignment = t["assignment"].value_or(std::string());
    r.title = t["title"].value_or(r.assignment);
    r.visibility = visibility(file, t, "after_published");
    r.total_points = number(file, t, "total_points", 0);
    if (const toml::table* l = t["limits"].as_table()) {
        r.test_limits.wall_seconds = number(file, *l, "test_timeout_seconds", 10);
        r.render_limits.wall_seconds = number(file, *l, "render_timeout_seconds", 60);
        const double mib = number(file, *l, "memory_mib", 1024);
        r.test_limits.memory_bytes = r.render_limits.memory_bytes = static_cast<std::uint64_t>(mib) << 20;
        r.grade_budget_seconds = number(file, *l, "grade_budget_seconds", 600);
    }
    r.render_limits.report_bytes = std::size_t{64} << 20;
    // The sanitizers' shadow memory and slower code need room.
    if (sanitized) {
        r.test_limits.wall_seconds *= 5;
        r.render_limits.wall_seconds *= 5;
        r.grade_budget_seconds *= 5;
    }
    std::set<std::string> names;
    if (const toml::array* cats = t["category"].as_array()) {
        for (const toml::node& n : *cats) {
            const toml::table& c = *n.as_table();
            rubric_category cat;
            cat.name = c["name"].value_or(std::string());
            if (cat.name.empty()) throw grader_error(place(file, n) + ": a [[category]] needs a name");
            if (!names.insert(cat.name).second) throw grader_error(place(file, n) + ": category '" + cat.name + "' twice");
            cat.title = c["title"].value_or(cat.name);
            cat.points = number(file, c, "points", 0);
            cat.tags = strings(file, c, "tags");
            cat.tests = strings(file, c, "tests");
            if (const toml::node* w = c.get("weights")) {
                const toml::table* wt = w->as_table();
                if (!wt) throw grader_error(place(file, *w) + ": 'weights' must be a table of tag or test name = number");
                for (const auto& [key, value] : *wt) {
                    const auto v = value.value<double>();
                    if (!v || *v < 0) throw grader_error(place(file, value) + ": the weight of '" + std::string(key.str()) +
                                                         "' must be a number, 0 or more");
                    cat.weights[std::string(key.str())] = *v;
                }
            }
            cat.visibility = visibility(file, c, r.visibility);
            cat.details = visibility(file, c, cat.details, "details");
            r.categories.push_back(cat);
        }
    }
    if (r.categories.empty()) throw grader_error(file.string() + ": no [[category]]: nothing would be graded");
    if (const toml::array* scenes = t["scene"].as_array()) {
        for (const toml::node& n : *scenes) {
            const toml::table& s = *n.as_table();
            only_keys(file, s, "[[scene]]",
                      {"file", "public", "title", "category", "points", "student_pieces", "metric", "threshold_levels",
                       "max_mean_difference", "max_flip_mean", "flip_pixel_level", "max_fraction_over", "visibility"});
            rubric_scene sc;
            sc.is_public = s["public"].value_or(false);
            sc.file = (sc.is_public ? public_scenes : file.parent_path() / "scenes") / s["file"].value_or(std::string());
            if (!fs::is_regular_file(sc.file)) throw grader_error(place(file, n) + ": scene " + sc.file.string() + " is missing");
            sc.id = (sc.is_public ? "public-" : "") + sc.file.stem().string();
            sc.student_pieces = strings(file, s, "student_pieces");
            for (const std::string& piece : sc.student_pieces) {
                const bool object = vl::registry::valid_name(piece);
                if (!object && piece != "camera" && !piece.starts_with("sampler:") && !piece.starts_with("tracer:"))
                    throw grader_error(place(file, n) + ": student_pieces names '" + piece +
                                       "': use camera, sampler:NAME, tracer:NAME or an object type such as SPHERE");
            }
            sc.title = s["title"].value_or(sc.file.stem().string());
            sc.category = s["category"].value_or(std::string());
            if (!names.contains(sc.category))
                throw grader_error(place(file, n) + ": scene's category '" + sc.category + "' is not a [[category]]");
            sc.points = number(file, s, "points", 0);
            sc.metric = s["metric"].value_or(std::string("mean_abs"));
            if (sc.metric != "mean_abs" && sc.metric != "flip")
                throw grader_error(place(file, n) + ": metric '" + sc.metric + "' is not one of flip, mean_abs");
            sc.threshold_levels = static_cast<int>(number(file, s, "threshold_levels", 8));
            sc.max_mean_difference = number(file, s, "max_mean_difference", 0.5);
            sc.max_flip_mean = number(file, s, "max_flip_mean", 0);
            sc.flip_pixel_level = number(file, s, "flip_pixel_level", 0.1);
            sc.max_fraction_over = number(file, s, "max_fraction_over", 0.005);
            if (sc.metric == "flip" && !(sc.max_flip_mean > 0 && sc.max_flip_mean < 1))
                throw grader_error(place(file, n) + ": metric = \"flip\" needs max_flip_mean in (0, 1): set it from the "
                                                    "spread that `grader/run calibrate-thresholds` measures");
            if (!(sc.flip_pixel_level > 0 && sc.flip_pixel_level < 1))
                throw grader_error(place(file, n) + ": flip_pixel_level must be in (0, 1)");
            if (!(sc.max_fraction_over >= 0 && sc.max_fraction_over < 1))
                throw grader_error(place(file, n) + ": max_fraction_over must be in [0, 1)");
            const auto cat = std::find_if(r.categories.begin(), r.categories.end(),
                                          [&](const rubric_category& c) { return c.name == sc.category; });
            sc.visibility = visibility(file, s, cat->visibility);
            r.scenes.push_back(sc);
        }
    }
    read_measurements(file, t, names, r);
    if (r.total_points > 0) {
        double sum = 0;
        for (const rubric_category& c : r.categories) sum += c.points;
        for (const rubric_scene& sc : r.scenes) sum += sc.points;
        for (const rubric_sweep& sw : r.sweeps) sum += sw.points;
        if (std::abs(sum - r.total_points) > 1e-9)
            throw grader_error(file.string() + ": the categories', scenes' and sweeps' points add up to " + std::to_string(sum) +
                               ", not total_points = " + std::to_string(r.total_points));
    }
    return r;
}

void check_rubric(const rubric& r, const std::vector<test_case_info>& tests) {
    std::string problems;
    auto find = [&](const std::string& name) {
        return std::find_if(tests.begin(), tests.end(), [&](const test_case_info& t) { return t.name == name; });
    };
    auto has_tag = [](const test_case_info& t, const char* tag) {
        return std::find(t.tags.begin(), t.tags.end(), tag) != t.tags.end();
    };
    for (const test_case_info& t : tests) {
        if (is_measurement(t)) {
            const bool swept = std::any_of(r.sweeps.begin(), r.sweeps.end(), [&](const rubric_sweep& s) { return s.test == t.name; });
            const bool charted = std::any_of(r.charts.begin(), r.charts.end(), [&](const rubric_chart& c) { return c.test == t.name; });
            if (has_tag(t, "sweep") && !swept) problems += "  sweep test '" + t.name + "' has no [[sweep]]\n";
            if (has_tag(t, "chart") && !charted) problems += "  chart test '" + t.name + "' has no [[chart]]\n";
        } else if (!r.category_of(t)) {
            problems += "  hidden test '" + t.name + "' is in no category\n";
        }
    }
    for (const rubric_sweep& s : r.sweeps) {
        const auto t = find(s.test);
        if (t == tests.end()) problems += "  [[sweep]] names test '" + s.test + "', which does not exist\n";
        else if (!has_tag(*t, "sweep")) problems += "  [[sweep]] names test '" + s.test + "', which is not tagged [sweep]\n";
    }
    for (const rubric_chart& c : r.charts) {
        const auto t = find(c.test);
        if (t == tests.end()) problems += "  [[chart]] names test '" + c.test + "', which does not exist\n";
        else if (!has_tag(*t, "chart")) problems += "  [[chart]] names test '" + c.test + "', which is not tagged [chart]\n";
    }
    for (const rubric_category& c : r.categories) {
        for (const std::string& name : c.tests)
            if (std::none_of(tests.begin(), tests.end(), [&](const test_case_info& t) { return t.name == name; }))
                problems += "  category '" + c.name + "' names test '" + name + "', which does not exist\n";
        double total_weight = 0;
        for (const test_case_info& t : tests)
            if (r.category_of(t) == &c) total_weight += c.weight_of(t);
        if (c.points > 0 && total_weight <= 0)
            problems += "  category '" + c.name + "' has " + std::to_string(c.points) + " points but no test that weighs\n";
        for (const auto& [key, weight] : c.weights) {
            const bool known = std::any_of(tests.begin(), tests.end(), [&](const test_case_info& t) {
                return t.name == key || std::find(t.tags.begin(), t.tags.end(), key) != t.tags.end();
            });
            if (!known) problems += "  category '" + c.name + "' weighs '" + key + "', which is no test's name or tag\n";
        }
    }
    if (!problems.empty()) throw grader_error(r.file.string() + " does not fit the hidden tests:\n" + problems);
}

}  // namespace vl::grader
