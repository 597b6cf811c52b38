#include "vl/scene_reader.hh"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

#include "vl/error.hh"
#include "vl/registry.hh"

namespace vl {

namespace {
constexpr std::size_t max_file_bytes = 64u << 20;  // a scene is text: 64 MiB is generous
constexpr std::size_t max_include_depth = 16;

bool word_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool word_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }
bool number_start(char c, char next) {
    return std::isdigit(static_cast<unsigned char>(c)) ||
           ((c == '-' || c == '+' || c == '.') && (std::isdigit(static_cast<unsigned char>(next)) || next == '.'));
}
}  // namespace

std::string source_location::str() const {
    return file + ':' + std::to_string(line) + ':' + std::to_string(column);
}

/// One file being read: its text and where the lexer is in it.
struct scene_reader::source {
    std::string name;
    std::filesystem::path canonical;  // empty for text given directly
    std::filesystem::path directory;  // includes are relative to this
    std::string text;
    std::size_t pos = 0;
    int line = 1, column = 1;

    char at(std::size_t k = 0) const { return pos + k < text.size() ? text[pos + k] : '\0'; }
    void advance() {
        if (text[pos] == '\n') {
            ++line;
            column = 1;
        } else {
            ++column;
        }
        ++pos;
    }
    source_location here() const { return {name, line, column}; }
};

scene_reader::scene_reader(const registry& types) : types_(types) {}
scene_reader::~scene_reader() = default;

void scene_reader::fail(const source_location& where, const std::string& message) const {
    throw file_error(where.str() + ": " + message);
}

std::string scene_reader::describe(const token& t) {
    switch (t.type) {
        case token::kind::end: return "the end of the file";
        case token::kind::number: return "the number " + t.text;
        case token::kind::string: return "the string \"" + t.text + '"';
        case token::kind::punct: return "'" + t.text + "'";
        case token::kind::word: return "'" + t.text + "'";
    }
    return t.text;
}

void scene_reader::fail_expected(std::string_view expected) {
    const token& t = peek();
    fail(t.where, "expected " + std::string(expected) + ", found " + describe(t));
}

void scene_reader::open(const std::filesystem::path& file) { push_file(file, nullptr); }

void scene_reader::open_text(std::string text, std::string name) {
    if (text.find('\0') != std::string::npos)
        throw file_error(name + ": this looks like a binary file, not a scene (it contains NUL bytes)");
    auto s = std::make_unique<source>();
    s->name = std::move(name);
    s->directory = std::filesystem::current_path();
    s->text = std::move(text);
    sources_.push_back(std::move(s));
}

void scene_reader::push_file(const std::filesystem::path& path, const source_location* from) {
    const std::string shown = path.string();
    auto fail_open = [&](const std::string& why) {
        if (from) fail(*from, "cannot include \"" + shown + "\": " + why);
        throw file_error(shown + ": " + why);
    };
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) fail_open("no such file");
    if (std::filesystem::is_directory(path, ec)) fail_open("it is a directory, not a scene file");
    const auto canonical = std::filesystem::weakly_canonical(path, ec);
    for (const auto& s : sources_)
        if (!s->canonical.empty() && s->canonical == canonical)
            fail_open("include cycle: that file is already being read (it includes itself, directly or not)");
    if (sources_.size() >= max_include_depth)
        fail_open("includes nested deeper than " + std::to_string(max_include_depth) + " files");
    std::ifstream in(path, std::ios::binary);
    if (!in) fail_open("cannot open it for reading (check its permissions)");
    std::string text;
    char buffer[1 << 16];
    while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
        text.append(buffer, static_cast<std::size_t>(in.gcount()));
        if (text.size() > max_file_bytes)
            fail_open("larger than " + std::to_string(max_file_bytes >> 20) + " MiB; is it really a scene?");
    }
    if (text.find('\0') != std::string::npos)
        fail_open("this looks like a binary file, not a scene (it contains NUL bytes)");
    auto s = std::make_unique<source>();
    s->name = shown;
    s->canonical = canonical;
    s->directory = path.parent_path();
    s->text = std::move(text);
    sources_.push_back(std::move(s));
}

