#include "vl/chart.hh"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

#include "vl/error.hh"

extern char** environ;

namespace vl {

namespace fs = std::filesystem;

namespace {

/// `x` in the shortest form that reads back exactly; "nan" for what gnuplot must skip.
std::string number(double x) {
    if (!std::isfinite(x)) return "nan";
    std::array<char, 64> buf{};
    const auto r = std::to_chars(buf.data(), buf.data() + buf.size(), x);
    return std::string(buf.data(), r.ptr);
}

/// A gnuplot single-quoted string: nothing in it is interpreted but '' (one quote).
std::string quoted(const std::string& s) {
    std::string out = "'";
    for (const char c : s) {
        if (c == '\'') out += "''";
        else if (c == '\n' || c == '\r') out += ' ';
        else out += c;
    }
    return out + "'";
}

void write_text(const fs::path& p, const std::string& text) {
    std::ofstream f(p, std::ios::binary | std::ios::trunc);
    f << text;
    f.close();
    if (!f) throw file_error(p.string() + ": cannot write the chart file (" + std::strerror(errno) + ")");
}

std::string read_text(const fs::path& p) {
    std::ifstream f(p, std::ios::binary);
    std::ostringstream s;
    s << f.rdbuf();
    return s.str();
}

/// The colours of the series in order: distinguishable, and in print too.
constexpr std::array<const char*, 8> palette = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd",
                                                "#ff7f0e", "#17becf", "#8c564b", "#e377c2"};

/// The commands that draw the chart, after the terminal and the output are set.
std::string plot_commands(const chart& c, const fs::path& tsv) {
    std::ostringstream g;
    g << "set title " << quoted(c.title) << " noenhanced\n";
    g << "set xlabel " << quoted(c.x_label) << " noenhanced\n";
    g << "set ylabel " << quoted(c.y_label) << " noenhanced\n";
    g << "set datafile missing 'nan'\n";
    // Many series (a submission's marks beside the reference's lines): the legend goes
    // under the plot, in columns, so the plot keeps its width.
    if (c.series.size() > 4) g << "set key outside bottom center horizontal maxcols 2 noenhanced\n";
    else g << "set key outside right top noenhanced\n";
    g << "set grid\n";
    if (c.log_x) g << "set logscale x\nset format x '10^{%L}'\n";
    if (c.log_y) g << "set logscale y\nset format y '10^{%L}'\n";
    if (c.y_range) g << "set yrange [" << number(c.y_range->first) << ":" << number(c.y_range->second) << "]\n";
    if (c.band) {
        g << "set object 1 rect from " << number(c.band->first) << ", graph 0 to " << number(c.band->second)
          << ", graph 1 fillcolor rgb '#e6f2e6' fillstyle solid 1.0 noborder behind\n";
        if (!c.band_label.empty())
            g << "set label 1 " << quoted(c.band_label) << " at graph 0.02, graph 0.96 left noenhanced\n";
    }
    // On a log axis a value <= 0 cannot be drawn: it is left out (the TSV keeps it).
    const std::string x = c.log_x ? "($1 > 0 ? $1 : NaN)" : "1";
    const std::string y = c.log_y ? "($2 > 0 ? $2 : NaN)" : "2";
    std::string plots;
    for (std::size_t k = 0; k < c.series.size(); ++k) {
        const chart_series& s = c.series[k];
        const std::size_t entry = s.colour_of >= 0 ? static_cast<std::size_t>(s.colour_of) : k;
        const char* colour = palette[entry % palette.size()];
        std::string with;
        switch (s.look) {
            case chart_series::style::line: with = "lines linewidth 2"; break;
            case chart_series::style::marks: with = "points pointtype 6 pointsize 1.6 linewidth 2"; break;
            case chart_series::style::line_and_marks: with = "linespoints linewidth 2 pointtype 7 pointsize 0.8"; break;
        }
        plots += (plots.empty() ? "plot " : ", \\\n     ") + quoted(tsv.filename().string()) + " index " +
                 std::to_string(k) + " using " + x + ":" + y + " with " + with + " linecolor rgb '" + colour +
                 "' title " + quoted(s.name);
    }
    if (plots.empty()) plots = "set label 2 'no points' at graph 0.5, graph 0.5 center\nplot NaN notitle";
    g << plots << "\n";
    return g.str();
}

/// Runs gnuplot on `script` in the script's folder; "" or what went wrong.
std::string run_gnuplot(const fs::path& script) {
    const fs::path log = fs::path(script).replace_extension(".gnuplot.log");
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
    const std::string dir = script.parent_path().empty() ? "." : script.parent_path().string();
    const std::string name = script.filename().string();
    // gnuplot reads the data file by its name, relative to the script's folder.
    std::string program = "gnuplot";
    std::array<char*, 5> argv = {program.data(), const_cast<char*>("-e"), nullptr, nullptr, nullptr};
    std::string chdir_and_load = "cd " + quoted(dir) + "; load " + quoted(name);
    argv[2] = chdir_and_load.data();
    pid_t pid = 0;
    const int spawned = posix_spawnp(&pid, "gnuplot", &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (spawned != 0) return std::string("gnuplot could not be started: ") + std::strerror(spawned);
    int status = 0;
    while (waitpid(pid, &status, 0) < 0)
        if (errno != EINTR) return std::string("waiting for gnuplot failed: ") + std::strerror(errno);
    const std::string said = read_text(log);
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
        return "gnuplot failed on " + script.string() + ": " + said.substr(0, 600);
    std::error_code ec;
    if (said.empty()) fs::remove(log, ec);
    return "";
}

}  // namespace

bool gnuplot_available() {
    const char* path = std::getenv("PATH");
    std::string dirs = path != nullptr ? path : "/usr/bin:/bin";
    std::size_t start = 0;
    while (start <= dirs.size()) {
        const std::size_t end = std::min(dirs.find(':', start), dirs.size());
        const std::string dir = dirs.substr(start, end - start);
        if (!dir.empty() && ::access((fs::path(dir) / "gnuplot").c_str(), X_OK) == 0) return true;
        start = end + 1;
    }
    return false;
}

chart_files draw_chart(const chart& c, const fs::path& out_stem) {
    chart_files out;
    out.tsv = fs::path(out_stem).concat(".tsv");
    out.script = fs::path(out_stem).concat(".gp");
    const fs::path svg = fs::path(out_stem).concat(".svg"), png = fs::path(out_stem).concat(".png");

    std::ostringstream data;
    data << "# " << c.title << "\n# x: " << c.x_label << "\n# y: " << c.y_label << "\n";
    for (std::size_t k = 0; k < c.series.size(); ++k) {
        if (k > 0) data << "\n\n";  // gnuplot's `index` counts blocks split by two blank lines
        data << "# series " << k << ": " << c.series[k].name << "\n";
        for (const auto& [x, y] : c.series[k].points) data << number(x) << '\t' << number(y) << '\n';
    }
    write_text(out.tsv, data.str());

    const std::string commands = plot_commands(c, out.tsv);
    std::ostringstream script;
    script << "# Draws " << out.tsv.filename().string() << " (gnuplot " << out.script.filename().string()
           << "): an SVG, then a PNG of the same chart.\n";
    script << "set terminal svg size " << c.width << "," << c.height << " font 'sans,12' background rgb 'white'\n";
    script << "set output " << quoted(svg.filename().string()) << "\n" << commands;
    script << "set terminal pngcairo size " << c.width << "," << c.height << " font 'sans,10' background rgb 'white'\n";
    script << "set output " << quoted(png.filename().string()) << "\nreplot\nset output\n";
    write_text(out.script, script.str());

    if (!gnuplot_available()) {
        out.problem = "gnuplot is not installed (Debian: apt-get install gnuplot-nox); the numbers are in " +
                      out.tsv.string() + " and " + out.script.string() + " draws them";
        return out;
    }
    out.problem = run_gnuplot(out.script);
    if (out.problem.empty()) {
        out.svg = svg;
        out.png = png;
        out.svg_text = read_text(svg);
    }
    return out;
}

}  // namespace vl
