// Malformed image files: each must give an error `FILE: what is wrong`, never a crash or a
// huge allocation. The files are made here, in a scratch directory.
#include "vl/image_io.hh"
#include "vl/vfb.hh"

#include "image_test_support.hh"

#include "vl/catch.hh"

#include <cstdint>
#include <vector>

using namespace vl;

namespace {

// The CRC of PNG chunks (ISO 3309, as given in the PNG specification's annex D).
std::uint32_t crc32(const std::string& bytes) {
    std::uint32_t c = 0xffffffffu;
    for (const unsigned char b : bytes) {
        c ^= b;
        for (int k = 0; k < 8; ++k) c = (c >> 1) ^ (0xedb88320u & (0u - (c & 1u)));
    }
    return c ^ 0xffffffffu;
}

std::string big_endian(std::uint32_t v) {
    return {static_cast<char>(v >> 24), static_cast<char>(v >> 16), static_cast<char>(v >> 8), static_cast<char>(v)};
}

// A valid 2 x 2 RGB PNG, written by our own writer.
std::string good_png(const test::temp_dir& dir) {
    write_image(dir / "good.png", image(2, 2, 3, sample_type::u8));
    return test::read_bytes(dir / "good.png");
}

// `png` with the IHDR's width and height replaced and its CRC made right again, so that
// only the sizes are wrong.
std::string with_size(std::string png, std::uint32_t w, std::uint32_t h) {
    png.replace(16, 4, big_endian(w));
    png.replace(20, 4, big_endian(h));
    png.replace(29, 4, big_endian(crc32(png.substr(12, 17))));  // over "IHDR" and its 13 bytes
    return png;
}

// `png` with the first byte of the IDAT data changed (and the CRC fixed): bad zlib data.
std::string with_bad_idat(std::string png) {
    const std::size_t at = png.find("IDAT");
    const std::uint32_t length = (static_cast<unsigned char>(png[at - 4]) << 24) | (static_cast<unsigned char>(png[at - 3]) << 16) |
                                 (static_cast<unsigned char>(png[at - 2]) << 8) | static_cast<unsigned char>(png[at - 1]);
    png[at + 4] = '\x00';  // not a zlib header
    png.replace(at + 4 + length, 4, big_endian(crc32(png.substr(at, 4 + length))));
    return png;
}

struct bad_file {
    const char* name;
    std::string bytes;
    const char* problem;  // a part of the expected message
};

}  // namespace

