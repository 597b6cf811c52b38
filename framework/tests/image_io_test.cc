// Image files: every format written and read back, the PNG variants libpng expands, the
// ASCII PNM forms, and what ImageMagick makes of our files.
#include "vl/image_io.hh"
#include "vl/pixel.hh"

#include "image_test_support.hh"

#include "vl/catch.hh"

#include <algorithm>
#include <cstring>

using namespace vl;

namespace {

const std::filesystem::path data_dir = VL_TEST_IMAGES;

// An image whose every sample differs from its neighbours.
image ramp(int w, int h, int channels, sample_type type) {
    image img(w, h, channels, type);
    std::size_t i = 0;
    if (type == sample_type::u8)
        for (auto& s : img.samples<std::uint8_t>()) s = static_cast<std::uint8_t>(i++ * 37);
    else if (type == sample_type::u16)
        for (auto& s : img.samples<std::uint16_t>()) s = static_cast<std::uint16_t>(i++ * 4099);
    else
        for (auto& s : img.samples<float>()) s = static_cast<float>(i++) * 0.37f - 1.0f;
    return img;
}

template <class T> bool same_samples(const image& a, const image& b) {
    const auto x = a.samples<T>();
    const auto y = b.samples<T>();
    return a.width() == b.width() && a.height() == b.height() && a.channels() == b.channels() &&
           std::equal(x.begin(), x.end(), y.begin(), y.end());
}

}  // namespace

TEST_CASE("image: rows are top to bottom and samples are checked for their type", "[image]") {
    image img(3, 2, 3, sample_type::u8);
    CHECK(img.row_samples() == 9);
    CHECK(img.samples<std::uint8_t>().size() == 18);
    img.row<std::uint8_t>(1)[0] = 7;
    CHECK(img.samples<std::uint8_t>()[9] == 7);
    CHECK_THROWS_AS(img.samples<float>(), usage_error);
    CHECK_THROWS_AS(img.row<std::uint8_t>(2), usage_error);
    CHECK_THROWS_AS(image(70000, 1, 3, sample_type::u8), usage_error);
    CHECK_THROWS_AS(image(1, 1, 5, sample_type::u8), usage_error);
}

TEST_CASE("image files: PPM and PGM round trip at 8 and 16 bits", "[image][pnm]") {
    test::temp_dir dir;
    for (const int channels : {1, 3})
        for (const auto type : {sample_type::u8, sample_type::u16}) {
            const image img = ramp(17, 5, channels, type);
            const auto file = dir / (channels == 1 ? "a.pgm" : "a.ppm");
            write_image(file, img);
            const image back = read_image(file);
            CHECK(back.type() == type);
            CHECK((type == sample_type::u8 ? same_samples<std::uint8_t>(img, back) : same_samples<std::uint16_t>(img, back)));
        }
}

TEST_CASE("image files: PBM round trips black and white", "[image][pnm]") {
    test::temp_dir dir;
    image img(13, 3, 1, sample_type::u8);  // 13 is not a multiple of 8: rows are padded
    auto s = img.samples<std::uint8_t>();
    for (std::size_t i = 0; i < s.size(); ++i) s[i] = i % 3 ? 255 : 0;
    write_image(dir / "a.pbm", img);
    CHECK(test::read_bytes(dir / "a.pbm").size() == std::string("P4\n13 3\n").size() + 3 * 2);
    CHECK(same_samples<std::uint8_t>(img, read_image(dir / "a.pbm")));
}

TEST_CASE("image files: PNG round trips every channel count at 8 and 16 bits", "[image][png]") {
    test::temp_dir dir;
    for (int channels = 1; channels <= 4; ++channels)
        for (const auto type : {sample_type::u8, sample_type::u16}) {
            const image img = ramp(31, 7, channels, type);
            write_image(dir / "a.png", img);
            const image back = read_image(dir / "a.png");
            INFO(channels << " channels");
            CHECK((type == sample_type::u8 ? same_samples<std::uint8_t>(img, back) : same_samples<std::uint16_t>(img, back)));
        }
}

