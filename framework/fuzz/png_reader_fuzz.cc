// libFuzzer target: the PNG reader (libpng behind vl::read_png). Whatever the bytes, it must
// return an image or throw vl::image_error; in particular libpng's longjmp must come back
// safely, and no header may make it allocate more than the data can hold.
#include "vl/image_io.hh"

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    try {
        (void)vl::read_png(std::span<const std::uint8_t>(data, size), "fuzz-input");
    } catch (const vl::image_error&) {
    }
    return 0;
}
