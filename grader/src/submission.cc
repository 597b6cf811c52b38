#include "submission.hh"

#include "safe_files.hh"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <set>
#include <sstream>

namespace vl::grader {

namespace fs = std::filesystem;

namespace {

constexpr const char* source_kinds[] = {".cc", ".cpp", ".hh", ".h", ".hpp", ".inl"};

bool is_source(const fs::path& p) {
    return std::find(std::begin(source_kinds), std::end(source_kinds), p.extension().string()) !=
           std::end(source_kinds);
}

bool has_cc(const fs::path& dir) {
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(dir, ec))
        if (e.is_regular_file() && e.path().extension() == ".cc") return true;
    return false;
}

/// The shell script the intake sandbox runs: unpack (when an archive) into the tmpfs, count
/// the files, name the oversized sources, and stream the regular source files as a tar to fd 3.
std::string intake_script(const intake_limits& l) {
    std::string names;
    for (const char* k : source_kinds) names += std::string(names.empty() ? "" : " -o") + " -name '*" + k + "'";
    return R"(set -u
src=/in/submission
if [ -f "$src" ]; then
  mkdir /scratch/u && cd /scratch/u || exit 90
  case "$VL_ARCHIVE" in
    zip) unzip -qq -n "$src" >"$TMPDIR"/err 2>&1 ;;
    *) tar -xf "$src" --no-same-owner --no-same-permissions >"$TMPDIR"/err 2>&1 ;;
  esac
  status=$?
  if [ $status -ge 128 ] || grep -q "No space left\|disk full\|write error\|Wrote only" "$TMPDIR"/err; then
    echo "VL-FULL"; exit 91
  fi
  if [ $status -ne 0 ]; then echo "VL-BROKEN"; head -c 600 "$TMPDIR"/err; exit 92; fi
  rm -f "$TMPDIR"/err
  src=/scratch/u
fi
cd "$src" || exit 90
n=$(find . -type f -o -type d | head -n )" + std::to_string(l.files + 2) + R"( | wc -l)
if [ "$n" -gt )" + std::to_string(l.files) + R"( ]; then echo "VL-TOO-MANY"; exit 93; fi
find . -type f -size +1024k \()" + names + R"( \) | head -n 20 | sed 's/^/VL-BIG /'
find . -type f -size -1025k \()" + names + R"( \) -print0 |
  tar --null --no-recursion -T - --format=gnu -cf /dev/fd/3 || exit 94
)";
}

/// Reads an octal field of a tar header.
std::uint64_t octal(const char* field, std::size_t n) {
    std::uint64_t v = 0;
    for (std::size_t k = 0; k < n && field[k] != '\0' && field[k] != ' '; ++k) {
        if (field[k] < '0' || field[k] > '7') return v;
        v = v * 8 + static_cast<std::uint64_t>(field[k] - '0');
    }
    return v;
}

/// Unpacks the sandbox's tar stream (regular files and folders, GNU long names) into
/// `into`. Names are checked part by part: nothing absolute, no "..", nothing hidden.
void extract_tar(const std::string& tar, const fs::path& into) {
    std::size_t at = 0;
    std::string long_name;
    while (at + 512 <= tar.size()) {
        const char* h = tar.data() + at;
        if (std::all_of(h, h + 512, [](char c) { return c == '\0'; })) break;
        const std::uint64_t size = octal(h + 124, 12);
        const char type = h[156];
        const std::size_t data = at + 512;
        at = data + ((size + 511) / 512) * 512;
        if (at > tar.size() + 511) throw submission_error("the submission's files came back cut short");
        const std::string body = tar.substr(data, std::min<std::size_t>(size, tar.size() - std::min(data, tar.size())));
        if (type == 'L') {
            long_name = body.c_str();
            continue;
        }
        const std::string name = long_name.empty() ? std::string(h, strnlen(h, 100)) : long_name;
        long_name.clear();
        if (type != '0' && type != '\0') continue;
        fs::path rel;
        bool ok = !name.empty() && name[0] != '/';
        for (const auto& part : fs::path(name)) {
            const std::string p = part.string();
            if (p == "." || p.empty()) continue;
            if (p == ".." || p.find('\0') != std::string::npos) ok = false;
            rel /= part;
        }
        if (!ok || rel.empty()) continue;
        fs::path dir = into;
        for (auto it = rel.begin(); std::next(it) != rel.end(); ++it) {
            dir /= *it;
            if (mkdir(dir.c_str(), 0755) != 0 && errno != EEXIST)
                throw grader_error("cannot make " + dir.string() + ": " + std::strerror(errno));
        }
        write_new_file(into / rel, body);
    }
}

