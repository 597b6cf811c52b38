// Image files, whatever their format: read_image() recognises the format by the file's
// first bytes and write_image() by the file name's extension, and each calls the reader or
// writer of that format (pnm.cc, png.cc, pfm.cc).
//
// Every reader follows the same rule: read the header, check each number it gives against
// what this reader takes *and* against the bytes the file really has, and only then
// allocate. A 20-byte file claiming to be 60000 x 60000 is an error message, not a
// 10 GB allocation.
#include "image_file.hh"

#include <algorithm>
#include <cctype>

namespace vl {

using namespace image_detail;

image read_image(std::span<const std::uint8_t> bytes, const std::string& name) {
    if (bytes.empty()) throw image_error(name, "the file is empty");
    if (has_png_signature(bytes)) return read_png(bytes, name);
    if (bytes.size() >= 2 && bytes[0] == 'P' && (bytes[1] == 'F' || bytes[1] == 'f')) return read_pfm(bytes, name);
    if (bytes.size() >= 2 && bytes[0] == 'P' && bytes[1] >= '1' && bytes[1] <= '6') return read_pnm(bytes, name);
    throw image_error(name, "not an image this reader knows: expected PNM (P1-P6), PFM (PF, Pf) or PNG, but the file starts with " +
                                header_reader::describe(bytes[0]));
}

image read_image(const std::filesystem::path& file) {
    const file_bytes contents(file);
    return read_image(contents.bytes(), file_name(file));
}

void write_image(const std::filesystem::path& file, const image& img) {
    std::string ext = file.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (ext == ".ppm" && img.channels() <= 2) {
        write_pnm(file, convert_channels(img, 3));
    } else if (ext == ".ppm" || ext == ".pnm") {
        write_pnm(file, img);
    } else if (ext == ".pgm" && img.channels() != 1) {
        write_pnm(file, convert_channels(img, 1));
    } else if (ext == ".pgm") {
        write_pnm(file, img);
    } else if (ext == ".pbm") {
        write_pnm(file, img, true);
    } else if (ext == ".png") {
        write_png(file, img);
    } else if (ext == ".pfm") {
        write_pfm(file, img);
    } else {
        throw image_error(file_name(file), "unknown image extension '" + ext +
                                               "': use .png, .ppm, .pgm, .pbm, .pnm or .pfm");
    }
}

}  // namespace vl
