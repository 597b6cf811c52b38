#include "report_html.hh"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <sstream>

#include "safe_files.hh"

namespace vl::grader {

namespace fs = std::filesystem;

namespace {

/// A chart in one line, for a report read as text: each series' value at the largest x
/// it reaches, the submission's beside the reference's.
std::string chart_summary(const graded_chart& c) {
    if (c.mine.empty()) return {};
    auto last = [](const std::vector<chart_point>& points, const std::string& series) {
        const chart_point* best = nullptr;
        for (const chart_point& p : points)
            if (p.series == series && (best == nullptr || p.x > best->x)) best = &p;
        return best;
    };
    std::vector<std::string> order;
    for (const chart_point& p : c.mine)
        if (std::find(order.begin(), order.end(), p.series) == order.end()) order.push_back(p.series);
    auto g = [](double v) {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%.4g", v);
        return std::string(buf);
    };
    std::string out = "At the right end of the chart, yours (the reference's):";
    for (std::size_t k = 0; k < order.size(); ++k) {
        const chart_point* m = last(c.mine, order[k]);
        const chart_point* r = last(c.reference, order[k]);
        out += (k == 0 ? " " : "; ") + order[k] + " at " + g(m->x) + ": " + g(m->y);
        if (r != nullptr) out += " (" + g(r->y) + (r->x != m->x ? " at " + g(r->x) : "") + ")";
    }
    return out + ".";
}

std::string escape(const std::string& s) {
    std::string out;
    for (const char c : s) {
        switch (c) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            default: out += c;
        }
    }
    return out;
}

std::string base64(const std::string& bytes) {
    static constexpr char digits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    std::size_t i = 0;
    for (; i + 2 < bytes.size(); i += 3) {
        const unsigned v = (unsigned char)bytes[i] << 16 | (unsigned char)bytes[i + 1] << 8 | (unsigned char)bytes[i + 2];
        out += {digits[v >> 18], digits[(v >> 12) & 63], digits[(v >> 6) & 63], digits[v & 63]};
    }
    if (i + 1 == bytes.size()) {
        const unsigned v = (unsigned char)bytes[i] << 16;
        out += {digits[v >> 18], digits[(v >> 12) & 63], '=', '='};
    } else if (i + 2 == bytes.size()) {
        const unsigned v = (unsigned char)bytes[i] << 16 | (unsigned char)bytes[i + 1] << 8;
        out += {digits[v >> 18], digits[(v >> 12) & 63], digits[(v >> 6) & 63], '='};
    }
    return out;
}

std::string image_tag(const fs::path& png, const std::string& caption) {
    std::string body;
    if (!png.empty() && fs::exists(png)) {
        std::ifstream in(png, std::ios::binary);
        const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
        body = "<img src=\"data:image/png;base64," + base64(bytes) + "\" alt=\"" + escape(caption) + "\">";
    } else {
        body = "<div class=\"noimage\">no image</div>";
    }
    return "<figure>" + body + "<figcaption>" + escape(caption) + "</figcaption></figure>";
}

/// A chart's SVG, inlined (gnuplot wrote it: the grader's own file, never the student's).
std::string chart_tag(const fs::path& svg, const std::string& caption) {
    if (svg.empty() || !fs::exists(svg)) return "<p class=\"meta\">(no chart: " + escape(caption) + ")</p>";
    std::ifstream in(svg, std::ios::binary);
    std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    // Drop the XML prolog and the doctype: only the <svg> element belongs in HTML.
    if (const auto at = text.find("<svg"); at != std::string::npos) text.erase(0, at);
    return "<div class=\"chart\">" + text + "</div>";
}

std::string points(double x) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.4g", std::round(x * 100) / 100);
    return buf;
}

std::string percent(double score, double max) { return max > 0 ? std::to_string(std::lround(100 * score / max)) : "-"; }

std::string badge(item_result result) {
    std::string cls = result == item_result::passed ? "ok" : result == item_result::not_run ? "skip" : "bad";
    return "<span class=\"badge " + cls + "\">" + escape(to_string(result)) + "</span>";
}

