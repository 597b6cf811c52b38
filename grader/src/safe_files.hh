#pragma once
/// \file
/// \brief The grader's only ways to touch files near a sandbox: write a new file without
/// following or replacing anything, and read a file a sandbox wrote only when it is a
/// regular file of bounded size. Together with folders that no sandbox can write, these
/// keep a planted link from making the grader read or write anything else.
#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

namespace vl::grader {

/// Writes `data` to a new file: never through a link, never over an existing file.
/// Throws grader_error (a full disk is the grader's problem, not the student's).
void write_new_file(const std::filesystem::path& file, std::string_view data);

/// Writes `data` to `file` whole or not at all: a temporary file beside it (named for this
/// process), flushed to disk, then a rename.
void replace_file(const std::filesystem::path& file, std::string_view data);

/// `file`'s path, size, modification time and inode ("PATH missing;" when it cannot be
/// stat()ed): what a rebuild, an edit or an upgrade changes. The caches of what is measured
/// once per build compare these.
std::string file_identity(const std::filesystem::path& file);

/// Keeps `data` as `file` (replace_file), making its folder first, when it can: for a cache
/// of what is measured once per build, which only saves time, so a build folder this user
/// cannot write costs nothing else.
void keep_cache_file(const std::filesystem::path& file, std::string_view data);

/// The contents of `file` when it is a regular file (not a link) of at most `cap` bytes;
/// otherwise empty.
std::string read_regular_file(const std::filesystem::path& file, std::size_t cap);

}  // namespace vl::grader
