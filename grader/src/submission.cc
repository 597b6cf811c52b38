#include "submission.hh"

#include <algorithm>
#include <fstream>
#include <iterator>
#include <set>

namespace vl::grader {

namespace fs = std::filesystem;

namespace {

constexpr std::uintmax_t max_file_bytes = 1 << 20;  // a source file larger than 1 MiB is not a source file
constexpr int max_files = 200;

bool is_source(const fs::path& p) {
    static const std::set<std::string> kinds = {".cc", ".cpp", ".hh", ".h", ".hpp", ".inl"};
    return kinds.contains(p.extension().string());
}

bool has_cc(const fs::path& dir) {
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(dir, ec))
        if (e.is_regular_file() && !e.is_symlink() && e.path().extension() == ".cc") return true;
    return false;
}

std::string read_all(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// Unpacks an archive into `into` with tar or unzip, under the sandbox's limits (an
/// archive can be a bomb).
void unpack(const fs::path& archive, const fs::path& into, const sandbox_capabilities& caps) {
    const std::string name = archive.filename().string();
    run_request rq;
    if (name.ends_with(".zip")) {
        rq.argv = {"/usr/bin/unzip", "-q", "-o", fs::absolute(archive).string(), "-d", into.string()};
    } else if (name.ends_with(".tar.gz") || name.ends_with(".tgz") || name.ends_with(".tar")) {
        rq.argv = {"/bin/tar", "-xf", fs::absolute(archive).string(), "-C", into.string(), "--no-same-owner",
                   "--no-same-permissions"};
    } else {
        throw submission_error(name + " is neither a folder nor a .zip, .tar.gz or .tar archive");
    }
    rq.cwd = into;
    rq.output = into.parent_path() / "unpack.log";
    rq.environment = child_environment(into);
    rq.limits.wall_seconds = 60;
    rq.limits.file_bytes = std::uint64_t{64} << 20;
    give_to_sandbox(into, caps);
    const run_result r = run(rq, caps);
    if (!r.succeeded())
        throw submission_error("could not unpack " + name + " (" + r.describe(60) + "): " + read_head(rq.output, 600));
}

/// The folder holding the stage's .cc files: the tree itself, assignments/NN-name in a
/// kit, a folder NN-name, or the same inside the one folder an archive wraps it in.
fs::path find_stage_dir(const fs::path& root, const std::string& stage, bool& is_kit, int depth = 0) {
    if (fs::is_directory(root / "assignments" / stage)) {
        is_kit = true;
        return root / "assignments" / stage;
    }
    if (has_cc(root)) return root;
    if (fs::is_directory(root / stage) && has_cc(root / stage)) return root / stage;
    std::vector<fs::path> dirs;
    for (const auto& e : fs::directory_iterator(root))
        if (e.is_directory() && !e.is_symlink() && e.path().filename().string()[0] != '.' &&
            e.path().filename() != "__MACOSX")
            dirs.push_back(e.path());
    if (dirs.size() == 1 && depth < 3) return find_stage_dir(dirs.front(), stage, is_kit, depth + 1);
    return {};
}

}  // namespace

prepared_submission prepare_submission(const fs::path& submission, const stage_info& stage, const installation& in,
                                       const fs::path& scratch, const sandbox_capabilities& caps) {
    if (!fs::exists(submission)) throw grader_error(submission.string() + ": no such file or folder");
    prepared_submission p;
    fs::create_directories(scratch);
    fs::path root = submission;
    if (!fs::is_directory(submission)) {
        root = scratch / "unpacked";
        fs::create_directories(root);
        unpack(submission, root, caps);
    }
    bool is_kit = false;
    const fs::path stage_dir = find_stage_dir(root, stage.name, is_kit);
    if (stage_dir.empty() || !has_cc(stage_dir))
        throw submission_error("found no .cc files for " + stage.name + " in " + submission.filename().string() +
                               ": hand in the folder assignments/" + stage.name + " (or the whole kit)");
    const std::string where = fs::relative(stage_dir, root).string();
    p.origin = (is_kit ? "a student kit; graded " : "graded ") + (where == "." ? std::string("its top folder") : where);
    if (is_kit) {
        for (const auto& [name, s] : in.stages)
            if (name != stage.name && has_cc(root / "assignments" / name)) p.kit_stages.push_back(name);
    }

    p.sources = scratch / "submission";
    p.contract = scratch / "contract";
    fs::create_directories(p.sources);
    fs::create_directories(p.contract);
    int copied = 0;
    for (const auto& e : fs::directory_iterator(stage_dir)) {
        if (e.is_symlink() || !e.is_regular_file() || !is_source(e.path())) continue;
        if (e.file_size() > max_file_bytes) {
            p.notes.push_back(e.path().filename().string() + " is larger than 1 MiB and was left out");
            continue;
        }
        if (++copied > max_files) throw submission_error("more than 200 source files: is this the right folder?");
        fs::copy_file(e.path(), p.sources / e.path().filename());
    }
    // The pristine contract: copied aside (it comes first on the include path) and the
    // student's copy removed, so an edited contract cannot change what is graded.
    for (const auto& e : fs::directory_iterator(in.assignment_dir(stage))) {
        if (!e.is_regular_file() || e.path().extension() != ".hh") continue;
        const fs::path name = e.path().filename();
        fs::copy_file(e.path(), p.contract / name);
        if (fs::exists(p.sources / name)) {
            if (read_all(p.sources / name) != read_all(e.path()))
                p.notes.push_back("your " + name.string() + " differs from the original; the original was used");
            fs::remove(p.sources / name);
        }
    }
    return p;
}

}  // namespace vl::grader