TEST_CASE("image files: written PNGs say they are sRGB", "[image][png]") {
    test::temp_dir dir;
    write_image(dir / "a.png", ramp(2, 2, 3, sample_type::u8));
    CHECK(test::read_bytes(dir / "a.png").find("sRGB") != std::string::npos);
}

TEST_CASE("image files: PFM round trips linear floats, bottom row first in the file", "[image][pfm]") {
    test::temp_dir dir;
    for (const int channels : {1, 3}) {
        const image img = ramp(9, 4, channels, sample_type::f32);
        write_image(dir / "a.pfm", img);
        CHECK(same_samples<float>(img, read_image(dir / "a.pfm")));
    }
    // The first float after the header is the bottom-left pixel.
    image img(1, 2, 1, sample_type::f32);
    img.row<float>(0)[0] = 1.0f;
    img.row<float>(1)[0] = 2.0f;
    write_image(dir / "b.pfm", img);
    const std::string bytes = test::read_bytes(dir / "b.pfm");
    float first;
    std::memcpy(&first, bytes.data() + std::string("Pf\n1 2\n-1.0\n").size(), 4);
    CHECK(first == 2.0f);
}

TEST_CASE("image files: a big-endian PFM (positive scale) reads the same", "[image][pfm]") {
    test::temp_dir dir;
    std::string bytes = "Pf\n2 1\n1.0\n";
    for (const unsigned char b : {0x3f, 0x80, 0x00, 0x00, 0xc0, 0x00, 0x00, 0x00}) bytes += static_cast<char>(b);  // 1, -2
    test::write_bytes(dir / "be.pfm", bytes);
    const image img = read_image(dir / "be.pfm");
    CHECK(img.samples<float>()[0] == 1.0f);
    CHECK(img.samples<float>()[1] == -2.0f);
}

TEST_CASE("image files: ASCII PNM with comments reads like binary", "[image][pnm]") {
    test::temp_dir dir;
    test::write_bytes(dir / "a.ppm", "P3\n# a comment\n2 # width\n1\n# maxval next\n15\n15 0 0   0 15 7\n");
    const image img = read_image(dir / "a.ppm");
    REQUIRE(img.channels() == 3);
    CHECK(img.samples<std::uint8_t>()[0] == 255);
    CHECK(img.samples<std::uint8_t>()[5] == 119);  // 7 of 15, rescaled to 255
    test::write_bytes(dir / "a.pgm", "P2 3 1 1000 0 500 1000");
    const image gray = read_image(dir / "a.pgm");
    CHECK(gray.type() == sample_type::u16);
    CHECK(gray.samples<std::uint16_t>()[1] == 32768);
    test::write_bytes(dir / "a.pbm", "P1\n4 2\n0101\n1 1 0 0\n");
    const image bw = read_image(dir / "a.pbm");
    CHECK(bw.samples<std::uint8_t>()[0] == 255);  // 0 is white
    CHECK(bw.samples<std::uint8_t>()[1] == 0);    // 1 is black
    CHECK(bw.samples<std::uint8_t>()[7] == 255);
}

TEST_CASE("image files: binary PNM with an odd maxval is rescaled", "[image][pnm]") {
    test::temp_dir dir;
    test::write_bytes(dir / "a.pgm", std::string("P5 2 1 3\n") + '\x00' + '\x03');
    const image img = read_image(dir / "a.pgm");
    CHECK(img.samples<std::uint8_t>()[1] == 255);
    test::write_bytes(dir / "b.pgm", std::string("P5 1 1 1000\n") + '\x01' + '\xf4');  // 500 of 1000
    CHECK(read_image(dir / "b.pgm").samples<std::uint16_t>()[0] == 32768);
}

