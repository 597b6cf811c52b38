#pragma once
// Helpers shared by the image tests: file writers and ImageMagick, and the scratch
// directory (support/temp_dir.hh). Students need not read this file.
#include "support/temp_dir.hh"

#include "vl/catch.hh"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace vl::test {

/// Writes `bytes` to `file` as they are.
inline void write_bytes(const std::filesystem::path& file, const std::string& bytes) {
    std::ofstream(file, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

/// Reads a whole file.
inline std::string read_bytes(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

/// True if ImageMagick's `identify` can be run.
inline bool have_imagemagick() { return std::system("identify -version >/dev/null 2>&1") == 0; }

/// What `identify -format "%w %h"` says of a file ("" if it fails).
inline std::string identify_size(const std::filesystem::path& file) {
    const std::string command = "identify -format '%w %h' '" + file.string() + "' 2>/dev/null";
    std::FILE* pipe = ::popen(command.c_str(), "r");
    if (!pipe) return "";
    std::string out;
    char buf[128];
    while (std::fgets(buf, sizeof buf, pipe)) out += buf;
    return ::pclose(pipe) == 0 ? out : "";
}

}  // namespace vl::test
