// The pieces of the grader's render program (there it replaces the build's aggregate
// vl::register_all_pieces, pieces/all_pieces.cc.in): a graded scene is rendered with the
// submission's code for the pieces the rubric names in the scene's `student_pieces`, and
// with the reference's for every other piece, so a scene of one category depends only on
// that category's code.
//
// The grader names the pieces in the environment variable VL_GRADED_PIECES, a list of
// `camera`, `sampler:NAME`, `tracer:NAME` and object type names (`SPHERE`) separated by
// spaces. Without it (the reference renders) every piece is the linked stage code's.
// The reference's copy of each stage is compiled into namespace vl::reference_stageNN
// (grader/CMakeLists.txt), so it links beside the submission's vl::stageNN; the stages are
// those the build declares (graded_stages.hh, generated from graded_stages.hh.in).
//
// The selection is read while the program starts, before any of the submission's code
// runs: this file comes first on the link line, so its initialisers run first.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "all_pieces.hh"
#include "graded_stages.hh"
#include "vl/registry.hh"

namespace vl {

namespace {

struct selection {
    bool everything = true;         // no VL_GRADED_PIECES: all pieces are the linked code's
    std::set<std::string> pieces;   // else: these are the submission's, the rest the reference's
};

selection read_selection() {
    selection s;
    if (const char* names = std::getenv("VL_GRADED_PIECES")) {
        s.everything = false;
        std::istringstream in(names);
        for (std::string name; in >> name;) s.pieces.insert(name);
    }
    return s;
}

const selection chosen = read_selection();

const registry& submission_pieces() {
    static const registry r = [] {
        registry out;
        register_framework(out);
        graded::register_linked_stages(out);
        return out;
    }();
    return r;
}

const registry& reference_pieces() {
    static const registry r = [] {
        registry out;
        register_framework(out);
        graded::register_reference_stages(out);
        return out;
    }();
    return r;
}

bool listed(const std::vector<std::string>& names, const std::string& name) {
    return std::find(names.begin(), names.end(), name) != names.end();
}

/// The names in `a` or `b`, sorted, each once.
std::set<std::string> both(const std::vector<std::string>& a, const std::vector<std::string>& b) {
    std::set<std::string> out(a.begin(), a.end());
    out.insert(b.begin(), b.end());
    return out;
}

/// The registry piece `key` comes from.
const registry& source_of(const std::string& key) {
    return chosen.everything || chosen.pieces.contains(key) ? submission_pieces() : reference_pieces();
}

}  // namespace

void register_all_pieces(registry& r) {
    const registry& mine = submission_pieces();
    const registry& theirs = reference_pieces();
    // A piece the grader names that no stage has is the grader's mistake: say so, and
    // stop with the code the grader recognises as its own failure.
    for (const std::string& key : chosen.pieces) {
        const bool known = key == "camera"                 ? mine.has_camera()
                           : key.starts_with("sampler:") ? listed(mine.sampler_names(), key.substr(8))
                           : key.starts_with("tracer:")  ? listed(mine.tracer_names(), key.substr(7))
                                                         : mine.contains(key);
        if (!known) {
            std::fprintf(stderr, "grader: VL_GRADED_PIECES names '%s', which no stage registers\n", key.c_str());
            std::_Exit(120);
        }
    }
    for (const std::string& n : both(mine.names(), theirs.names())) {
        const registry& from = source_of(n).contains(n) ? source_of(n) : mine;
        r.add(n, [&from, n] { return from.create(n); });
    }
    for (const std::string& n : both(mine.sampler_names(), theirs.sampler_names())) {
        const registry& from = source_of("sampler:" + n);
        r.add_sampler(n, [&from, n] { return from.make_sampler(n); });
    }
    for (const std::string& n : both(mine.tracer_names(), theirs.tracer_names())) {
        const registry& from = source_of("tracer:" + n);
        r.add_tracer(n, [&from, n](const scene& s) { return from.make_tracer(n, s); });
    }
    const registry& cameras = source_of("camera");
    if (cameras.has_camera())
        r.set_camera([&cameras](const camera_settings& s, int w, int h) { return cameras.make_camera(s, w, h); });
}

}  // namespace vl
