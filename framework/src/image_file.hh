#pragma once
// What the image readers and writers (pnm.cc, png.cc, pfm.cc, image_io.cc) share: a whole
// file's bytes, the guarded writer, the size checks every reader makes before allocating,
// the reader of PNM and PFM text headers, and the conversion a writer makes before
// writing. What is not inline here is in image_file.cc. Private to the framework's
// sources, not a public header.
#include "vl/image_io.hh"

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace vl::image_detail {

// ---------------------------------------------------------------------------------------
// Files: read whole, write whole rows.

struct file_closer {
    void operator()(std::FILE* f) const { std::fclose(f); }
};
using file_ptr = std::unique_ptr<std::FILE, file_closer>;

std::string file_name(const std::filesystem::path& file);

// A whole file's bytes. A regular file is mapped into memory (POSIX mmap), which costs no
// copy: reading a 50 MB PPM touches its bytes once, on the way into the image. Anything
// else (a pipe, /dev/stdin) is read in large chunks.
class file_bytes {
public:
    explicit file_bytes(const std::filesystem::path& file);
    ~file_bytes();
    file_bytes(const file_bytes&) = delete;
    file_bytes& operator=(const file_bytes&) = delete;

    std::span<const std::uint8_t> bytes() const { return mapped_.empty() ? std::span<const std::uint8_t>(read_) : mapped_; }

private:
    void read_chunks(int fd);

    std::string name_;
    std::span<const std::uint8_t> mapped_;
    std::vector<std::uint8_t> read_;
};

// Opens for writing; closes on destruction. finish() reports a failed final flush.
class output_file {
public:
    explicit output_file(const std::filesystem::path& file);
    std::FILE* get() const { return f_.get(); }
    const std::string& name() const { return name_; }
    void write(const void* data, std::size_t n) {
        if (n != 0 && std::fwrite(data, 1, n, f_.get()) != n) fail();
    }
    void write(std::string_view s) { write(s.data(), s.size()); }
    void finish() {
        if (std::fclose(f_.release()) != 0) fail();
    }
    [[noreturn]] void fail() const;

private:
    std::string name_;
    file_ptr f_;
};

// "W x H", for messages.
std::string size_text(std::int64_t w, std::int64_t h);

// The checks every reader makes before allocating.
void check_size(const std::string& name, std::int64_t w, std::int64_t h);

// ---------------------------------------------------------------------------------------
// The text header of PNM and PFM files.

inline bool pnm_space(std::uint8_t c) { return c == ' ' || c == '\t' || c == '\n' || c == '\v' || c == '\f' || c == '\r'; }
inline bool digit(std::uint8_t c) { return c >= '0' && c <= '9'; }

// Reads the text tokens of a PNM or PFM header; '#' starts a comment up to the line's end.
class header_reader {
public:
    header_reader(std::span<const std::uint8_t> bytes, std::size_t pos, const std::string& name)
        : bytes_(bytes), pos_(pos), name_(name) {}

    void skip_space_and_comments() {
        while (pos_ < bytes_.size()) {
            if (pnm_space(bytes_[pos_])) {
                ++pos_;
            } else if (bytes_[pos_] == '#') {
                while (pos_ < bytes_.size() && bytes_[pos_] != '\n' && bytes_[pos_] != '\r') ++pos_;
            } else {
                break;
            }
        }
    }

    // A decimal number of at most `max`; `what` names it in messages ("the width").
    std::int64_t number(const char* what, std::int64_t max) {
        skip_space_and_comments();
        if (pos_ >= bytes_.size()) throw image_error(name_, std::string("the header ends before ") + what + " (the file is truncated)");
        if (bytes_[pos_] == '-') throw image_error(name_, std::string(what) + " is negative");
        if (!digit(bytes_[pos_]))
            throw image_error(name_, std::string(what) + " is not a number (found " + describe(bytes_[pos_]) + ")");
        std::int64_t v = 0;
        while (pos_ < bytes_.size() && digit(bytes_[pos_])) {
            v = v * 10 + (bytes_[pos_++] - '0');
            if (v > max) throw image_error(name_, std::string(what) + " is larger than " + std::to_string(max));
        }
        if (pos_ < bytes_.size() && !pnm_space(bytes_[pos_]) && bytes_[pos_] != '#')
            throw image_error(name_, std::string(what) + " is followed by " + describe(bytes_[pos_]) + ", not white space");
        return v;
    }

    // A non-blank token (for the PFM scale, which is a decimal fraction).
    std::string_view token(const char* what) {
        skip_space_and_comments();
        const std::size_t start = pos_;
        while (pos_ < bytes_.size() && !pnm_space(bytes_[pos_]) && pos_ - start < 64) ++pos_;
        if (start == pos_) throw image_error(name_, std::string("the header ends before ") + what + " (the file is truncated)");
        return {reinterpret_cast<const char*>(bytes_.data()) + start, pos_ - start};
    }

    // The single white-space byte that ends a header before binary samples.
    void end_of_header(const char* after) {
        if (pos_ >= bytes_.size()) throw image_error(name_, "the file ends after the header: no samples (truncated)");
        if (!pnm_space(bytes_[pos_]))
            throw image_error(name_, std::string("expected one white-space byte after ") + after + ", found " + describe(bytes_[pos_]));
        ++pos_;
    }

    void advance() { ++pos_; }
    std::size_t left() const { return bytes_.size() - pos_; }
    const std::uint8_t* here() const { return bytes_.data() + pos_; }

    // A byte as a message shows it: 'P', or byte 0x0a.
    static std::string describe(std::uint8_t c) {
        if (c >= 0x21 && c < 0x7f) return std::string("'") + static_cast<char>(c) + "'";
        char hex[8];
        std::snprintf(hex, sizeof hex, "0x%02x", c);
        return std::string("byte ") + hex;
    }

private:
    std::span<const std::uint8_t> bytes_;
    std::size_t pos_;
    const std::string& name_;
};

// ---------------------------------------------------------------------------------------
// Writers

// `img` with the given sample type and channel count: `img` itself when it has them (no
// copy of a 50 MB image just to write it), else a converted copy kept in `keep`.
const image& as_needed(const image& img, sample_type type, int channels, std::optional<image>& keep);

// True if `bytes` start with the 8-byte PNG signature (png.cc).
bool has_png_signature(std::span<const std::uint8_t> bytes);

}  // namespace vl::image_detail
