#pragma once
/// \file
/// \brief Reads scene files: tokens, comments, `include`, typed values, objects.
///
/// The format is described in docs/scene-format.md. Every error is a vl::file_error
/// whose message is `FILE:LINE:COL: what was expected, what was found`.

#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "vl/error.hh"
#include "vl/rt_base_objects.hh"

namespace vl {

class registry;

/// \brief A place in a scene file.
struct source_location {
    std::string file;  ///< as given (relative to the including file for includes)
    int line = 1;      ///< counted from 1
    int column = 1;    ///< counted from 1, in bytes
    /// `FILE:LINE:COL`.
    std::string str() const;
};

/// \brief One token of a scene file.
struct token {
    /// What the token is.
    enum class kind {
        word,    ///< letters, digits and `_`, starting with a letter: `SPHERE`, `radius`
        number,  ///< a finite decimal number: `1`, `-2.5`, `1e-3`
        string,  ///< text between double quotes (the quotes are not kept)
        punct,   ///< one of `{ } ( ) ,`
        end      ///< the end of the outermost file
    };
    kind type = kind::end;  ///< what it is
    std::string text;       ///< its text as written (a string's without quotes)
    double number = 0;      ///< its value, for kind::number
    source_location where;  ///< where it starts
};

/// \brief A scene file as a stream of tokens, with typed reads that report errors at the
/// token where they happen.
///
/// `include "other.ray_trace"` anywhere between tokens is replaced by the other file's
/// tokens (the path is relative to the including file); include cycles and nesting
/// deeper than 16 files are errors. `#` starts a comment that runs to the end of the line.
class scene_reader {
public:
    /// A reader that creates objects through `types`.
    explicit scene_reader(const registry& types);
    ~scene_reader();
    scene_reader(const scene_reader&) = delete;
    scene_reader& operator=(const scene_reader&) = delete;

    /// Starts reading `file`. Throws vl::file_error when it cannot be read.
    void open(const std::filesystem::path& file);
    /// Starts reading `text` as if it were a file called `name` (includes are resolved
    /// relative to the current directory).
    void open_text(std::string text, std::string name);

    /// \name Tokens
    ///@{
    /// The next token, not consumed.
    const token& peek();
    /// The next token, consumed.
    token next();
    /// True when every file has been read.
    bool at_end() { return peek().type == token::kind::end; }
    /// Consumes the next token when it is the punctuation `c`.
    bool accept(char c);
    /// Consumes the punctuation `c` or fails with "expected 'c' `context`".
    void expect(char c, std::string_view context);
    ///@}

    /// \name Typed reads
    /// `what` names the value in error messages ("radius of SPHERE").
    ///@{
    double read_number(std::string_view what);
    /// A number > 0.
    double read_positive(std::string_view what);
    /// A number >= 0.
    double read_nonnegative(std::string_view what);
    /// A whole number in [lo, hi].
    int read_int(std::string_view what, int lo, int hi);
    /// A word (letters, digits, `_`).
    std::string read_word(std::string_view what);
    /// A double-quoted string.
    std::string read_string(std::string_view what);
    /// An optional label (a word, ignored, as in the thesis), then x y z and an optional
    /// w (default 1), bare or as `(x, y, z)` / `(x, y, z, w)`.
    point read_point(std::string_view what);
    /// As read_point(), w defaulting to 0.
    vector read_vector(std::string_view what);
    /// As read_point(), for r g b and an optional a (default 0).
    color read_color(std::string_view what);
    ///@}

    /// \name Objects and property blocks
    ///@{
    /// A registered type name followed by what that type's read() takes.
    std::unique_ptr<rtab_component> read_object();
    /// `{ OBJECT OBJECT ... }`, each inserted into `parent` as by read_child().
    void read_children(rtab_composite& parent);
    /// One object, inserted into `parent`. When insert() refuses it (a vl::usage_error:
    /// a composite that cannot hold it), fails with that message at the object's place.
    void read_child(rtab_composite& parent);

    /// One key of a property block and what reads its value.
    struct property {
        std::string_view key;         ///< the word that introduces the value
        std::function<void()> read;   ///< reads the value (through this reader)
    };
    /// `{ key value key value ... }`: each key at most once, in any order; a missing key
    /// keeps its default. `owner` names the block in messages ("SPHERE", "camera").
    void read_block(std::string_view owner, const std::vector<property>& properties);
    ///@}

    /// Throws vl::file_error `WHERE: message`.
    [[noreturn]] void fail(const source_location& where, const std::string& message) const;
    /// Throws `WHERE: expected EXPECTED, found TOKEN` at the next token.
    [[noreturn]] void fail_expected(std::string_view expected);

    /// A token described for a message: `'radius'`, `the number 3`, `the end of the file`.
    static std::string describe(const token& t);

private:
    struct source;
    token lex();
    void push_file(const std::filesystem::path& path, const source_location* from);
    double tuple_component(std::string_view what, const char* name);
    void tuple_numbers(std::string_view what, const char* const names[4], double out[4], double default_last);

    const registry& types_;
    std::vector<std::unique_ptr<source>> sources_;
    std::vector<const std::vector<property>*> open_blocks_;  // innermost last: their keys are never labels
    token lookahead_;
    bool has_lookahead_ = false;
};

}  // namespace vl