constexpr const char* style = R"(
body { font: 15px/1.45 system-ui, sans-serif; margin: 2em auto; max-width: 70em; padding: 0 1em; color: #222; }
h1 { font-size: 1.5em; margin-bottom: .2em; } h2 { font-size: 1.2em; margin-top: 1.6em; border-bottom: 1px solid #ddd; }
.meta { color: #555; } .score { font-size: 2.2em; font-weight: 600; }
table { border-collapse: collapse; width: 100%; } td, th { padding: .3em .6em; text-align: left; vertical-align: top; }
tr + tr td { border-top: 1px solid #eee; } td.num { text-align: right; white-space: nowrap; font-variant-numeric: tabular-nums; }
.bar { background: #eee; width: 12em; height: .8em; border-radius: .4em; overflow: hidden; }
.bar span { display: block; height: 100%; background: #3a8f47; }
.badge { display: inline-block; min-width: 5.5em; text-align: center; border-radius: .3em; padding: 0 .4em; font-size: .85em; }
.ok { background: #dff3e1; color: #1d5e27; } .bad { background: #fbe0dd; color: #8c1d12; } .skip { background: #eee; color: #555; }
pre { background: #f6f6f6; padding: .6em; overflow-x: auto; font-size: .85em; white-space: pre-wrap; margin: .3em 0; }
.figures { display: flex; gap: 1em; flex-wrap: wrap; margin: .4em 0 1em; cursor: zoom-in; }
.figures.big { cursor: zoom-out; }
figure { margin: 0; } figure img { image-rendering: pixelated; width: 180px; border: 1px solid #ccc; display: block; }
.figures.big figure img { width: min(25em, 40vw); }
figcaption { font-size: .85em; color: #555; text-align: center; }
.noimage { width: 180px; height: 135px; display: flex; align-items: center; justify-content: center; background: #f2f2f2; color: #999; }
.notes li { color: #7a4b00; }
.chart svg { max-width: 100%; height: auto; display: block; margin: .4em 0; }
)";

}  // namespace

std::string report_html(const graded_submission& g) {
    std::ostringstream h;
    h << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n<title>" << escape(g.assignment)
      << ": " << points(g.score) << " / " << points(g.max_score) << "</title>\n<style>" << style
      << "</style></head><body>\n";
    h << "<h1>" << escape(g.title) << "</h1>\n<p class=\"meta\">" << escape(g.submission);
    if (!g.origin.empty()) h << " (" << escape(g.origin) << ")";
    h << "<br>graded " << escape(g.started_at) << " in " << points(g.seconds) << " s</p>\n";
    h << "<p class=\"score\">" << points(g.score) << " / " << points(g.max_score) << " <small>("
      << percent(g.score, g.max_score) << "%)</small></p>\n";
    if (!g.notes.empty()) {
        h << "<ul class=\"notes\">";
        for (const std::string& n : g.notes) h << "<li>" << escape(n) << "</li>";
        h << "</ul>\n";
    }

    h << "<h2>By category</h2>\n<table><tr><th>category</th><th></th><th class=\"num\">points</th><th "
         "class=\"num\">passed</th></tr>\n";
    for (const category_total& c : g.categories) {
        const double fill = c.max_score > 0 ? 100 * c.score / c.max_score : 100;
        h << "<tr><td>" << escape(c.title) << "</td><td><div class=\"bar\"><span style=\"width:" << fill
          << "%\"></span></div></td><td class=\"num\">" << points(c.score) << " / " << points(c.max_score)
          << "</td><td class=\"num\">" << c.passed << " of " << c.items << "</td></tr>\n";
    }
    h << "</table>\n";

    const graded_item& build = g.items.front();
    h << "<h2>Build " << badge(build.result) << "</h2>\n";
    if (!build.passed())
        h << (build.result == item_result::refused ? "<p>Why it was refused:</p><pre>" : "<p>The first errors:</p><pre>")
          << escape(build.message) << "</pre>\n";
    else h << "<p>Built in " << points(build.seconds) << " s, with the reference for every other stage.</p>\n";

    for (const category_total& c : g.categories) {
        h << "<h2>" << escape(c.title) << " <small>" << points(c.score) << " / " << points(c.max_score)
          << "</small></h2>\n<table>\n";
        for (const graded_item& i : g.items) {
            if (i.category != c.name) continue;
            h << "<tr><td>" << badge(i.result) << "</td><td>" << escape(i.name);
            if (std::find(i.tags.begin(), i.tags.end(), "public") != i.tags.end())
                h << " <small>(a public test: in your tests/)</small>";
            if (!i.passed() && !i.message.empty() && g.built) h << "<pre>" << escape(i.message) << "</pre>";
            // A passed test's message: the kit passes it too, or a budget's margin.
            if (i.passed() && i.what == graded_item::kind::test && !i.message.empty())
                h << "<br><small>" << escape(i.message) << "</small>";
            if (i.what == graded_item::kind::scene && g.built) {
                if (i.passed()) h << "<br><small>" << escape(i.message) << "</small>";
                h << "<div class=\"figures\" title=\"click to enlarge\">" << image_tag(i.image, "this submission")
                  << image_tag(i.reference_image, "reference")
                  << image_tag(i.flip_image, "FLIP error (dark: none)")
                  << image_tag(i.highlight_image, "differences in red") << "</div>";
            }
            if (i.what == graded_item::kind::sweep) {
                if (i.passed()) h << "<br><small>" << escape(i.message) << "</small>";
                h << chart_tag(i.chart_svg, "the sweep's chart needs gnuplot");
            }
            h << "</td><td class=\"num\">" << points(i.score) << " / " << points(i.max_score) << "</td></tr>\n";
        }
        h << "</table>\n";
    }
    if (!g.charts.empty()) {
        h << "<h2>Charts <small>(worth no points)</small></h2>\n";
        for (const graded_chart& c : g.charts) {
            h << "<h3>" << escape(c.title) << "</h3>\n";
            if (!c.message.empty()) h << "<p class=\"meta\">" << escape(c.message) << "</p>\n";
            if (const std::string line = chart_summary(c); !line.empty()) h << "<p>" << escape(line) << "</p>\n";
            h << chart_tag(c.svg, "gnuplot is not installed; the numbers are in " + c.tsv.filename().string());
        }
    }
    h << "<h2>How this was graded</h2>\n<p class=\"meta\">Each test ran on its own, decided by the grader's "
         "own process (the judge) while your code ran in another (the subject), each call between them crossing "
         "as data; only the judge's Catch2 report of each test counts, never what a program printed. Sandbox: "
      << escape(g.sandbox)
      << ".</p>\n"
         // A click on a scene's images shows all four large, pixels as squares (a half-pixel
         // shift shows); another click shows them small again.
         "<script>for (const f of document.querySelectorAll('.figures')) "
         "f.addEventListener('click', () => f.classList.toggle('big'));</script>\n</body></html>\n";
    return h.str();
}

void write_report_html(const graded_submission& g, const std::filesystem::path& file) { replace_file(file, report_html(g)); }

}  // namespace vl::grader
