// What a failed build says to the student: the compiler's first errors with the sandbox's
// folders named for a reader, a note for each contract header the grader put back, and a
// failed link in terms of the student's own symbols and files.
#include <algorithm>
#include <map>
#include <set>
#include <sstream>
#include <utility>
#include <vector>

#include "build_submission.hh"

namespace vl::grader {

namespace {

void replace_all(std::string& s, const std::string& from, const std::string& to) {
    if (from.empty()) return;
    for (std::size_t at = s.find(from); at != std::string::npos; at = s.find(from, at + to.size()))
        s.replace(at, from.size(), to);
}

/// The file a linker message names before `:(` (`b.cc:(.text+0x0)`, or after an object's
/// name: `a.o:a.cc:(.text+0x0)`), when it is one of `files`; otherwise "" (the grader's own
/// parts are never named).
std::string file_named_in(const std::string& part, const std::vector<std::string>& files) {
    const auto paren = part.find(":(");
    if (paren == std::string::npos || paren == 0) return {};
    const auto colon = part.rfind(':', paren - 1);
    const auto space = part.rfind(' ', paren - 1);
    std::size_t from = 0;
    if (colon != std::string::npos) from = colon + 1;
    if (space != std::string::npos && space + 1 > from) from = space + 1;
    const std::string file = part.substr(from, paren - from);
    return std::find(files.begin(), files.end(), file) != files.end() ? file : std::string();
}

/// The student's file whose object a linker names in `part` (`/in/STEM.o`, as gold and
/// lld name them), or "".
std::string file_of_object_in(const std::string& part, const std::vector<std::string>& files) {
    for (std::size_t at = part.find("/in/"); at != std::string::npos; at = part.find("/in/", at + 1)) {
        const auto end = part.find(".o", at);
        if (end == std::string::npos) break;
        const std::string stem = part.substr(at + 4, end - at - 4);
        for (const std::string& f : files)
            if (std::filesystem::path(f).stem().string() == stem) return f;
    }
    return {};
}

}  // namespace

std::string trim_compiler_errors(const std::string& log, int max_lines) {
    std::vector<std::string> lines;
    std::istringstream in(log);
    for (std::string line; std::getline(in, line);) {
        replace_all(line, "/submission/", "");
        replace_all(line, "/vl/framework/", "<framework>/");
        replace_all(line, "/vl/contract/", "<contract>/");
        replace_all(line, "/out/", "");
        lines.push_back(line);
    }
    std::size_t first = 0;
    while (first < lines.size() && lines[first].find("error") == std::string::npos) ++first;
    if (first == lines.size()) first = 0;
    // Keep the "In function ..." line that names where the error is.
    if (first > 0 && lines[first - 1].find("In ") != std::string::npos) --first;
    std::string out;
    const std::size_t last = std::min(lines.size(), first + static_cast<std::size_t>(max_lines));
    for (std::size_t k = first; k < last; ++k) out += lines[k] + "\n";
    if (last < lines.size()) out += "[... " + std::to_string(lines.size() - last) + " more lines]\n";
    return out;
}

std::string with_contract_note(const prepared_submission& sub, std::string errors) {
    for (const std::string& h : sub.replaced_contracts)
        errors = "note: your " + h + " differs from the original, and the original was used (the grader always "
                 "uses the contract as handed out). If the errors below are about something you declared or "
                 "changed in " + h + ", move it into your own .cc or .hh files.\n\n" + errors;
    return errors;
}

std::string explain_link_errors(const std::string& log, const std::vector<std::string>& files) {
    std::set<std::string> missing;
    std::map<std::string, std::set<std::string>> twice;  // symbol -> the files that define it
    std::vector<std::string> other;
    std::string last_twice;  // the symbol of the last "defined twice", for the lines that go on about it
    auto add_files = [&](const std::string& part, std::set<std::string>& where) {
        if (std::string file = file_named_in(part, files); !file.empty()) where.insert(file);
        if (std::string file = file_of_object_in(part, files); !file.empty()) where.insert(file);
    };
    std::istringstream in(log);
    for (std::string line; std::getline(in, line);) {
        // GNU ld:   b.cc:(.text+0x0): multiple definition of `f()'; a.o:a.cc:(.text+0x0): first defined here
        // GNU gold: error: /in/b.o: multiple definition of 'f()'  /  /in/a.o: previous definition here
        // LLVM lld: error: duplicate symbol: f()  /  >>> defined at ...  /in/a.o:(f())
        // and for a symbol nobody defines: undefined reference to `g()' (ld, gold), undefined symbol: g() (lld)
        enum class link_error { undefined, defined_twice };
        const std::pair<const char*, link_error> markers[] = {{"undefined reference to ", link_error::undefined},
                                                              {"undefined symbol: ", link_error::undefined},
                                                              {"multiple definition of ", link_error::defined_twice},
                                                              {"duplicate symbol: ", link_error::defined_twice}};
        bool explained = false;
        for (const auto& [marker, kind] : markers) {
            const auto at = line.find(marker);
            if (at == std::string::npos) continue;
            explained = true;
            std::string symbol = line.substr(at + std::string(marker).size());
            if (symbol.size() >= 2 && (symbol.front() == '`' || symbol.front() == '\'')) symbol = symbol.substr(1);
            std::string rest;
            if (const auto end = symbol.rfind('\''); end != std::string::npos) {
                rest = symbol.substr(end + 1);
                symbol.erase(end);
            }
            if (kind == link_error::undefined) {
                missing.insert(symbol);
                last_twice.clear();
                break;
            }
            last_twice = symbol;
            for (const std::string& part : {line.substr(0, at), rest}) add_files(part, twice[symbol]);
            break;
        }
        if (explained) continue;
        if (!last_twice.empty() && (line.find("previous definition here") != std::string::npos || line.starts_with(">>>"))) {
            add_files(line, twice[last_twice]);
            continue;
        }
        last_twice.clear();
        if (line.find("error:") != std::string::npos && line.find("collect2") == std::string::npos &&
            line.find("ld returned") == std::string::npos && line.find("/vl/prebuilt") == std::string::npos)
            other.push_back(line);
    }
    std::string out = "your code does not link with the tests and the framework:\n";
    for (const std::string& s : missing) out += "  missing: " + s + " (declared, but your files do not define it)\n";
    for (const auto& [s, defined_in] : twice) {
        std::string in_files;
        for (const std::string& f : defined_in) in_files += (in_files.empty() ? ", in " : " and ") + f;
        out += "  defined twice: " + s + in_files +
               (s.find("register_stage_") != std::string::npos
                    ? " (the grader always compiles the stage's register.cc as handed out, which defines it: "
                      "remove your own definition)\n"
                    : " (define it once, in one .cc file, or make it inline or static)\n");
    }
    for (std::size_t k = 0; k < other.size() && k < 10; ++k) {
        std::string l = other[k];
        replace_all(l, "/in/", "");
        out += "  " + l + "\n";
    }
    if (missing.empty() && twice.empty() && other.empty()) out += "  (the linker gave no reason a student can act on)\n";
    return out;
}

}  // namespace vl::grader
