#include "safe_files.hh"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "install.hh"

namespace vl::grader {

std::string file_identity(const std::filesystem::path& file) {
    struct stat st {};
    if (stat(file.c_str(), &st) != 0) return file.string() + " missing;";
    char text[160];
    std::snprintf(text, sizeof text, " %lld %lld.%09ld %llu;", static_cast<long long>(st.st_size),
                  static_cast<long long>(st.st_mtim.tv_sec), st.st_mtim.tv_nsec,
                  static_cast<unsigned long long>(st.st_ino));
    return file.string() + text;
}

void keep_cache_file(const std::filesystem::path& file, std::string_view data) {
    std::error_code ec;
    std::filesystem::create_directories(file.parent_path(), ec);
    if (ec) return;
    try {
        replace_file(file, data);
    } catch (const grader_error&) {
    }
}

void write_new_file(const std::filesystem::path& file, std::string_view data) {
    const int fd = open(file.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
    if (fd < 0) throw grader_error("cannot write " + file.string() + ": " + std::strerror(errno));
    std::size_t done = 0;
    while (done < data.size()) {
        const ssize_t w = ::write(fd, data.data() + done, data.size() - done);
        if (w <= 0) {
            const int err = errno;
            close(fd);
            throw grader_error("cannot write " + file.string() + ": " + std::strerror(err));
        }
        done += static_cast<std::size_t>(w);
    }
    if (close(fd) != 0) throw grader_error("cannot write " + file.string() + ": " + std::strerror(errno));
}

void replace_file(const std::filesystem::path& file, std::string_view data) {
    // Named for this process, so that two processes replacing one file (a cluster's array
    // tasks) never write the same temporary file; flushed to disk before the rename, so
    // that a machine that goes down keeps the old file or the new one, never a torn one.
    const std::filesystem::path temporary = file.string() + ".partial-" + std::to_string(getpid());
    std::error_code ec;
    std::filesystem::remove(temporary, ec);
    write_new_file(temporary, data);
    if (const int fd = open(temporary.c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC); fd >= 0) {
        fsync(fd);
        close(fd);
    }
    std::filesystem::rename(temporary, file, ec);
    if (ec) throw grader_error("cannot write " + file.string() + ": " + ec.message());
}

std::string read_regular_file(const std::filesystem::path& file, std::size_t cap) {
    const int fd = open(file.c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC);
    struct stat st {};
    if (fd < 0 || fstat(fd, &st) != 0 || !S_ISREG(st.st_mode) || static_cast<std::size_t>(st.st_size) > cap) {
        if (fd >= 0) close(fd);
        return {};
    }
    std::string s(static_cast<std::size_t>(st.st_size), '\0');
    std::size_t got = 0;
    while (got < s.size()) {
        const ssize_t r = read(fd, s.data() + got, s.size() - got);
        if (r <= 0) break;
        got += static_cast<std::size_t>(r);
    }
    close(fd);
    s.resize(got);
    return s;
}

}  // namespace vl::grader
