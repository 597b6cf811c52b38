// libFuzzer target: the PNM and PFM readers. Whatever the bytes, the reader must return an
// image or throw vl::image_error; a crash, a sanitizer report, any other exception or an
// allocation beyond libFuzzer's limit is a bug.
#include "vl/image_io.hh"

#include <cstddef>
#include <cstdint>
#include <cstring>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const std::uint8_t png_signature[] = {0x89, 'P', 'N', 'G'};
    if (size >= 4 && std::memcmp(data, png_signature, 4) == 0) return 0;  // the PNG target's job
    try {
        (void)vl::read_image(std::span<const std::uint8_t>(data, size), "fuzz-input");
    } catch (const vl::image_error&) {
    }
    return 0;
}
