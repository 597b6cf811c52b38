#include "thresholds.hh"

#include <toml++/toml.h>

#include <algorithm>
#include <cmath>

#include "external.hh"
#include "rubric.hh"
#include "vl/flip.hh"
#include "vl/image_io.hh"

namespace vl::grader {

namespace fs = std::filesystem;

namespace {

/// The correct alternatives among the stage's calibration cases: a folder of sources of
/// their own (no patch, no submission) that must score 100.
std::vector<std::string> alternatives(const installation& in, const stage_info& stage) {
    std::vector<std::string> names;
    const fs::path cases = in.source_dir / "grader" / "tests" / "submissions" / stage.name;
    if (!fs::is_directory(cases)) return names;
    for (const fs::directory_entry& e : fs::directory_iterator(cases)) {
        const fs::path expected = e.path() / "expected.toml";
        if (!fs::is_regular_file(expected)) continue;
        try {
            const toml::table t = toml::parse_file(expected.string());
            const toml::array* score = t["score_percent"].as_array();
            const bool full = score && score->size() == 2 && (*score)[0].value<double>().value_or(0) == 100;
            if (full && !t.contains("patch") && !t.contains("submission")) names.push_back(e.path().filename().string());
        } catch (const toml::parse_error&) {
            // The calibrate command reports a broken expected.toml; here it is simply no alternative.
        }
    }
    std::sort(names.begin(), names.end());
    return names;
}

/// `x` rounded up to two significant digits.
double round_up(double x) {
    if (!(x > 0)) return 0;
    const double unit = std::pow(10.0, std::floor(std::log10(x)) - 1);
    return std::ceil(x / unit - 1e-9) * unit;
}

threshold_variation compare(const std::string& name, const vl::image& reference, const fs::path& render, double level) {
    threshold_variation v;
    v.name = name;
    try {
        const vl::image mine = read_image(render);
        if (mine.width() != reference.width() || mine.height() != reference.height()) {
            v.problem = render.string() + " is " + std::to_string(mine.width()) + "x" + std::to_string(mine.height()) +
                        ", the reference " + std::to_string(reference.width()) + "x" + std::to_string(reference.height());
            return v;
        }
        const vl::flip_result f = vl::flip(reference, mine);
        std::size_t over = 0;
        for (const float e : f.error) over += e > level;
        v.flip_mean = f.mean;
        v.fraction_over = f.error.empty() ? 0 : static_cast<double>(over) / static_cast<double>(f.error.size());
    } catch (const std::exception& e) {
        v.problem = e.what();
    }
    return v;
}

}  // namespace

std::vector<scene_spread> measure_spread(const installation& in, const stage_info& stage, const fs::path& calibration,
                                         const fs::path& out, const std::vector<fs::path>& other_renderers) {
    const rubric r = load_rubric(in.hidden_dir(stage) / "rubric.toml", in.assignment_dir(stage) / "scenes", in.sanitized);
    fs::create_directories(out);
    const std::vector<std::string> cases = alternatives(in, stage);
    std::vector<scene_spread> spreads;
    for (const rubric_scene& s : r.scenes) {
        scene_spread sp;
        sp.id = s.id;
        sp.title = s.title;
        sp.metric = s.metric;
        sp.current_max_flip_mean = s.max_flip_mean;
        sp.current_max_fraction_over = s.max_fraction_over;
        const fs::path reference_png = in.reference_renders / stage.name / (s.id + ".png");
        const vl::image reference = read_image(reference_png);
        // The reference itself, on two threads and with other seeds of its random samplers.
        struct run {
            std::string name;
            fs::path renderer;
            std::vector<std::string> extra;
        };
        std::vector<run> runs = {{"threads 2", in.reference_renderer, {"--threads", "2"}},
                                 {"seed 1", in.reference_renderer, {"--threads", "1", "--seed", "1"}},
                                 {"seed 2", in.reference_renderer, {"--threads", "1", "--seed", "2"}}};
        for (std::size_t k = 0; k < other_renderers.size(); ++k)
            runs.push_back({"renderer " + std::to_string(k + 1) + " (" + other_renderers[k].string() + ")",
                            other_renderers[k],
                            {"--threads", "1"}});
        for (std::size_t k = 0; k < runs.size(); ++k) {
            const auto& [name, renderer, extra] = runs[k];
            const std::string tag = "variation-" + std::to_string(k + 1);
            const fs::path png = out / (s.id + "." + tag + ".png");
            std::vector<std::string> argv = {renderer.string(), s.file.string(), "-o", png.string()};
            argv.insert(argv.end(), extra.begin(), extra.end());
            const std::string problem = run_tool(argv, out / (s.id + "." + tag + ".log"), 600);
            if (!problem.empty()) throw grader_error("the reference renderer failed on " + s.file.string() + ": " + problem);
            sp.variations.push_back(compare(name, reference, png, s.flip_pixel_level));
        }
        // The correct alternatives, as the calibrate command rendered them.
        for (const std::string& c : cases) {
            const fs::path png = calibration / c / "renders" / (s.id + ".png");
            if (!fs::is_regular_file(png)) {
                threshold_variation v;
                v.name = c;
                v.problem = png.string() + " is missing: grade the case first (grader/run calibrate " +
                            (in.source_dir / "grader" / "tests" / "submissions" / stage.name / c).string() + ")";
                sp.variations.push_back(v);
                continue;
            }
            sp.variations.push_back(compare(c, reference, png, s.flip_pixel_level));
        }
        for (const threshold_variation& v : sp.variations) {
            if (!v.problem.empty()) continue;
            sp.max_flip_mean = std::max(sp.max_flip_mean, v.flip_mean);
            sp.max_fraction_over = std::max(sp.max_fraction_over, v.fraction_over);
        }
        sp.suggested_flip_mean = round_up(std::max(0.04, 2 * sp.max_flip_mean));
        sp.suggested_fraction = round_up(std::max(0.005, 2 * sp.max_fraction_over));
        spreads.push_back(sp);
    }
    return spreads;
}

}  // namespace vl::grader