TEST_CASE("bad images: every malformed file gives `FILE: what is wrong`", "[image][errors]") {
    test::temp_dir dir;
    const std::string png = good_png(dir);
    const std::vector<bad_file> files = {
        {"empty.ppm", "", "empty"},
        {"garbage.png", "hello, world\n", "not an image"},
        {"wrong_magic.ppm", "P7\n2 2\n255\n", "not an image"},
        {"magic_only.ppm", "P6", "header ends before the width"},
        {"magic_glued.ppm", "P6x 2 2 255\n", "not a PNM file"},
        {"negative_width.ppm", "P6\n-3 2\n255\n", "width is negative"},
        {"zero_width.ppm", "P6\n0 2\n255\n", "at least one pixel"},
        {"wide.ppm", "P6\n70000 2\n255\n", "width is larger than 65536"},
        {"huge_number.ppm", "P6\n99999999999999999999999 2\n255\n", "width is larger"},
        {"too_many_pixels.ppm", "P6\n60000 60000\n255\n", "more than the 268435456 pixels"},
        {"width_not_number.ppm", "P6\nabc 2\n255\n", "width is not a number"},
        {"width_glued.ppm", "P6\n2x 2\n255\n", "followed by 'x'"},
        {"maxval_zero.ppm", "P6\n2 2\n0\n", "maxval is 0"},
        {"maxval_big.ppm", "P6\n2 2\n65536\n", "maxval is 65536; it must be 1 to 65535"},
        {"no_space_after_maxval.ppm", "P6\n2 2\n255", "ends after the header"},
        {"truncated_raster.ppm", "P6\n2 2\n255\n12345", "truncated"},
        {"truncated_big.ppm", "P6\n4096 4096\n255\n" + std::string(100, 'x'), "truncated"},
        {"truncated_16bit.pgm", "P5\n2 2\n65535\n123456", "truncated"},
        {"truncated_bits.pbm", "P4\n9 2\n\x01", "truncated"},
        {"sample_over_maxval.pgm", std::string("P5\n2 1\n3\n") + '\x00' + '\x09', "more than the maxval 3"},
        {"ascii_truncated.ppm", "P3\n2 1\n255\n1 2 3 4 5\n", "truncated"},
        {"ascii_not_number.pgm", "P2\n2 1\n255\n1 x\n", "sample is not a number"},
        {"ascii_over_maxval.ppm", "P3\n1 1\n255\n256 0 0\n", "more than the maxval 255"},
        {"ascii_bad_bit.pbm", "P1\n3 1\n0 2 1\n", "not 0 or 1"},
        {"png_signature_only.png", png.substr(0, 8), "bad PNG"},
        {"png_truncated.png", png.substr(0, png.size() / 2), "bad PNG"},
        {"png_bad_crc.png", [&] { auto p = png; p[17] ^= 0x40; return p; }(), "bad PNG"},
        {"png_zero_width.png", with_size(png, 0, 2), "bad PNG"},
        {"png_too_wide.png", with_size(png, 70000, 2), "bad PNG"},
        {"png_too_many_pixels.png", with_size(png, 60000, 60000), "more than the 268435456 pixels"},
        {"png_claims_more_than_it_holds.png", with_size(png, 16000, 16000), "more than a"},
        {"png_bad_zlib.png", with_bad_idat(png), "bad PNG"},
        {"pfm_bad_scale.pfm", "PF\n2 2\nabc\n", "scale 'abc' is not a non-zero number"},
        {"pfm_zero_scale.pfm", "PF\n2 2\n0.0\n", "not a non-zero number"},
        {"pfm_negative_height.pfm", "PF\n2 -2\n-1.0\n", "height is negative"},
        {"pfm_truncated.pfm", "Pf\n2 2\n-1.0\n" + std::string(15, '\0'), "truncated"},
        {"pfm_no_scale.pfm", "PF\n2 2", "header ends before the scale"},
    };
    REQUIRE(files.size() >= 20);
    for (const auto& f : files) {
        const auto path = dir / f.name;
        test::write_bytes(path, f.bytes);
        INFO(f.name);
        try {
            (void)read_image(path);
            FAIL("read_image accepted " << f.name);
        } catch (const image_error& e) {
            const std::string message = e.what();
            CHECK(message.rfind(path.string() + ": ", 0) == 0);  // starts with the file's name
            CHECK_THAT(message, Catch::Contains(f.problem));
        }
        // vfb::load reports the same way, and a bad image is a bad file like any other.
        vfb v(3, 3);
        CHECK_THROWS_AS(v.load(path), image_error);
        CHECK_THROWS_AS(v.load(path), file_error);
    }
}

TEST_CASE("bad images: a directory is not an image", "[image][errors]") {
    test::temp_dir dir;
    std::filesystem::create_directory(dir / "sub.png");
    CHECK_THROWS_WITH(read_image(dir / "sub.png"), Catch::Contains("sub.png: is a directory"));
}

TEST_CASE("bad images: a header comment may hold anything, even what looks like numbers", "[image][pnm]") {
    test::temp_dir dir;
    test::write_bytes(dir / "c.pgm", std::string("P5\n#99 99\n1#x\n# 7\n1\n#\n255\n") + '\x2a');
    // "#\n255": the comment ends at the line, and the maxval follows.
    const image img = read_image(dir / "c.pgm");
    CHECK(img.width() == 1);
    CHECK(img.samples<std::uint8_t>()[0] == 42);
}