token scene_reader::lex() {
    while (!sources_.empty()) {
        source& s = *sources_.back();
        // white space and comments
        while (s.pos < s.text.size()) {
            const char c = s.at();
            if (c == '#') {
                while (s.pos < s.text.size() && s.at() != '\n') s.advance();
            } else if (std::isspace(static_cast<unsigned char>(c))) {
                s.advance();
            } else {
                break;
            }
        }
        if (s.pos >= s.text.size()) {
            if (sources_.size() == 1) return {token::kind::end, "", 0, s.here()};
            sources_.pop_back();  // back to the including file
            continue;
        }
        token t;
        t.where = s.here();
        const char c = s.at();
        if (word_start(c)) {
            const std::size_t start = s.pos;
            while (s.pos < s.text.size() && word_char(s.at())) s.advance();
            t.type = token::kind::word;
            t.text = s.text.substr(start, s.pos - start);
            if (t.text == "include") {
                const token file = lex();
                if (file.type != token::kind::string)
                    fail(file.where, "expected a file name in double quotes after include, found " + describe(file));
                push_file(sources_.back()->directory / file.text, &file.where);
                continue;
            }
            return t;
        }
        if (number_start(c, s.at(1))) {
            const std::size_t start = s.pos;
            if (c == '+' || c == '-') s.advance();
            while (s.pos < s.text.size() &&
                   (std::isalnum(static_cast<unsigned char>(s.at())) || s.at() == '.' ||
                    ((s.at() == '-' || s.at() == '+') && (s.text[s.pos - 1] == 'e' || s.text[s.pos - 1] == 'E'))))
                s.advance();
            t.type = token::kind::number;
            t.text = s.text.substr(start, s.pos - start);
            const char* first = t.text.data() + (t.text[0] == '+' ? 1 : 0);
            const char* last = t.text.data() + t.text.size();
            const auto [end, err] = std::from_chars(first, last, t.number);
            if (err == std::errc::result_out_of_range)
                fail(t.where, "the number " + t.text + " is out of range (a double holds magnitudes from about 2.2e-308 to 1.8e308)");
            if (err != std::errc() || end != last || !std::isfinite(t.number))
                fail(t.where, "'" + t.text + "' is not a number (write numbers like 1, -2.5 or 1e-3)");
            return t;
        }
        if (c == '"') {
            s.advance();
            const std::size_t start = s.pos;
            while (s.pos < s.text.size() && s.at() != '"' && s.at() != '\n') s.advance();
            if (s.at() != '"') fail(t.where, "unterminated string: add the closing \" on the same line");
            t.type = token::kind::string;
            t.text = s.text.substr(start, s.pos - start);
            s.advance();
            return t;
        }
        if (c == '{' || c == '}' || c == '(' || c == ')' || c == ',') {
            t.type = token::kind::punct;
            t.text = std::string(1, c);
            s.advance();
            return t;
        }
        std::ostringstream shown;
        if (std::isprint(static_cast<unsigned char>(c)))
            shown << "'" << c << "'";
        else
            shown << "byte 0x" << std::hex << (static_cast<unsigned>(static_cast<unsigned char>(c)));
        fail(t.where, "unexpected character " + shown.str() +
                          " (a scene holds words, numbers, \"strings\", { } ( ) , and # comments)");
    }
    return {token::kind::end, "", 0, {"<no input>", 1, 1}};
}

const token& scene_reader::peek() {
    if (!has_lookahead_) {
        lookahead_ = lex();
        has_lookahead_ = true;
    }
    return lookahead_;
}

token scene_reader::next() {
    peek();
    has_lookahead_ = false;
    return std::move(lookahead_);
}

bool scene_reader::accept(char c) {
    const token& t = peek();
    if (t.type == token::kind::punct && t.text[0] == c) {
        next();
        return true;
    }
    return false;
}

void scene_reader::expect(char c, std::string_view context) {
    if (!accept(c)) fail_expected("'" + std::string(1, c) + "' " + std::string(context));
}

double scene_reader::read_number(std::string_view what) {
    if (peek().type != token::kind::number) fail_expected("a number for " + std::string(what));
    return next().number;
}

double scene_reader::read_positive(std::string_view what) {
    const token t = peek();
    const double v = read_number(what);
    if (!(v > 0)) fail(t.where, std::string(what) + " must be greater than 0, found " + t.text);
    return v;
}

double scene_reader::read_nonnegative(std::string_view what) {
    const token t = peek();
    const double v = read_number(what);
    if (v < 0) fail(t.where, std::string(what) + " must be 0 or more, found " + t.text);
    return v;
}

int scene_reader::read_int(std::string_view what, int lo, int hi) {
    const token t = peek();
    const double v = read_number(what);
    if (v != std::floor(v)) fail(t.where, std::string(what) + " must be a whole number, found " + t.text);
    if (v < lo || v > hi)
        fail(t.where, std::string(what) + " must be from " + std::to_string(lo) + " to " + std::to_string(hi) +
                          ", found " + t.text);
    return static_cast<int>(v);
}

std::string scene_reader::read_word(std::string_view what) {
    if (peek().type != token::kind::word) fail_expected(std::string(what));
    return next().text;
}

