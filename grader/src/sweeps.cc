#include "sweeps.hh"

#include <charconv>
#include <cmath>
#include <map>
#include <sstream>

namespace vl::grader {

namespace {

std::string trim(const std::string& s) {
    const auto first = s.find_first_not_of(" \t\n\r");
    if (first == std::string::npos) return {};
    return s.substr(first, s.find_last_not_of(" \t\n\r") - first + 1);
}

/// The value of `key=` in `line` up to the next space (or the rest, for the last key).
bool field(const std::string& line, const std::string& key, std::string& out, bool rest = false) {
    const std::string k = " " + key + "=";
    const auto at = (" " + line).find(k);
    if (at == std::string::npos) return false;
    const auto start = at + k.size() - 1;
    const auto end = rest ? std::string::npos : line.find(' ', start);
    out = line.substr(start, end == std::string::npos ? std::string::npos : end - start);
    return true;
}

bool parse(const std::string& s, double& v) {
    if (s == "infinity") v = HUGE_VAL;
    else if (s == "-infinity") v = -HUGE_VAL;
    else if (s == "NaN") v = NAN;
    else {
        const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
        return r.ec == std::errc() && r.ptr == s.data() + s.size();
    }
    return true;
}

bool parse(const std::string& s, long long& v) {
    const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
    return r.ec == std::errc() && r.ptr == s.data() + s.size() && v >= 0;
}

std::string num(double x) {
    std::ostringstream s;
    s.precision(6);
    s << x;
    return s.str();
}

std::string percent(double rate) {
    std::ostringstream s;
    s.precision(3);
    s << 100 * rate << "%";
    return s.str();
}

}  // namespace

measured_points read_points(const std::vector<std::string>& warnings) {
    measured_points m;
    for (const std::string& raw : warnings) {
        const std::string w = trim(raw);
        std::string a, b, c, d;
        if (w.starts_with("vl-sweep ")) {
            sweep_point p;
            const std::string line = w.substr(9);
            if (!field(line, "x", a) || !field(line, "trials", b) || !field(line, "failures", c) || !parse(a, p.x) ||
                !parse(b, p.trials) || !parse(c, p.failures) || p.failures > p.trials) {
                m.problem = "a sweep point that cannot be read: " + w.substr(0, 200);
                return m;
            }
            if (field(line, "example", d, true)) p.example = d.substr(0, 400);
            m.sweep.push_back(p);
        } else if (w.starts_with("vl-chart ")) {
            chart_point p;
            const std::string line = w.substr(9);
            if (!field(line, "series", p.series) || !field(line, "x", a) || !field(line, "y", b) || !parse(a, p.x) ||
                !parse(b, p.y) || p.series.empty()) {
                m.problem = "a chart point that cannot be read: " + w.substr(0, 200);
                return m;
            }
            m.chart.push_back(p);
        }
    }
    return m;
}

sweep_verdict judge_sweep(const rubric_sweep& s, const std::vector<sweep_point>& mine,
                          const std::vector<sweep_point>& reference) {
    sweep_verdict v;
    if (mine.size() != reference.size()) {
        v.message = "the sweep's report does not match the test: " + std::to_string(mine.size()) + " values reported, " +
                    std::to_string(reference.size()) + " expected";
        return v;
    }
    for (std::size_t k = 0; k < mine.size(); ++k)
        if (mine[k].x != reference[k].x || mine[k].trials != reference[k].trials) {
            v.message = "the sweep's report does not match the test at value " + std::to_string(k + 1) + " (" +
                        s.x_label + " = " + num(mine[k].x) + " with " + std::to_string(mine[k].trials) +
                        " trials; expected " + num(reference[k].x) + " with " + std::to_string(reference[k].trials) + ")";
            return v;
        }
    long long trials = 0, failures = 0;
    int values = 0;
    std::string first_bad;
    for (const sweep_point& p : mine) {
        if (!(p.x >= s.stable_from && p.x <= s.stable_through)) continue;
        ++values;
        trials += p.trials;
        failures += p.failures;
        if (first_bad.empty() && p.rate() > s.max_failure_rate) {
            first_bad = "at " + s.x_label + " = " + num(p.x) + ", " + std::to_string(p.failures) + " of " +
                        std::to_string(p.trials) + " trials failed (" + percent(p.rate()) + "; a correct method fails " +
                        (s.max_failure_rate > 0 ? "at most " + percent(s.max_failure_rate) : std::string("none")) +
                        " from " + num(s.stable_from) + " to " + num(s.stable_through) + ")";
            if (!p.example.empty()) first_bad += "\nfor example: " + p.example;
        }
    }
    // Where the values outside the stable range fail, say so: it shows where the method breaks.
    std::string beyond;
    for (const sweep_point& p : mine)
        if (!(p.x >= s.stable_from && p.x <= s.stable_through) && p.failures > 0) {
            beyond = "; outside that range (not graded) it first fails at " + s.x_label + " = " + num(p.x);
            break;
        }
    v.passed = first_bad.empty();
    v.message = v.passed ? "stable at all " + std::to_string(values) + " values from " + num(s.stable_from) + " to " +
                               num(s.stable_through) + " (" + std::to_string(failures) + " of " +
                               std::to_string(trials) + " trials failed)" + beyond
                         : first_bad;
    return v;
}

vl::chart sweep_chart(const rubric_sweep& s, const std::vector<sweep_point>& mine,
                      const std::vector<sweep_point>& reference, const std::string& whose) {
    vl::chart c;
    c.title = s.title;
    c.x_label = s.x_label;
    c.y_label = "share of trials that failed";
    c.log_x = s.log_x;
    c.y_range = {{-0.03, 1.03}};
    c.band = {{s.stable_from, s.stable_through}};
    c.band_label = "a correct method is stable here";
    vl::chart_series ref{"reference", {}, vl::chart_series::style::line_and_marks};
    for (const sweep_point& p : reference) ref.points.push_back({p.x, p.rate()});
    c.series.push_back(ref);
    if (!whose.empty()) {
        vl::chart_series sub{whose, {}, vl::chart_series::style::marks};
        for (const sweep_point& p : mine) sub.points.push_back({p.x, p.rate()});
        c.series.push_back(sub);
    }
    return c;
}

vl::chart measured_chart(const rubric_chart& r, const std::vector<chart_point>& mine,
                         const std::vector<chart_point>& reference, const std::string& whose) {
    vl::chart c;
    c.title = r.title;
    c.x_label = r.x_label;
    c.y_label = r.y_label;
    c.log_x = r.log_x;
    c.log_y = r.log_y;
    // A submission's series wears the colour of the reference's series of that name.
    std::map<std::string, int> colour;
    auto add = [&](const std::vector<chart_point>& points, const std::string& prefix, vl::chart_series::style look) {
        std::vector<std::string> order;
        std::map<std::string, vl::chart_series> by;
        for (const chart_point& p : points) {
            if (!by.contains(p.series)) {
                order.push_back(p.series);
                by[p.series] = {prefix + p.series, {}, look};
            }
            by[p.series].points.push_back({p.x, p.y});
        }
        for (const std::string& name : order) {
            if (const auto known = colour.find(name); known != colour.end()) by[name].colour_of = known->second;
            else colour[name] = static_cast<int>(c.series.size());
            c.series.push_back(by[name]);
        }
    };
    add(reference, "reference: ", vl::chart_series::style::line_and_marks);
    if (!whose.empty()) add(mine, whose + ": ", vl::chart_series::style::marks);
    if (c.series.size() > 4) c.height = 520;  // the legend goes under the plot
    return c;
}

}  // namespace vl::grader
