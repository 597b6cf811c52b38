#include "terminal_summary.hh"

#include <sstream>

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ostream>
#include <string>
#include <vector>

namespace vl::grader {

namespace {

std::string fixed(double x, int decimals = 1) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, x);
    return buf;
}

std::string first_line(const std::string& s, std::size_t width = 110) {
    const std::string line = s.substr(0, s.find('\n'));
    return line.size() > width ? line.substr(0, width - 3) + "..." : line;
}

}  // namespace

bool stdout_wants_colour() { return isatty(STDOUT_FILENO) && !std::getenv("NO_COLOR"); }

void print_summary(std::ostream& s, const graded_submission& g, const std::filesystem::path& out, bool colour) {
    const char* green = colour ? "\033[32m" : "";
    const char* red = colour ? "\033[31m" : "";
    const char* bold = colour ? "\033[1m" : "";
    const char* dim = colour ? "\033[2m" : "";
    const char* reset = colour ? "\033[0m" : "";
    auto tint = [&](double score, double max) { return score >= max - 1e-9 ? green : red; };

    s << bold << g.assignment << reset << "  " << g.submission << "\n";
    s << "  score " << tint(g.score, g.max_score) << bold << fixed(g.score) << " / " << fixed(g.max_score) << reset
      << " (" << (g.max_score > 0 ? std::lround(100 * g.score / g.max_score) : 0) << "%)  " << dim << "in "
      << fixed(g.seconds) << " s" << reset << "\n";
    if (!g.built) {
        const bool refused = g.items.front().result == item_result::refused;
        s << "  " << red << (refused ? "refused:" : "did not build:") << reset << " " << first_line(g.items.front().message)
          << "\n";
        // What follows the first line: for a refusal, its reasons (one per line, indented,
        // as the report gives them); for a build, the compiler's or the linker's next lines,
        // so that the first error itself is on screen, not only the context before it.
        constexpr std::size_t most_lines = 6;
        std::vector<std::string> rest;
        std::istringstream lines(g.items.front().message);
        std::string line;
        std::getline(lines, line);
        while (std::getline(lines, line)) {
            if (refused && !line.starts_with("  ")) break;
            if (line.find_first_not_of(' ') != std::string::npos)
                rest.push_back(refused ? line : "  " + first_line(line, 160));
        }
        for (std::size_t k = 0; k < rest.size() && k < most_lines; ++k) s << "  " << dim << rest[k] << reset << "\n";
        if (rest.size() > most_lines)
            s << "    " << dim << "... and " << rest.size() - most_lines << " more lines in the report" << reset << "\n";
    }
    for (const category_total& c : g.categories)
        s << "  " << tint(c.score, c.max_score) << fixed(c.score) << " / " << fixed(c.max_score) << reset << "  "
          << c.title << dim << "  (" << c.passed << " of " << c.items << " passed)" << reset << "\n";
    if (g.built) {
        int shown = 0;
        for (const graded_item& i : g.items) {
            if (i.passed() || i.what == graded_item::kind::build) continue;
            if (++shown > 8) continue;
            s << "  " << red << to_string(i.result) << reset << ": " << i.name << "\n      " << dim << first_line(i.message)
              << reset << "\n";
        }
        if (shown > 8) s << "  ... and " << shown - 8 << " more in the report\n";
    }
    for (const std::string& n : g.notes) s << "  note: " << n << "\n";
    s << "  results " << (out / "results.json").string() << "\n  report  " << (out / "report.html").string() << "\n";
}

}  // namespace vl::grader
