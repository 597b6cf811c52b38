#pragma once
// Helpers shared by the image tests: a scratch directory and file writers. Students need not
// read this file.
#include <catch2/catch.hpp>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace vl::test {

/// A fresh directory under the system's temp directory, removed with everything in it.
class scratch_dir {
public:
    scratch_dir() {
        static int counter = 0;
        path_ = std::filesystem::temp_directory_path() /
                ("vl_image_test_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
        std::filesystem::create_directories(path_);
    }
    ~scratch_dir() {
        std::error_code ec;
        std::filesystem::remove_all(path_, ec);
    }
    scratch_dir(const scratch_dir&) = delete;
    scratch_dir& operator=(const scratch_dir&) = delete;
    std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

private:
    std::filesystem::path path_;
};

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
