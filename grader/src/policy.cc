// The source half of the policy (policy.hh): what the lines of a student's own files may
// not say, preprocessed and as written, and what a finding says. The symbol half is in
// policy_symbols.cc.
#include "policy.hh"

#include <algorithm>
#include <array>
#include <cctype>
#include <filesystem>
#include <map>
#include <sstream>
#include <string_view>

#include "policy_reasons.hh"

namespace vl::grader {

using namespace policy_reasons;

namespace {

bool is_identifier_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

/// The source with string and character literals blanked, so words inside them are not code.
std::string without_literals(const std::string& line, bool& in_raw, std::string& raw_end) {
    std::string out = line;
    std::size_t k = 0;
    auto blank = [&](std::size_t from, std::size_t to) {
        for (std::size_t j = from; j < to && j < out.size(); ++j) out[j] = ' ';
    };
    if (in_raw) {
        const auto close = line.find(raw_end);
        if (close == std::string::npos) return std::string(line.size(), ' ');
        blank(0, close + raw_end.size());
        k = close + raw_end.size();
        in_raw = false;
    }
    while (k < line.size()) {
        const char c = line[k];
        if (c == 'R' && k + 1 < line.size() && line[k + 1] == '"' && (k == 0 || !is_identifier_char(line[k - 1]) ||
                                                                     line[k - 1] == 'u' || line[k - 1] == 'U' ||
                                                                     line[k - 1] == 'L' || line[k - 1] == '8')) {
            const auto paren = line.find('(', k + 2);
            if (paren == std::string::npos) break;
            raw_end = ")" + line.substr(k + 2, paren - k - 2) + "\"";
            const auto close = line.find(raw_end, paren);
            if (close == std::string::npos) {
                blank(k, line.size());
                in_raw = true;
                break;
            }
            blank(k, close + raw_end.size());
            k = close + raw_end.size();
        } else if (c == '"' || (c == '\'' && (k == 0 || !std::isxdigit(static_cast<unsigned char>(line[k - 1]))))) {
            std::size_t j = k + 1;
            while (j < line.size() && line[j] != c) j += line[j] == '\\' ? 2 : 1;
            blank(k, j + 1);
            k = j + 1;
        } else {
            ++k;
        }
    }
    return out;
}

/// Words inside attribute brackets that make code run or link differently.
const std::map<std::string, const char*, std::less<>>& denied_attribute_words() {
    static const std::map<std::string, const char*, std::less<>> m = {
        {"constructor", early}, {"destructor", early},  {"init_priority", early}, {"section", replaces},
        {"alias", replaces},    {"weak", replaces},     {"weakref", replaces},    {"ifunc", replaces},
        {"visibility", replaces}, {"symver", replaces}, {"naked", assembly},
    };
    return m;
}

/// Identifiers that are denied wherever they appear in a student's own code.
const std::map<std::string, const char*, std::less<>>& denied_words() {
    static const std::map<std::string, const char*, std::less<>> m = {
        {"asm", assembly},          {"__asm", assembly},        {"__asm__", assembly},
        {"thread_tallies", counters}, {"clear_counts", counters}, {"syscall", syscalls},
        {"_fileno", files},         {"_IO_write_ptr", files},   {"_IO_buf_base", files},
        {"__builtin_frame_address", harness}, {"__builtin_return_address", harness},
        {"Catch", harness},
    };
    return m;
}

/// Whether a line marker's file is the student's: anything but the toolchain's and the
/// framework's headers, whatever spelling of a path led to it (/./submission/x.hh,
/// //submission/x.hh and /proc/self/root/submission/x.hh are all the student's).
bool is_students(const std::string& file, const std::string& student_prefix, const std::vector<std::string>& trusted) {
    if (file == "<built-in>" || file == "<command-line>") return false;
    std::string normal = std::filesystem::path(file).lexically_normal().string();
    while (normal.starts_with("//")) normal.erase(0, 1);
    if (normal.starts_with(student_prefix)) return true;
    for (const std::string& t : trusted)
        if (normal.starts_with(t)) return false;
    return true;
}

}  // namespace

std::string policy_finding::describe() const {
    const bool definition = std::string_view(reason) == replaces && line == 0;
    std::string s = file + (line > 0 ? ":" + std::to_string(line) : std::string()) +
                    (definition ? ": defines '" : ": uses '") + what + "' (" + reason + ")";
    return s;
}

std::vector<policy_finding> check_preprocessed(const std::string& text, const std::string& student_prefix,
                                               const std::vector<std::string>& trusted) {
    std::vector<policy_finding> found;
    std::set<std::pair<std::string, std::string>> seen;
    std::istringstream in(text);
    std::string line, file;
    int number = 0;
    bool mine = false, in_raw = false;
    std::string raw_end;
    int attribute_depth = 0;      // inside __attribute__((...)): parentheses still open
    int bracket_attribute = 0;    // inside [[...]]
    auto add = [&](const std::string& what, const char* reason) {
        const std::string base = file.substr(file.rfind('/') + 1);
        if (seen.insert({base, what}).second) found.push_back({base, number, what, reason});
    };
    while (std::getline(in, line)) {
        // Line markers: # 12 "/submission/sphere.cc" 2
        if (line.starts_with("# ") && line.size() > 2 && std::isdigit(static_cast<unsigned char>(line[2]))) {
            const auto q1 = line.find('"'), q2 = line.rfind('"');
            number = std::atoi(line.c_str() + 2) - 1;
            if (q1 != std::string::npos && q2 > q1) {
                file = line.substr(q1 + 1, q2 - q1 - 1);
                mine = is_students(file, student_prefix, trusted);
            }
            continue;
        }
        ++number;
        if (!mine) continue;
        if (line.starts_with("#pragma") || line.starts_with("# pragma")) {
            for (const char* word : {"weak", "redefine_extname", "GCC poison", "push_macro"})
                if (line.find(word) != std::string::npos) add("#pragma " + std::string(word), replaces);
            continue;
        }
        const std::string code = without_literals(line, in_raw, raw_end);
        std::size_t k = 0;
        while (k < code.size()) {
            const char c = code[k];
            if (c == '[' && k + 1 < code.size() && code[k + 1] == '[') {
                ++bracket_attribute;
                k += 2;
                continue;
            }
            if (c == ']' && k + 1 < code.size() && code[k + 1] == ']' && bracket_attribute > 0) {
                --bracket_attribute;
                k += 2;
                continue;
            }
            if (attribute_depth > 0 && c == '(') ++attribute_depth;
            if (attribute_depth > 0 && c == ')') --attribute_depth;
            if (!is_identifier_char(c) || std::isdigit(static_cast<unsigned char>(c))) {
                if (std::isdigit(static_cast<unsigned char>(c)))
                    while (k < code.size() && is_identifier_char(code[k])) ++k;
                else
                    ++k;
                continue;
            }
            std::size_t j = k;
            while (j < code.size() && is_identifier_char(code[j])) ++j;
            const std::string word = code.substr(k, j - k);
            std::size_t after = j;
            while (after < code.size() && code[after] == ' ') ++after;
            const bool scope_follows = code.compare(after, 2, "::") == 0;
            if (word == "__attribute__" || word == "__attribute") {
                const auto open = code.find('(', j);
                if (open != std::string::npos) {
                    attribute_depth = 1;
                    j = open + 1;
                }
            } else if (attribute_depth > 0 || bracket_attribute > 0) {
                std::string bare = word;
                if (bare.size() > 4 && bare.starts_with("__") && bare.ends_with("__")) bare = bare.substr(2, bare.size() - 4);
                if (const auto d = denied_attribute_words().find(bare); d != denied_attribute_words().end())
                    add("attribute " + bare, d->second);
            }
            if (const auto d = denied_words().find(word); d != denied_words().end() &&
                                                          (word != "Catch" || scope_follows)) {
                add(word, d->second);
            }
            // vl::detail is the framework's inside (the counters among it).
            if (word == "vl" && scope_follows) {
                std::size_t m = after + 2;
                while (m < code.size() && code[m] == ' ') ++m;
                if (code.compare(m, 6, "detail") == 0 && (m + 6 >= code.size() || !is_identifier_char(code[m + 6])))
                    add("vl::detail", counters);
            }
            k = j;
        }
    }
    return found;
}

std::vector<policy_finding> check_raw_source(const std::string& file, const std::string& text) {
    // Translation phases 2 and 3, as far as directives need them: backslash-newlines are
    // spliced, comments are whitespace, literals are skipped, and `%:` is `#`. A directive is
    // a `#` first on a logical line; `#line` and a GNU line marker (`# 12 "file" 1`) are refused.
    std::vector<policy_finding> found;
    std::string t;       // the text with splices removed
    std::vector<int> at;  // the physical line of each character of t
    int line = 1;
    for (std::size_t k = 0; k < text.size(); ++k) {
        if (text[k] == '\\') {
            std::size_t j = k + 1;
            while (j < text.size() && (text[j] == ' ' || text[j] == '\t' || text[j] == '\r')) ++j;
            if (j < text.size() && text[j] == '\n') {
                k = j;
                ++line;
                continue;
            }
        }
        t += text[k];
        at.push_back(line);
        if (text[k] == '\n') ++line;
    }
    bool line_start = true;
    std::size_t k = 0;
    auto skip_blank = [&](bool newlines) {
        for (;;) {
            if (k < t.size() && (t[k] == ' ' || t[k] == '\t' || t[k] == '\r' || t[k] == '\f' || t[k] == '\v' ||
                                 (newlines && t[k] == '\n'))) {
                ++k;
            } else if (t.compare(k, 2, "/*") == 0) {
                const auto end = t.find("*/", k + 2);
                k = end == std::string::npos ? t.size() : end + 2;
            } else {
                return;
            }
        }
    };
    while (k < t.size()) {
        if (line_start) {
            skip_blank(false);
            line_start = false;
            if (k < t.size() && (t[k] == '#' || t.compare(k, 2, "%:") == 0)) {
                const int where = at[k];
                k += t[k] == '#' ? 1 : 2;
                skip_blank(false);
                std::size_t j = k;
                while (j < t.size() && is_identifier_char(t[j])) ++j;
                const std::string word = t.substr(k, j - k);
                if (word == "line" || (!word.empty() && std::isdigit(static_cast<unsigned char>(word[0]))))
                    found.push_back({file, where, "#line", "hides where its code comes from"});
                k = j;
            }
            continue;
        }
        const char c = t[k];
        if (c == '\n') {
            line_start = true;
            ++k;
        } else if (t.compare(k, 2, "//") == 0) {
            while (k < t.size() && t[k] != '\n') ++k;
        } else if (t.compare(k, 2, "/*") == 0) {
            const auto end = t.find("*/", k + 2);
            k = end == std::string::npos ? t.size() : end + 2;
        } else if (c == 'R' && t.compare(k + 1, 1, "\"") == 0 && (k == 0 || !is_identifier_char(t[k - 1]) ||
                                                                  t[k - 1] == 'u' || t[k - 1] == 'U' ||
                                                                  t[k - 1] == 'L' || t[k - 1] == '8')) {
            const auto paren = t.find('(', k + 2);
            if (paren == std::string::npos) break;
            const std::string close = ")" + t.substr(k + 2, paren - k - 2) + "\"";
            const auto end = t.find(close, paren);
            k = end == std::string::npos ? t.size() : end + close.size();
        } else if (c == '"' || (c == '\'' && (k == 0 || !std::isxdigit(static_cast<unsigned char>(t[k - 1]))))) {
            std::size_t j = k + 1;
            while (j < t.size() && t[j] != c && t[j] != '\n') j += t[j] == '\\' ? 2 : 1;
            k = j + 1;
        } else {
            ++k;
        }
    }
    return found;
}

}  // namespace vl::grader
