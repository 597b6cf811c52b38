// The plumbing every image format shares (declared in image_file.hh): reading a whole
// file, the guarded writer, the size checks made before allocating, and the conversion
// before writing.
#include "image_file.hh"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

namespace vl::image_detail {

std::string file_name(const std::filesystem::path& file) { return file.string(); }

file_bytes::file_bytes(const std::filesystem::path& file) : name_(file_name(file)) {
    std::error_code ec;
    if (std::filesystem::is_directory(file, ec)) throw image_error(name_, "is a directory, not an image file");
    const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) throw image_error(name_, std::string("cannot open: ") + std::strerror(errno));
    struct stat st {};
    if (::fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && st.st_size > 0) {
        void* p = ::mmap(nullptr, static_cast<std::size_t>(st.st_size), PROT_READ, MAP_PRIVATE | MAP_POPULATE, fd, 0);
        if (p != MAP_FAILED) {
            mapped_ = {static_cast<const std::uint8_t*>(p), static_cast<std::size_t>(st.st_size)};
            ::close(fd);
            return;
        }
    }
    read_chunks(fd);
    ::close(fd);
}

file_bytes::~file_bytes() {
    if (!mapped_.empty()) ::munmap(const_cast<std::uint8_t*>(mapped_.data()), mapped_.size());
}

void file_bytes::read_chunks(int fd) {
    std::size_t used = 0;
    for (std::size_t chunk = std::size_t{1} << 20;; chunk = std::min(chunk * 2, std::size_t{1} << 28)) {
        read_.resize(used + chunk);
        const ::ssize_t got = ::read(fd, read_.data() + used, chunk);
        if (got < 0) {
            if (errno == EINTR) continue;
            throw image_error(name_, std::string("read failed: ") + std::strerror(errno));
        }
        if (got == 0) break;
        used += static_cast<std::size_t>(got);
    }
    read_.resize(used);
}

output_file::output_file(const std::filesystem::path& file) : name_(file_name(file)), f_(std::fopen(file.c_str(), "wb")) {
    if (!f_) throw image_error(name_, std::string("cannot create: ") + std::strerror(errno));
    // A larger buffer turns row-sized writes into fewer system calls; 64 KB stays below
    // malloc's mmap threshold, so it is reused memory, not fresh pages every time.
    std::setvbuf(f_.get(), nullptr, _IOFBF, std::size_t{1} << 16);
}

void output_file::fail() const {
    throw image_error(name_, std::string("write failed: ") + std::strerror(errno) + " (is the disk full?)");
}

std::string size_text(std::int64_t w, std::int64_t h) { return std::to_string(w) + " x " + std::to_string(h); }

void check_size(const std::string& name, std::int64_t w, std::int64_t h) {
    if (w < 1 || h < 1) throw image_error(name, "the image is " + size_text(w, h) + "; it needs at least one pixel");
    if (w > max_image_dimension || h > max_image_dimension)
        throw image_error(name, "the image is " + size_text(w, h) + "; this reader takes at most " +
                                    std::to_string(max_image_dimension) + " pixels in each direction");
    if (w * h > max_image_pixels)
        throw image_error(name, "the image is " + size_text(w, h) + ", more than the " +
                                    std::to_string(max_image_pixels) + " pixels this reader takes");
}

const image& as_needed(const image& img, sample_type type, int channels, std::optional<image>& keep) {
    if (img.type() == type && img.channels() == channels) return img;
    keep = convert_channels(img.type() == type ? img : convert_samples(img, type), channels);
    return *keep;
}

}  // namespace vl::image_detail