TEST_CASE("image files: PNG palettes, transparency and small bit depths are expanded", "[image][png]") {
    const image pal = read_image(data_dir / "palette_trns_4x2.png");
    REQUIRE(pal.channels() == 4);
    const auto p = pal.row<std::uint8_t>(0);
    CHECK((p[0] == 255 && p[1] == 0 && p[2] == 0 && p[3] == 255));  // red, opaque
    CHECK(p[15] == 0);                                               // index 3 is transparent
    const image bits = read_image(data_dir / "gray1_10x1.png");
    REQUIRE(bits.channels() == 1);
    CHECK(bits.samples<std::uint8_t>()[0] == 255);
    CHECK(bits.samples<std::uint8_t>()[1] == 0);
    const image ga = read_image(data_dir / "gray_alpha_2x1.png");
    CHECK(ga.channels() == 2);
    CHECK(ga.samples<std::uint8_t>()[3] == 128);
    const image rgb16 = read_image(data_dir / "rgb16_2x1.png");
    REQUIRE(rgb16.type() == sample_type::u16);
    CHECK(rgb16.samples<std::uint16_t>()[0] == 65535);
    CHECK(rgb16.samples<std::uint16_t>()[2] == 256);  // byte order handled
    const image g16 = read_image(data_dir / "gray16_3x1.png");
    CHECK(g16.samples<std::uint16_t>()[1] == 32768);
    const image rgba = read_image(data_dir / "rgba_1x2.png");
    CHECK(rgba.row<std::uint8_t>(1)[3] == 8);
}

TEST_CASE("image files: conversions go through the sRGB transfer function and luminance", "[image]") {
    image lin(2, 1, 3, sample_type::f32);
    const auto s = lin.samples<float>();
    s[0] = 0.18f; s[1] = 0.18f; s[2] = 0.18f; s[3] = 1.0f; s[4] = 0.0f; s[5] = 0.0f;
    const image u8 = convert_samples(lin, sample_type::u8);
    CHECK(u8.samples<std::uint8_t>()[0] == linear_to_srgb8(0.18));
    const image gray = convert_channels(lin, 1);
    CHECK(gray.samples<float>()[1] == Approx(0.2126));
    const image back = convert_samples(convert_samples(u8, sample_type::u16), sample_type::u8);
    CHECK(same_samples<std::uint8_t>(u8, back));
}

TEST_CASE("image files: ImageMagick reads our PNG, PPM, PGM and PBM files at the right size", "[image][imagemagick]") {
    if (!test::have_imagemagick()) {
        WARN("ImageMagick's identify is not installed: skipped");
        return;
    }
    test::temp_dir dir;
    write_image(dir / "a.png", ramp(875, 700, 3, sample_type::u8));
    write_image(dir / "b.png", ramp(33, 21, 4, sample_type::u16));
    write_image(dir / "a.ppm", ramp(875, 700, 3, sample_type::u8));
    write_image(dir / "a.pgm", ramp(13, 2, 1, sample_type::u16));
    write_image(dir / "a.pbm", ramp(13, 2, 1, sample_type::u8));
    CHECK(test::identify_size(dir / "a.png") == "875 700");
    CHECK(test::identify_size(dir / "b.png") == "33 21");
    CHECK(test::identify_size(dir / "a.ppm") == "875 700");
    CHECK(test::identify_size(dir / "a.pgm") == "13 2");
    CHECK(test::identify_size(dir / "a.pbm") == "13 2");
}

TEST_CASE("image files: ImageMagick's pixels match ours", "[image][imagemagick]") {
    if (!test::have_imagemagick()) {
        WARN("ImageMagick's convert is not installed: skipped");
        return;
    }
    test::temp_dir dir;
    const image img = ramp(40, 30, 3, sample_type::u8);
    write_image(dir / "a.png", img);
    const std::string command = "convert '" + (dir / "a.png").string() + "' '" + (dir / "b.ppm").string() + "'";
    REQUIRE(std::system(command.c_str()) == 0);
    CHECK(same_samples<std::uint8_t>(img, read_image(dir / "b.ppm")));
}
