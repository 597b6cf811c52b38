// The virtual frame buffer: coordinates, errors, storages chosen at run time, load and save.
#include "vl/vfb.hh"
#include "vl/image_io.hh"

#include "image_test_support.hh"

#include "vl/catch.hh"

using namespace vl;

namespace {

// A recognisable pattern: every pixel's colour encodes its coordinates.
vfb_pixel pattern(vfb_int x, vfb_int y) { return {x / 8.0, y / 8.0, (x + y) % 2 ? 1.0 : 0.0}; }

void fill(vfb& v) {
    for (vfb_int y = 0; y <= v.max_y(); ++y)
        for (vfb_int x = 0; x <= v.max_x(); ++x) v.put_pixel(x, y, pattern(x, y));
}

}  // namespace

TEST_CASE("vfb: a buffer from (0, 0) to (max_x, max_y) includes both corners", "[vfb]") {
    vfb v(4, 2);
    CHECK(v.width() == 5);
    CHECK(v.height() == 3);
    CHECK(v.storage_name() == storage_class::name);
    v.put_pixel(4, 2, vfb_pixel(1));
    CHECK(v.get_pixel(4, 2) == vfb_pixel(1));
    CHECK(v.get_pixel(0, 0) == vfb_pixel(0));
}

TEST_CASE("vfb: a pixel outside the buffer is an error that names it and the bounds", "[vfb][errors]") {
    vfb v(9, 4);
    CHECK_THROWS_WITH(v.put_pixel(10, 0, vfb_pixel(1)), "vfb: pixel (10, 0) is outside (0, 0)..(9, 4)");
    CHECK_THROWS_AS(v.get_pixel(0, -1), vfb_range_error);
    CHECK_THROWS_AS(v.get_pixel(-1, 0), usage_error);
    CHECK_THROWS_AS(v.put_pixel(vfb_pixel(3.5, 5.0, 0.0, 1.0, 1.0, 1.0)), vfb_range_error);
    CHECK_THROWS_AS(v.put_pixel(vfb_pixel(1e300, 0.0, 0.0, 1.0, 1.0, 1.0)), vfb_range_error);
    CHECK_THROWS_AS(v.put_pixel(vfb_pixel(std::nan(""), 0.0, 0.0, 1.0, 1.0, 1.0)), vfb_range_error);
    CHECK_THROWS_AS(v.row<rgb8_storage>(5), vfb_range_error);
    CHECK_THROWS_AS(vfb(-1, 3), usage_error);
    CHECK_THROWS_AS(vfb(70000, 1), usage_error);
    CHECK_THROWS_WITH(vfb(2, 2, "hdr"), Catch::Contains("unknown pixel storage 'hdr'") && Catch::Contains("aa4"));
}

TEST_CASE("vfb: the storage is chosen by name at run time or by type in one line", "[vfb][storage]") {
    for (const auto name : vfb::storage_names()) {
        vfb v(3, 3, name);
        CHECK(v.storage_name() == name);
        v.put_pixel(1, 2, vfb_pixel(1));  // the same client code for every storage
        CHECK(v.get_pixel(1, 2).r() == Approx(1.0));
        CHECK(v.get_pixel(2, 1).r() == Approx(0.0));
    }
    auto z = vfb::with_storage<zbuffer_storage>(3, 3);
    CHECK(z.storage_name() == "zrgb");
    CHECK(z.bytes_per_pixel() == 16);
    CHECK(z.holds<zbuffer_storage>());
    CHECK_THROWS_AS(z.cells<rgb8_storage>(), usage_error);
}

TEST_CASE("vfb: a pixel made with coordinates goes where they point", "[vfb]") {
    auto v = vfb::with_storage<antialiased_storage<2>>(3, 3);
    v.put_pixel(vfb_pixel(point(2.25, 1.25, 0.0), WHITE));
    v.put_pixel(vfb_pixel(point(2.75, 1.75, 0.0), WHITE));
    CHECK(v.get_pixel(2, 1).r() == Approx(0.5));
    CHECK(v.get_pixel(1, 2).r() == 0.0);
    CHECK_THROWS_AS(v.put_pixel(vfb_pixel(1.0, 1.0, 1.0)), usage_error);  // no coordinates
}

TEST_CASE("vfb: the z rule holds through put_pixel", "[vfb][zbuffer]") {
    vfb v(1, 1, "zrgb");
    v.put_pixel(0, 0, vfb_pixel(-2.0, 1.0, 0.0, 0.0));
    v.put_pixel(0, 0, vfb_pixel(-3.0, 0.0, 1.0, 0.0));
    CHECK(v.get_pixel(0, 0) == vfb_pixel(-2.0, 1.0, 0.0, 0.0));
    v.clear();
    CHECK(v.get_pixel(0, 0).az() == vfb_pixel::no_az);
    v.put_pixel(0, 0, vfb_pixel(-3.0, 0.0, 1.0, 0.0));
    CHECK(v.get_pixel(0, 0).g() == 1.0);
}

TEST_CASE("vfb: the typed fast path sees the cells row by row from the bottom", "[vfb]") {
    vfb v(2, 1);
    v.put_pixel(2, 0, vfb_pixel(1.0, 0.0, 0.0));
    const auto row = v.row<rgb8_storage>(0);
    REQUIRE(row.size() == 3);
    CHECK(row[2].r == 255);
    row[0].g = 255;  // writing a cell is writing the pixel
    CHECK(v.get_pixel(0, 0).g() == 1.0);
}

