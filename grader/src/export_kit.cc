#include "export_kit.hh"

#include <fstream>
#include <iterator>
#include <regex>
#include <sstream>

#include "sandbox.hh"

namespace vl::grader {

namespace fs = std::filesystem;

namespace {

/// What the kit takes from the top of the tree. Everything else (reference/, .ci/, build
/// trees, version control, the instructor's tools) stays behind; of grader/ only its
/// CMakeLists.txt goes, which builds nothing without grader/hidden/. pieces/ is what the
/// build makes from the list of stages: the aggregate's template and the programs' main()s.
/// The kit's README.md is kit_readme, the student's page, not the instructor's.
const std::vector<std::string> kit_parts = {"CMakeLists.txt", "CMakePresets.json", ".gitignore", "LICENSE", "framework",
                                            "pieces", "assignments", "docs", "scenes", "tools/setup", "bench",
                                            "cmake/stages.cmake", "cmake/check_test_names.cmake",
                                            "grader/CMakeLists.txt"};
const char* const kit_readme = "kit/README.md";

std::string read_all(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string strip(const std::string& s) {
    const auto first = s.find_first_not_of(" \t\r");
    if (first == std::string::npos) return {};
    return s.substr(first, s.find_last_not_of(" \t\r") - first + 1);
}

std::vector<fs::path> files_under(const fs::path& dir) {
    std::vector<fs::path> out;
    if (!fs::exists(dir)) return out;
    for (const auto& e : fs::recursive_directory_iterator(dir))
        if (e.is_regular_file() && !e.is_symlink() && e.file_size() < (4 << 20)) out.push_back(e.path());
    return out;
}

/// Code lines worth searching for: long enough to be specific, not comments or includes.
bool is_code_line(const std::string& line) {
    return line.size() >= 24 && !line.starts_with("//") && !line.starts_with("#include") && !line.starts_with("*") &&
           !line.starts_with("/*");
}

}  // namespace

std::vector<std::string> find_leaks(const fs::path& source_dir, const fs::path& kit) {
    std::vector<std::string> leaks;
    for (const char* part : {"reference", "grader/hidden", "grader/tests", "grader/src"})
        if (fs::exists(kit / part)) leaks.push_back(std::string(part) + "/ is in the kit");

    // Text the kit may share with the reference: everything students get anyway (a stub
    // keeps the reference's finished parts, such as reading a scene, sometimes reflowed).
    std::string public_text;
    for (const char* part : {"assignments", "framework", "pieces"})
        for (const fs::path& f : files_under(source_dir / part)) public_text += read_all(f) + "\n";
    auto is_public = [&](const std::string& s) { return public_text.find(s) != std::string::npos; };
    std::vector<std::pair<std::string, std::string>> secrets;  // (what, where it is from)
    for (const fs::path& f : files_under(source_dir / "reference")) {
        if (f.extension() != ".cc" && f.extension() != ".hh") continue;
        std::istringstream in(read_all(f));
        int number = 0;
        for (std::string line; std::getline(in, line);) {
            ++number;
            const std::string s = strip(line);
            if (is_code_line(s) && !is_public(s))
                secrets.emplace_back(s, fs::relative(f, source_dir).string() + ":" + std::to_string(number));
        }
    }
    const std::regex test_case(R"re(TEST_CASE\s*\(\s*"((?:[^"\\]|\\.)*)")re");
    for (const fs::path& f : files_under(source_dir / "grader" / "hidden")) {
        const std::string text = read_all(f);
        for (auto it = std::sregex_iterator(text.begin(), text.end(), test_case); it != std::sregex_iterator(); ++it)
            if (!is_public((*it)[1].str()))
                secrets.emplace_back((*it)[1].str(), "hidden test in " + fs::relative(f, source_dir).string());
    }
    if (secrets.empty()) leaks.push_back("found nothing to search for: is this the instructor's tree?");

    for (const fs::path& f : files_under(kit)) {
        const std::string text = read_all(f);
        for (const auto& [secret, from] : secrets)
            if (text.find(secret) != std::string::npos)
                leaks.push_back(fs::relative(f, kit).string() + " holds \"" + secret + "\" (" + from + ")");
    }
    return leaks;
}

void export_kit(const installation& in, const fs::path& dir) {
    if (!fs::exists(in.source_dir / kit_readme))
        throw grader_error((in.source_dir / kit_readme).string() + " is missing: it is the kit's README.md (the "
                           "student's first page); restore it from version control");
    if (fs::exists(dir) && !fs::is_empty(dir))
        throw grader_error(dir.string() + " exists and is not empty: name a new folder for the kit");
    fs::create_directories(dir);
    for (const std::string& part : kit_parts) {
        const fs::path from = in.source_dir / part;
        if (!fs::exists(from)) continue;
        fs::create_directories((dir / part).parent_path());
        fs::copy(from, dir / part, fs::copy_options::recursive | fs::copy_options::copy_symlinks);
    }
    fs::copy_file(in.source_dir / kit_readme, dir / "README.md");
    // A student's grader/ holds only the CMakeLists.txt that builds nothing without hidden/.
    std::ofstream(dir / "grader" / "README.md")
        << "# grader\n\nYour instructor grades your stages with hidden tests and scenes that are not part of this "
           "kit.\nRun the public tests (`ctest --preset student`) and render the public scenes to check your "
           "work;\nthe kit's README.md says how.\n";

    const std::vector<std::string> leaks = find_leaks(in.source_dir, dir);
    if (!leaks.empty()) {
        std::string list;
        for (const std::string& l : leaks) list += "  " + l + "\n";
        fs::remove_all(dir);
        throw grader_error("the kit would leak instructor-only material, so none was written:\n" + list);
    }
    const fs::path tarball = dir.string() + ".tar.gz";
    run_request rq;
    rq.argv = {"/bin/tar", "-czf", tarball.string(), "-C", fs::absolute(dir).parent_path().string(),
               dir.filename().string()};
    rq.cwd = fs::absolute(dir).parent_path().string();
    rq.environment = child_environment(rq.cwd);
    rq.sandboxed = false;
    rq.limits.wall_seconds = 300;
    const run_result r = run(rq, sandbox_capabilities{});
    if (!r.succeeded()) throw grader_error("tar could not write " + tarball.string() + ": " + r.output_head(600));
}

}  // namespace vl::grader
