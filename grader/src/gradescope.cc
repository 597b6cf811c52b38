#include "gradescope.hh"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>

#include "sandbox.hh"

namespace vl::grader {

namespace fs = std::filesystem;

namespace {

/// What a grade never reads: CI's script, the benchmarks (the preset `grader` builds
/// none), the student kit's README (export-kit's), the documentation but the two files the
/// configure step reads (docs/CMakeLists.txt and the Doxyfile it configures).
const std::vector<std::string> left_out = {".ci/", "bench/", "kit/", "docs/"};
const std::vector<std::string> kept_anyway = {"docs/CMakeLists.txt", "docs/Doxyfile.in"};

/// The bundle's own files, at the top of the zip: Gradescope runs the first two.
const char* const setup_script = "setup.sh";
const char* const run_script = "run_autograder";
const char* const config_file = "autograder.conf";
/// Where their sources are in the project.
const char* const scripts_dir = "grader/gradescope";

/// Every file of the bundle has this time (2000-01-01 00:00 UTC), so the zip's bytes
/// depend only on the files' contents, names and modes.
constexpr time_t fixed_time = 946684800;

bool needed_for_grading(const std::string& name) {
    const std::string top = name.substr(0, name.find('/'));
    if (top == "build" || top == ".git") return false;
    if (std::find(kept_anyway.begin(), kept_anyway.end(), name) != kept_anyway.end()) return true;
    return std::none_of(left_out.begin(), left_out.end(), [&](const std::string& p) { return name.starts_with(p); });
}

/// `name` on PATH, or empty.
fs::path on_path(const std::string& name) {
    const char* path = std::getenv("PATH");
    const std::string dirs = path ? path : "/usr/bin:/bin";
    for (std::size_t start = 0; start <= dirs.size();) {
        const std::size_t end = std::min(dirs.find(':', start), dirs.size());
        const fs::path candidate = fs::path(dirs.substr(start, end - start)) / name;
        if (!candidate.parent_path().empty() && access(candidate.c_str(), X_OK) == 0) return candidate;
        start = end + 1;
    }
    return {};
}

/// Runs a trusted program of the host (git, zip) in `cwd`; its output on success.
run_result run_tool(std::vector<std::string> argv, const fs::path& cwd, double seconds) {
    run_request rq;
    rq.argv = std::move(argv);
    rq.cwd = cwd.string();
    rq.environment = child_environment(cwd.string(), {"TZ=UTC", "LC_ALL=C"});
    rq.sandboxed = false;
    rq.limits.wall_seconds = seconds;
    rq.limits.output_bytes = std::size_t{64} << 20;
    return run(rq, sandbox_capabilities{});
}

/// The NUL-separated names git printed.
std::vector<std::string> split_nul(const std::string& text) {
    std::vector<std::string> names;
    for (std::size_t start = 0; start < text.size();) {
        const std::size_t end = std::min(text.find('\0', start), text.size());
        if (end > start) names.push_back(text.substr(start, end - start));
        start = end + 1;
    }
    return names;
}

/// `git -C source_dir ls-files -z ARGS...`, or a grader_error saying what git said.
std::vector<std::string> git_files(const fs::path& git, const fs::path& source_dir, std::vector<std::string> args) {
    std::vector<std::string> argv = {git.string(), "-C", source_dir.string(), "ls-files", "-z"};
    argv.insert(argv.end(), args.begin(), args.end());
    const run_result r = run_tool(argv, source_dir, 120);
    if (!r.succeeded())
        throw grader_error(source_dir.string() + " is a git checkout, but `git ls-files` failed there (" +
                           r.describe(120) + "): " + r.output_head(600) +
                           " -- the bundle takes its files from git; if git calls the folder unsafe, run "
                           "git config --global --add safe.directory " + source_dir.string());
    return split_nul(r.output);
}

/// A regular file of the tree (not a link, not a folder).
bool is_regular(const fs::path& p) {
    std::error_code ec;
    return fs::symlink_status(p, ec).type() == fs::file_type::regular;
}

/// Gives `file` mode 0755 or 0644 and the fixed time.
void fix_mode_and_time(const fs::path& file, bool executable) {
    const timespec times[2] = {{fixed_time, 0}, {fixed_time, 0}};
    if (chmod(file.c_str(), executable ? 0755 : 0644) != 0 || utimensat(AT_FDCWD, file.c_str(), times, 0) != 0)
        throw grader_error("cannot set the mode and time of " + file.string() + ": " + std::strerror(errno));
}

/// Copies `from` to `to`, executable when `from` is executable by its owner.
void stage_file(const fs::path& from, const fs::path& to) {
    std::error_code ec;
    fs::create_directories(to.parent_path(), ec);
    if (!ec) fs::copy_file(from, to, fs::copy_options::overwrite_existing, ec);
    if (ec) throw grader_error("cannot copy " + from.string() + " into the bundle (" + to.string() + "): " + ec.message());
    struct stat st {};
    fix_mode_and_time(to, stat(from.c_str(), &st) == 0 && (st.st_mode & S_IXUSR) != 0);
}

/// A folder of the grader's own, removed with everything in it when it goes out of scope.
struct scratch_folder {
    fs::path path;
    explicit scratch_folder(fs::path p) : path(std::move(p)) {
        std::error_code ec;
        fs::remove_all(path, ec);
        fs::create_directories(path, ec);
        if (ec) throw grader_error("cannot make " + path.string() + ": " + ec.message() + " (is TMPDIR writable?)");
    }
    ~scratch_folder() {
        std::error_code ec;
        fs::remove_all(path, ec);
    }
    scratch_folder(const scratch_folder&) = delete;
    scratch_folder& operator=(const scratch_folder&) = delete;
};

}  // namespace

std::string gradescope_bundle::summary() const {
    std::string s = "Gradescope bundle: " + zip.string() + "\ngrades " + assignment + "; holds setup.sh, run_autograder, " +
                    config_file + " and " + std::to_string(files) + " project files (" +
                    (from_git ? "the checkout's git ls-files" : "every file of the tree but build/") + ")\n";
    if (untracked_count > 0) {
        s += "left out, as git does not track them (git add what grading needs, then make the bundle again):";
        for (const std::string& u : untracked) s += " " + u;
        s += untracked_count > untracked.size() ? " ...\n" : "\n";
    }
    return s + "upload it on Gradescope: the assignment's Configure Autograder page, Zip file upload "
               "(grader/README.md, \"Gradescope\")\n";
}

std::vector<fs::path> bundle_files(const fs::path& source_dir, gradescope_bundle& bundle) {
    std::vector<std::string> names;
    std::error_code ec;
    const fs::path git = on_path("git");
    bundle.from_git = fs::exists(fs::symlink_status(source_dir / ".git", ec)) && !git.empty();
    if (bundle.from_git) {
        names = git_files(git, source_dir, {"--cached"});
        std::vector<std::string> untracked = git_files(git, source_dir, {"--others", "--exclude-standard"});
        std::erase_if(untracked, [](const std::string& n) { return !needed_for_grading(n); });
        bundle.untracked_count = untracked.size();
        untracked.resize(std::min<std::size_t>(untracked.size(), 5));
        bundle.untracked = untracked;
    } else {
        for (auto it = fs::recursive_directory_iterator(source_dir, ec); !ec && it != fs::recursive_directory_iterator();
             it.increment(ec)) {
            const std::string name = fs::relative(it->path(), source_dir).generic_string();
            const bool holds_kept = std::any_of(kept_anyway.begin(), kept_anyway.end(),
                                                [&](const std::string& k) { return k.starts_with(name + "/"); });
            if (it->is_directory() && !it->is_symlink() && !needed_for_grading(name + "/") && !holds_kept) {
                it.disable_recursion_pending();
                continue;
            }
            names.push_back(name);
        }
        if (ec) throw grader_error("cannot list " + source_dir.string() + ": " + ec.message());
    }
    std::vector<fs::path> files;
    for (const std::string& n : names)
        // A tracked file deleted from the work tree is not in the bundle, as it is not in a build.
        if (needed_for_grading(n) && is_regular(source_dir / n)) files.emplace_back(n);
    std::sort(files.begin(), files.end());
    files.erase(std::unique(files.begin(), files.end()), files.end());
    return files;
}

gradescope_bundle write_gradescope_bundle(const installation& in, const stage_info& stage, const fs::path& zip_arg) {
    gradescope_bundle bundle;
    bundle.assignment = stage.name;
    bundle.zip = fs::absolute(zip_arg).lexically_normal();
    if (bundle.zip.extension() != ".zip")
        throw grader_error(zip_arg.string() + ": the bundle's name must end in .zip (Gradescope takes a zip file), "
                           "such as " + stage.name + "-autograder.zip");
    if (stage.trusted_tests.empty())
        throw grader_error(stage.name + " has no hidden tests yet (grader/hidden/" + stage.name +
                           "/tests/): a bundle for it could grade nothing; write them first (grader/README.md, "
                           "\"Adding a stage\")");
    const fs::path out_dir = bundle.zip.parent_path();
    if (!fs::is_directory(out_dir) || access(out_dir.c_str(), W_OK | X_OK) != 0)
        throw grader_error("cannot write " + bundle.zip.string() + ": the folder " + out_dir.string() +
                           " does not exist or is not writable (make it, or name the bundle elsewhere)");
    const fs::path zip_program = on_path("zip");
    if (zip_program.empty())
        throw grader_error("cannot find 'zip' on PATH: install the Debian package zip (tools/setup does)");
    const fs::path scripts = in.source_dir / scripts_dir;
    for (const char* s : {setup_script, run_script})
        if (!is_regular(scripts / s))
            throw grader_error((scripts / s).string() + " is missing: it is the bundle's " + s +
                               "; restore it from version control");

    const std::vector<fs::path> files = bundle_files(in.source_dir, bundle);
    for (const char* top : {setup_script, run_script, config_file})
        if (std::find(files.begin(), files.end(), fs::path(top)) != files.end())
            throw grader_error((in.source_dir / top).string() + " would take the place of the bundle's own " + top +
                               " at the top of the zip: move or rename it");
    bundle.files = files.size();

    const scratch_folder staging(fs::temp_directory_path() /
                                 ("vl-gradescope-" + std::to_string(getpid()) + "-" + stage.name));
    for (const fs::path& f : files) stage_file(in.source_dir / f, staging.path / f);
    stage_file(scripts / setup_script, staging.path / setup_script);
    stage_file(scripts / run_script, staging.path / run_script);
    {
        std::ofstream conf(staging.path / config_file);
        conf << "# Written by grader/run gradescope: the assignment this bundle grades (run_autograder reads it).\n"
             << "assignment=" << stage.name << "\nnumber=" << stage.number << "\n";
        if (!conf) throw grader_error("cannot write " + (staging.path / config_file).string());
    }
    fix_mode_and_time(staging.path / config_file, false);

    // zip adds to an archive that exists: write a new one beside the bundle, then rename.
    const fs::path partial = out_dir / (".partial-" + std::to_string(getpid()) + "-" + bundle.zip.filename().string());
    std::error_code ec;
    fs::remove(partial, ec);
    std::vector<std::string> argv = {zip_program.string(), "-q", "-X", "-D", partial.string(), setup_script,
                                     run_script, config_file};
    for (const fs::path& f : files) argv.push_back(f.generic_string());
    const run_result r = run_tool(argv, staging.path, 600);
    if (!r.succeeded()) {
        fs::remove(partial, ec);
        throw grader_error("zip could not write " + bundle.zip.string() + " (" + r.describe(600) + "): " +
                           r.output_head(1000) + " (is there room in " + out_dir.string() + "?)");
    }
    fs::rename(partial, bundle.zip, ec);
    if (ec) {
        const std::string why = ec.message();
        fs::remove(partial, ec);
        throw grader_error("cannot write " + bundle.zip.string() + ": " + why);
    }
    return bundle;
}

}  // namespace vl::grader