TEST_CASE("vfb: pixel (0, 0) is the lower left, the last row of a saved file", "[vfb][files]") {
    test::temp_dir dir;
    vfb v(2, 1);
    v.put_pixel(0, 0, vfb_pixel(1.0, 0.0, 0.0));
    v.save(dir / "corner.ppm");
    const image img = read_image(dir / "corner.ppm");
    REQUIRE(img.height() == 2);
    CHECK(img.row<std::uint8_t>(1)[0] == 255);  // bottom row, first pixel: red
    CHECK(img.row<std::uint8_t>(0)[0] == 0);
    const std::string bytes = test::read_bytes(dir / "corner.ppm");
    CHECK(bytes.substr(0, 11) == "P6\n3 2\n255\n");
    CHECK(static_cast<unsigned char>(bytes[11 + 9]) == 255);  // first byte of the last row
}

TEST_CASE("vfb: load places the image's lower left at (x1, y1) and clips what falls outside", "[vfb][files]") {
    test::temp_dir dir;
    vfb src(3, 2);  // 4 x 3
    fill(src);
    src.save(dir / "src.png");

    vfb dst(5, 5);
    dst.load(dir / "src.png", 4, -1);  // only columns 0..1 and rows 1..2 of src fit
    for (vfb_int y = 0; y <= 5; ++y)
        for (vfb_int x = 0; x <= 5; ++x) {
            const bool inside = x >= 4 && y <= 1;
            INFO("pixel " << x << ", " << y);
            if (inside)
                CHECK(dst.get_pixel(x, y) == src.get_pixel(x - 4, y + 1));
            else
                CHECK(dst.get_pixel(x, y) == vfb_pixel(0));
        }
    dst.load(dir / "src.png", 100, 100);  // entirely outside: nothing changes, no error
    dst.load(dir / "src.png", -4, -3);
    CHECK(dst.get_pixel(0, 0) == vfb_pixel(0));
}

TEST_CASE("vfb: loading replaces z-buffered pixels instead of testing their depth", "[vfb][files][zbuffer]") {
    test::temp_dir dir;
    vfb white(0, 0);
    white.put_pixel(0, 0, vfb_pixel(1));
    white.save(dir / "white.pfm");
    vfb z(0, 0, "zrgb");
    z.put_pixel(0, 0, vfb_pixel(100.0, 0.0, 0.0, 0.0));
    z.load(dir / "white.pfm");
    CHECK(z.get_pixel(0, 0).r() == 1.0);
}

TEST_CASE("vfb: every storage survives a save and load in every format", "[vfb][files][storage]") {
    test::temp_dir dir;
    for (const auto name : vfb::storage_names()) {
        vfb v(6, 4, name);
        fill(v);
        for (const char* ext : {".png", ".ppm", ".pnm", ".pfm"}) {
            const auto file = dir / (std::string(name) + ext);
            v.save(file);
            vfb back(6, 4, name);
            back.load(file);
            for (vfb_int y = 0; y <= 4; ++y)
                for (vfb_int x = 0; x <= 6; ++x) {
                    INFO(name << ext << " at " << x << ", " << y);
                    const vfb_pixel a = v.get_pixel(x, y), b = back.get_pixel(x, y);
                    // 8-bit files carry what 8-bit storages hold exactly, the others to 8 bits.
                    const double tol = std::string(ext) == ".pfm" ? 1e-6 : 0.01;
                    CHECK(b.r() == Approx(a.r()).margin(tol));
                    CHECK(b.g() == Approx(a.g()).margin(tol));
                    CHECK(b.b() == Approx(a.b()).margin(tol));
                }
        }
    }
}

TEST_CASE("vfb: gray storages save gray files, the alpha storage an RGBA PNG", "[vfb][files]") {
    test::temp_dir dir;
    vfb g(3, 3, "gray8");
    g.save(dir / "g.png");
    CHECK(read_image(dir / "g.png").channels() == 1);
    vfb a(3, 3, "rgba");
    a.put_pixel(1, 1, vfb_pixel(0.5, 1.0, 1.0, 1.0));
    a.save(dir / "a.png");
    const image img = read_image(dir / "a.png");
    REQUIRE(img.channels() == 4);
    CHECK(img.row<std::uint8_t>(2)[1 * 4 + 3] == 128);  // alpha is linear, not sRGB-encoded
    vfb back(3, 3, "rgba");
    back.load(dir / "a.png");
    CHECK(back.get_pixel(1, 1).az() == Approx(0.5).margin(0.003));
    vfb bw(8, 1, "bw");
    bw.put_pixel(3, 1, vfb_pixel(1));
    bw.save(dir / "bw.pbm");
    vfb bw_back(8, 1, "bw");
    bw_back.load(dir / "bw.pbm");
    CHECK(bw_back.get_pixel(3, 1) == vfb_pixel(1));
    CHECK(bw_back.get_pixel(4, 1) == vfb_pixel(0));
}

TEST_CASE("vfb: a file in an unknown format or a missing file names the file", "[vfb][files][errors]") {
    test::temp_dir dir;
    vfb v(1, 1);
    CHECK_THROWS_WITH(v.save(dir / "out.jpg"), Catch::Contains("out.jpg: unknown image extension '.jpg'"));
    CHECK_THROWS_WITH(v.load(dir / "missing.png"), Catch::Contains("missing.png: cannot open"));
    CHECK_THROWS_WITH(v.save(dir / "no_such_dir" / "x.png"), Catch::Contains("x.png: cannot create"));
}