std::string scene_reader::read_string(std::string_view what) {
    if (peek().type != token::kind::string) fail_expected(std::string(what) + " in double quotes");
    return next().text;
}

double scene_reader::tuple_component(std::string_view what, const char* name) {
    return read_number(std::string(name) + " of " + std::string(what));
}

void scene_reader::tuple_numbers(std::string_view what, const char* const names[4], double out[4],
                                 double default_last) {
    // An optional label: a word before the numbers (the thesis's `center pos 0 0 0`). A key
    // of the block being read is never a label, so `eye look_at 0 0 0` says eye is missing.
    if (peek().type == token::kind::word) {
        const std::string& word = peek().text;
        const bool is_key = !open_blocks_.empty() &&
                            std::any_of(open_blocks_.back()->begin(), open_blocks_.back()->end(),
                                        [&](const property& p) { return p.key == word; });
        if (!is_key) next();
    }
    const bool bracketed = accept('(');
    for (int i = 0; i < 3; ++i) {
        if (bracketed && i > 0) expect(',', "between the components of " + std::string(what));
        out[i] = tuple_component(what, names[i]);
    }
    out[3] = default_last;
    if (bracketed) {
        if (accept(',')) out[3] = tuple_component(what, names[3]);
        expect(')', "to close " + std::string(what));
    } else if (peek().type == token::kind::number) {
        out[3] = next().number;
    }
}

point scene_reader::read_point(std::string_view what) {
    static const char* const names[4] = {"x", "y", "z", "w"};
    double v[4];
    tuple_numbers(what, names, v, 1);
    return {v[0], v[1], v[2], v[3]};
}

vector scene_reader::read_vector(std::string_view what) {
    static const char* const names[4] = {"x", "y", "z", "w"};
    double v[4];
    tuple_numbers(what, names, v, 0);
    return {v[0], v[1], v[2], v[3]};
}

color scene_reader::read_color(std::string_view what) {
    static const char* const names[4] = {"red", "green", "blue", "alpha"};
    double v[4];
    tuple_numbers(what, names, v, 0);
    return {v[0], v[1], v[2], v[3]};
}

std::unique_ptr<rtab_component> scene_reader::read_object() {
    const token t = peek();
    if (t.type != token::kind::word) fail_expected("an object type such as SPHERE");
    if (!registry::valid_name(t.text))
        fail(t.where, "'" + t.text + "' is not an object type: type names are 1 to 10 upper-case letters (like SPHERE)");
    auto object = types_.create(t.text);
    if (!object) {
        std::string known;
        for (const auto& n : types_.names()) known += (known.empty() ? "" : ", ") + n;
        fail(t.where, "unknown object type '" + t.text + "'; the types this program knows are: " + known);
    }
    next();
    object->read(*this);
    return object;
}

void scene_reader::read_child(rtab_composite& parent) {
    if (at_end()) fail_expected("'}' to close " + parent.type_name());
    const source_location where = peek().where;
    std::unique_ptr<rtab_component> child = read_object();
    try {
        parent.insert(std::move(child));
    } catch (const usage_error& refused) {
        fail(where, refused.what());
    }
}

void scene_reader::read_children(rtab_composite& parent) {
    expect('{', "to open the children of " + parent.type_name());
    while (!accept('}')) read_child(parent);
}

void scene_reader::read_block(std::string_view owner, const std::vector<property>& properties) {
    const std::string who(owner);
    expect('{', "after " + who);
    open_blocks_.push_back(&properties);
    struct pop_on_exit {
        std::vector<const std::vector<property>*>& blocks;
        ~pop_on_exit() { blocks.pop_back(); }
    } pop{open_blocks_};
    std::vector<source_location> seen(properties.size());
    std::vector<bool> given(properties.size(), false);
    while (!accept('}')) {
        const token key = peek();
        if (key.type != token::kind::word) {
            if (key.type == token::kind::end) fail_expected("'}' to close " + who);
            fail_expected("a property of " + who + " or '}'");
        }
        const auto it = std::find_if(properties.begin(), properties.end(),
                                     [&](const property& p) { return p.key == key.text; });
        if (it == properties.end()) {
            std::string keys;
            for (const auto& p : properties) keys += (keys.empty() ? "" : ", ") + std::string(p.key);
            fail(key.where, who + " has no property '" + key.text + "'; its properties are: " + keys);
        }
        const auto index = static_cast<std::size_t>(it - properties.begin());
        if (given[index])
            fail(key.where, who + " " + key.text + " is given twice (first at " + seen[index].str() + ")");
        given[index] = true;
        seen[index] = key.where;
        next();
        it->read();
    }
}

}  // namespace vl
