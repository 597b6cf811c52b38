// The pieces of the grader's render program (there it replaces the build's aggregate
// vl::register_all_pieces, pieces/all_pieces.cc.in): a graded scene is rendered with the
// submission's code for the pieces the rubric names in the scene's `student_pieces`, and
// with the reference's for every other piece, so a scene of one category depends only on
// that category's code.
//
// The grader names the pieces in the environment variable VL_GRADED_PIECES, a list of
// `camera`, `sampler:NAME`, `tracer:NAME` and object type names (`SPHERE`) separated by
// spaces. Without it (the reference renders) every piece is the linked stage code's.
// The reference's pieces of the graded stage come from its oracle, a second copy compiled
// into namespace vl::reference_stageNN so that it links beside the submission's
// vl::stageNN (vl_grader_oracle_library in cmake/grader.cmake), through its entry
// vl::graded::register_reference_pieces; the other stages' pieces are the linked code's,
// which is their reference.
//
// A render links no reference code of the pieces its scenes grade: the grader links one
// render program per set of graded pieces, without the oracle's objects that hold them
// (build_submission.cc, oracle.hh). The oracle's registration still names their
// functions; the grader binds each to vl_grader_withheld_reference below, which is all a
// call of them reaches. The grader names all those pieces in VL_GRADED_PIECES, so this
// file never asks the reference for one: if it did, the render stops as the grader's
// mistake (exit status 120, a line that starts with "grader:").
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

namespace {

/// The piece this file is asking the reference for, while it does (else nullptr).
thread_local const std::string* asking_reference = nullptr;

}  // namespace

/// What the functions of the pieces a render withholds are bound to (by the grader's link,
/// --defsym): they are called with their own arguments, which this never reads, and it
/// never returns.
extern "C" [[noreturn]] void vl_grader_withheld_reference() {
    if (const std::string* piece = asking_reference) {
        std::fprintf(stderr, "grader: VL_GRADED_PIECES leaves '%s' to the reference, which this render program does "
                             "not link\n", piece->c_str());
        std::_Exit(120);
    }
    std::fputs("this render program links no reference code of the pieces its scene grades: a call of it reached "
               "none\n", stderr);
    std::abort();
}

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
        graded::register_reference_pieces(out);
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

/// The registry piece `key` comes from: the submission's when the grader names it (or
/// names nothing), else the reference's oracle when it has the piece (`theirs_has`: a piece
/// of the graded stage), else the linked code (another stage's reference, the framework).
const registry& source_of(const std::string& key, bool theirs_has) {
    return chosen.everything || chosen.pieces.contains(key) || !theirs_has ? submission_pieces() : reference_pieces();
}

/// `make()`, a call of `from`'s factory for `key`; while the reference's runs, a call that
/// reaches a withheld piece's code names `key` as the grader's mistake.
template <class Make>
auto made(const registry& from, const std::string& key, Make make) {
    if (&from != &reference_pieces()) return make();
    struct restore {
        const std::string* before;
        ~restore() { asking_reference = before; }
    } guard{asking_reference};
    asking_reference = &key;
    return make();
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
        const registry& from = source_of(n, theirs.contains(n));
        r.add(n, [&from, n] { return made(from, n, [&] { return from.create(n); }); });
    }
    for (const std::string& n : both(mine.sampler_names(), theirs.sampler_names())) {
        const std::string key = "sampler:" + n;
        const registry& from = source_of(key, listed(theirs.sampler_names(), n));
        r.add_sampler(n, [&from, n, key] { return made(from, key, [&] { return from.make_sampler(n); }); });
    }
    for (const std::string& n : both(mine.tracer_names(), theirs.tracer_names())) {
        const std::string key = "tracer:" + n;
        const registry& from = source_of(key, listed(theirs.tracer_names(), n));
        r.add_tracer(n, [&from, n, key](const scene& s) { return made(from, key, [&] { return from.make_tracer(n, s); }); });
    }
    const registry& cameras = source_of("camera", theirs.has_camera());
    if (cameras.has_camera())
        r.set_camera([&cameras, key = std::string("camera")](const camera_settings& s, int w, int h) {
            return made(cameras, key, [&] { return cameras.make_camera(s, w, h); });
        });
}

}  // namespace vl
