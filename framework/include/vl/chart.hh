#pragma once
/// \file
/// \brief Line charts drawn by gnuplot: a sweep's failure rate, cost against error, tests
/// per ray against N. The grader inlines the SVG in report.html; the standalone commands
/// write the SVG and a PNG beside it.
///
/// A chart is its series of (x, y) points. draw_chart writes three files that each stand
/// on their own: OUT.tsv (the numbers, one block per series, for any other tool),
/// OUT.gp (the gnuplot script that reads OUT.tsv, to restyle by hand) and, when gnuplot
/// is installed (Debian `gnuplot-nox`), OUT.svg and OUT.png.
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace vl {

/// \brief One curve of a chart.
struct chart_series {
    std::string name;                              ///< the legend's text
    std::vector<std::pair<double, double>> points; ///< (x, y), drawn in this order
    /// A measured reference is drawn as a line; what is compared with it (a submission's
    /// points) as marks over it.
    enum class style {
        line,           ///< a line through the points
        marks,          ///< a mark at each point, no line
        line_and_marks  ///< both
    };
    style look = style::line_and_marks;  ///< how the curve is drawn
    /// The colour: the palette entry of the series at this position in chart::series, so
    /// that marks over a line wear the line's colour; -1 (the default): its own position's.
    int colour_of = -1;
};

/// \brief A whole chart.
struct chart {
    std::string title;    ///< above the plot
    std::string x_label;  ///< under the x axis
    std::string y_label;  ///< beside the y axis
    bool log_x = false;   ///< x on a logarithmic scale (points with x <= 0 are left out)
    bool log_y = false;   ///< y on a logarithmic scale (points with y <= 0 are left out)
    std::optional<std::pair<double, double>> y_range;  ///< fixed y limits (a rate: 0 to 1), else gnuplot's
    std::vector<chart_series> series;  ///< the curves, in the legend's order (right of the plot; under it, in two columns, for more than 4)
    /// A range of x to shade (a sweep's "a correct method is stable here"), with its label.
    std::optional<std::pair<double, double>> band;
    std::string band_label;  ///< the band's legend text
    int width = 720;   ///< pixels across the PNG and the SVG's view box
    int height = 420;  ///< pixels down the PNG and the SVG's view box
};

/// \brief What draw_chart wrote.
struct chart_files {
    std::filesystem::path tsv;     ///< the numbers
    std::filesystem::path script;  ///< the gnuplot script
    std::filesystem::path svg;     ///< the SVG, empty without gnuplot
    std::filesystem::path png;     ///< the PNG, empty without gnuplot
    std::string svg_text;                         ///< the SVG itself, to inline in HTML
    std::string problem;                          ///< why there is no SVG/PNG, or ""
};

/// True when a gnuplot program is on PATH.
bool gnuplot_available();

/// Writes `out_stem`.tsv and .gp, and with gnuplot .svg and .png. Non-finite points and,
/// on a log axis, points <= 0 are left out (the TSV keeps them, as "nan"). Throws
/// vl::file_error when a file cannot be written; a failure of gnuplot itself is reported
/// in chart_files::problem, never thrown.
chart_files draw_chart(const chart& c, const std::filesystem::path& out_stem);

}  // namespace vl
