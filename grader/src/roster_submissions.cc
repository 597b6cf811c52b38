// The roster's submissions: which entries of the roster's folder are students' submissions
// (list_submissions), and the hashes that tell a changed submission, or a changed grader,
// from an unchanged one (content_hash, setup_hash).
#include "roster.hh"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <map>

#include "oracle.hh"
#include "roster_results.hh"

namespace vl::grader {

namespace fs = std::filesystem;

namespace {

const std::vector<std::string> archive_suffixes = {".tar.gz", ".tgz", ".zip", ".tar"};

/// The suffix of an archive's name that the roster knows, or "".
std::string archive_suffix(const std::string& name) {
    for (const std::string& s : archive_suffixes)
        if (name.size() > s.size() && name.compare(name.size() - s.size(), s.size(), s) == 0) return s;
    return {};
}

/// Adds a regular file's size and bytes, read without following a link and without
/// blocking on a pipe planted where a file was.
void hash_file(fnv1a64& h, const fs::path& file) {
    const int fd = open(file.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
    struct stat st {};
    if (fd < 0 || fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        if (fd >= 0) close(fd);
        h.add("unreadable");
        return;
    }
    const auto size = static_cast<std::uint64_t>(st.st_size);
    h.add(&size, sizeof size);
    char buffer[1 << 16];
    for (ssize_t n; (n = read(fd, buffer, sizeof buffer)) > 0;) h.add(buffer, static_cast<std::size_t>(n));
    close(fd);
}

}  // namespace

std::string setup_hash(const installation& in, const stage_info& stage, const fs::path& grader_program) {
    fnv1a64 h;
    std::vector<fs::path> files = {grader_program, stage.trusted_tests, stage.tests_on_stubs, stage.reference_library,
                                   stage.oracle_map, in.reference_renderer};
    // The oracle's objects, as its map lists them (without a map, the grades themselves fail
    // and say why).
    try {
        for (const oracle_map::object& o : load_oracle_map(stage).objects) files.push_back(o.path);
    } catch (const grader_error&) {
    }
    std::error_code ec;
    std::vector<fs::path> hidden;
    for (auto it = fs::recursive_directory_iterator(in.hidden_dir(stage), ec); !ec && it != fs::recursive_directory_iterator();
         it.increment(ec))
        if (it->is_regular_file(ec)) hidden.push_back(it->path());
    std::sort(hidden.begin(), hidden.end());
    files.insert(files.end(), hidden.begin(), hidden.end());
    for (const fs::path& f : files) {
        if (f.empty()) continue;
        h.add(f.string());
        hash_file(h, f);
    }
    return h.hex();
}

std::vector<roster_entry> list_submissions(const fs::path& dir, std::vector<std::string>& skipped, const fs::path& out) {
    std::error_code ec;
    if (!fs::is_directory(dir, ec))
        throw grader_error(dir.string() + ": no such folder (give the folder that holds one folder or archive per student)");
    std::map<std::string, fs::path> by_name;
    fs::directory_iterator it(dir, ec);
    if (ec) throw grader_error("cannot read the folder " + dir.string() + ": " + ec.message());
    for (const auto& e : it) {
        const std::string file = e.path().filename().string();
        if (file.empty() || file[0] == '.') continue;
        std::string name = file;
        if (const auto rel = out.lexically_relative(fs::absolute(e.path())); !out.empty() && !rel.empty() && *rel.begin() != "..") {
            skipped.push_back(file + ": it holds the roster's own output folder");
            continue;
        }
        if (fs::is_directory(e.status(ec))) {
        } else if (const std::string suffix = archive_suffix(file); !suffix.empty() && fs::is_regular_file(e.status(ec))) {
            name = file.substr(0, file.size() - suffix.size());
        } else {
            skipped.push_back(file + ": neither a folder nor a .zip, .tar.gz, .tgz or .tar archive");
            continue;
        }
        // A link the instructor made (a demo's, a shared folder's) is resolved here, once:
        // the grade itself never follows one.
        const fs::path resolved = fs::canonical(e.path(), ec);
        if (ec) {
            skipped.push_back(file + ": cannot be resolved (" + ec.message() + ")");
            continue;
        }
        const auto [at, inserted] = by_name.emplace(name, resolved);
        if (!inserted)
            throw grader_error(dir.string() + ": two submissions of the student '" + name + "': " +
                               at->second.filename().string() + " and " + file + " (keep one of them)");
    }
    std::vector<roster_entry> entries;
    for (const auto& [name, path] : by_name) entries.push_back({name, path});
    return entries;
}

std::string content_hash(const fs::path& submission) {
    fnv1a64 h;
    std::error_code ec;
    if (!fs::is_directory(fs::symlink_status(submission, ec))) {  // an archive
        h.add("archive");
        hash_file(h, submission);
        return h.hex();
    }
    std::vector<std::pair<std::string, fs::file_status>> files;
    for (auto it = fs::recursive_directory_iterator(submission, fs::directory_options::skip_permission_denied, ec);
         !ec && it != fs::recursive_directory_iterator(); it.increment(ec))
        files.emplace_back(fs::relative(it->path(), submission, ec).generic_string(), it->symlink_status(ec));
    std::sort(files.begin(), files.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    h.add("folder");
    for (const auto& [path, status] : files) {
        h.add(path);
        if (fs::is_symlink(status)) {
            h.add("link");
            h.add(fs::read_symlink(submission / path, ec).string());
        } else if (fs::is_regular_file(status)) {
            h.add("file");
            hash_file(h, submission / path);
        } else {
            h.add(fs::is_directory(status) ? "folder" : "other");
        }
    }
    return h.hex();
}

}  // namespace vl::grader