/// The folder holding the stage's .cc files: the tree itself, assignments/NN-name in a
/// kit, a folder NN-name, or the same inside the one folder an archive wraps it in. The
/// tree holds only folders and regular files (extract_tar made it).
fs::path find_stage_dir(const fs::path& root, const std::string& stage, bool& is_kit, int depth = 0) {
    if (fs::is_directory(root / "assignments" / stage)) {
        is_kit = true;
        return root / "assignments" / stage;
    }
    if (has_cc(root)) return root;
    if (fs::is_directory(root / stage) && has_cc(root / stage)) return root / stage;
    std::vector<fs::path> dirs;
    for (const auto& e : fs::directory_iterator(root))
        if (e.is_directory() && e.path().filename().string()[0] != '.' && e.path().filename() != "__MACOSX")
            dirs.push_back(e.path());
    if (dirs.size() == 1 && depth < 3) return find_stage_dir(dirs.front(), stage, is_kit, depth + 1);
    return {};
}

std::string megabytes(std::uint64_t bytes) { return std::to_string(bytes >> 20) + " MiB"; }

}  // namespace

prepared_submission prepare_submission(const fs::path& submission, const stage_info& stage, const installation& in,
                                       const fs::path& work, const sandbox_capabilities& caps, double wall_seconds,
                                       const intake_limits& limits) {
    std::error_code ec;
    // The instructor names the submission; that one path may be a link. Nothing inside it is followed.
    const fs::path given = fs::canonical(submission, ec);
    if (ec) throw grader_error(submission.string() + ": " + ec.message());
    const bool folder = fs::is_directory(given);
    const std::string name = submission.filename().string();
    std::string archive = "tar";
    if (!folder) {
        if (name.ends_with(".zip")) archive = "zip";
        else if (!(name.ends_with(".tar.gz") || name.ends_with(".tgz") || name.ends_with(".tar") ||
                   name.ends_with(".tar.xz") || name.ends_with(".tar.bz2")))
            throw submission_error(name + " is neither a folder nor a .zip, .tar.gz or .tar archive: hand in the folder "
                                          "assignments/" + stage.name + ", or an archive of it");
    }

    run_request rq;
    rq.argv = {"/bin/sh", "-c", intake_script(limits)};
    rq.mounts = {{given, "/in/submission", false}};
    rq.environment = child_environment("/scratch", {"VL_ARCHIVE=" + archive});
    rq.report_fd = true;
    rq.limits.wall_seconds = std::min(60.0, wall_seconds);
    rq.limits.scratch_bytes = limits.unpacked_bytes;
    rq.limits.file_bytes = limits.unpacked_bytes + (1 << 20);  // the tmpfs fills first
    rq.limits.memory_bytes = std::uint64_t{1} << 30;
    rq.limits.report_bytes = limits.source_bytes * 4 + (1 << 20);
    const run_result r = run(rq, caps);
    if (!r.started) throw grader_error("could not take in " + submission.string() + ": " + r.error);
    if (r.timed_out) throw submission_error("unpacking " + name + " " + r.describe(rq.limits.wall_seconds));
    if (r.output.find("VL-FULL") != std::string::npos)
        throw submission_error(name + " unpacks to more than " + megabytes(limits.unpacked_bytes) +
                               ": hand in only the folder assignments/" + stage.name);
    if (r.output.find("VL-TOO-MANY") != std::string::npos)
        throw submission_error(name + " holds more than " + std::to_string(limits.files) +
                               " files: hand in only the folder assignments/" + stage.name);
    if (r.output.find("VL-BROKEN") != std::string::npos)
        throw submission_error("could not unpack " + name + ": " + r.output.substr(r.output.find("VL-BROKEN") + 10, 600));
    if (r.report_overflow)
        throw submission_error(name + " holds more than " + megabytes(limits.source_bytes) +
                               " of source files: hand in only the folder assignments/" + stage.name);
    if (r.exit_code == 94 || r.exit_code == 90)
        throw grader_error("could not read the files of " + submission.string() + ": " + r.output_head(600) +
                           (caps.drop_to_nobody ? " (the sandbox reads a submission as the user nobody: make its files "
                                                  "readable to all, e.g. chmod -R a+rX)"
                                                : ""));
    if (!r.succeeded())
        throw submission_error("could not read " + name + " (" + r.describe(rq.limits.wall_seconds) + "): " +
                               r.output_head(600));

    prepared_submission p;
    {
        std::istringstream lines(r.output);
        for (std::string line; std::getline(lines, line);)
            if (line.starts_with("VL-BIG ./"))
                p.notes.push_back(line.substr(9) + " is larger than 1 MiB and was left out");
    }
    const fs::path root = work / "intake";
    fs::create_directories(root);
    extract_tar(r.report, root);

    bool is_kit = false;
    const fs::path stage_dir = find_stage_dir(root, stage.name, is_kit);
    if (stage_dir.empty() || !has_cc(stage_dir))
        throw submission_error("found no .cc files for " + stage.name + " in " + name +
                               ": hand in the folder assignments/" + stage.name + " (or the whole kit)");
    const std::string where = fs::relative(stage_dir, root).string();
    p.origin = (is_kit ? "a student kit; graded " : "graded ") + (where == "." ? std::string("its top folder") : where);
    if (is_kit) {
        for (const auto& [other, s] : in.stages)
            if (other != stage.name && has_cc(root / "assignments" / other)) p.kit_stages.push_back(other);
    }

    p.sources = work / "sources";
    p.contract = work / "contract";
    fs::create_directories(p.sources);
    fs::create_directories(p.contract);
    int copied = 0;
    std::uint64_t bytes = 0;
    for (const auto& e : fs::directory_iterator(stage_dir)) {
        if (!e.is_regular_file() || !is_source(e.path())) continue;
        if (++copied > limits.sources)
            throw submission_error("more than " + std::to_string(limits.sources) + " source files in " + where +
                                   ": is this the right folder?");
        bytes += e.file_size();
        if (bytes > limits.source_bytes)
            throw submission_error("the source files in " + where + " add up to more than " +
                                   megabytes(limits.source_bytes));
        fs::copy_file(e.path(), p.sources / e.path().filename());
    }
    // The pristine contracts of every stage (a stage's code may use an earlier stage's): the
    // student's copy of one is dropped, so an edited contract cannot change what is graded.
    for (const auto& [other, s] : in.stages) {
        const fs::path header = in.contract_header(s);
        if (!fs::is_regular_file(header)) continue;
        const fs::path file = header.filename();
        fs::copy_file(header, p.contract / file, fs::copy_options::overwrite_existing);
        if (fs::exists(p.sources / file)) {
            if (read_regular_file(p.sources / file, limits.source_bytes) != read_regular_file(header, limits.source_bytes)) {
                p.notes.push_back("your " + file.string() + " differs from the original; the original was used");
                p.replaced_contracts.push_back(file.string());
            }
            fs::remove(p.sources / file);
        }
    }
    // The stage's registration, as handed out (the reference has no copy of its own).
    if (const fs::path handed_out = in.registration(stage); fs::is_regular_file(handed_out)) {
        const fs::path mine = p.sources / handed_out.filename();
        if (fs::exists(mine) &&
            read_regular_file(mine, limits.source_bytes) != read_regular_file(handed_out, limits.source_bytes))
            p.notes.push_back("your " + handed_out.filename().string() + " differs from the original; the original was used");
        fs::copy_file(handed_out, mine, fs::copy_options::overwrite_existing);
    }
    for (const auto& e : fs::directory_iterator(p.sources))
        if (e.path().extension() == ".cc") p.files.push_back(e.path().filename().string());
    std::sort(p.files.begin(), p.files.end());
    return p;
}

}  // namespace vl::grader
