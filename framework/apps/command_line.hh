#pragma once
/// \file
/// \brief What the framework's programs (rt, tradeoff) share in reading a command line.
#include <charconv>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "vl/scene.hh"

namespace vl::apps {

/// A command-line mistake: the program prints `NAME: MESSAGE` with a hint, exit status 2.
struct command_line_error {
    std::string message;
};

/// `a, b, c`, or `none` for no names.
inline std::string listing(const std::vector<std::string>& names) {
    std::string out;
    for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
    return out.empty() ? "none" : out;
}

/// `text` as a whole number in [lo, hi]; else a command_line_error naming `flag`.
inline int to_int(std::string_view flag, std::string_view text, int lo, int hi) {
    int v = 0;
    const auto [end, err] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (err != std::errc() || end != text.data() + text.size() || v < lo || v > hi)
        throw command_line_error{std::string(flag) + " wants a whole number from " + std::to_string(lo) + " to " +
                                 std::to_string(hi) + ", not '" + std::string(text) + "'"};
    return v;
}

/// `--size WIDTHxHEIGHT` (each 1 to vl::max_image_side); `example` goes into the message.
inline std::pair<int, int> to_size(std::string_view text, std::string_view example) {
    const auto x = text.find('x');
    if (x == std::string_view::npos)
        throw command_line_error{"--size wants WIDTHxHEIGHT, like " + std::string(example) + ", not '" +
                                 std::string(text) + "'"};
    return {to_int("--size width", text.substr(0, x), 1, vl::max_image_side),
            to_int("--size height", text.substr(x + 1), 1, vl::max_image_side)};
}

}  // namespace vl::apps
