// Tests of the scene reader: tokens, typed reads, includes, and the error for every kind
// of malformed input (each must name FILE:LINE:COL, say what was expected, never crash).
#include "vl/catch.hh"

#include "support/probes.hh"
#include "support/temp_dir.hh"
#include "vl/registry.hh"
#include "vl/scene.hh"

using namespace vl;

namespace {

registry test_types() { return test::probe_types(); }

/// The message parse_scene throws for `text`, or "" when it does not throw.
std::string error_for(const std::string& text) {
    const registry types = test_types();
    try {
        parse_scene(text, "bad.ray_trace", types);
    } catch (const file_error& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST_CASE("scene_reader: tokens carry their kind, text and line:column", "[scene][reader]") {
    const registry types = test_types();
    scene_reader in(types);
    in.open_text("size 10 20 # a comment { ignored\n  \"a string\" { } ( ) , -1.5e3 word_2", "t");
    token t = in.next();
    CHECK(t.type == token::kind::word);
    CHECK(t.text == "size");
    CHECK(t.where.str() == "t:1:1");
    CHECK(in.next().number == 10);
    t = in.next();
    CHECK(t.number == 20);
    CHECK(t.where.column == 9);
    t = in.next();
    CHECK(t.type == token::kind::string);
    CHECK(t.text == "a string");
    CHECK(t.where.str() == "t:2:3");
    for (const char* p : {"{", "}", "(", ")", ","}) {
        t = in.next();
        CHECK(t.type == token::kind::punct);
        CHECK(t.text == p);
    }
    CHECK(in.next().number == -1500);
    CHECK(in.next().text == "word_2");
    CHECK(in.at_end());
}

TEST_CASE("scene_reader: tuples take an optional label, 3 or 4 numbers, bare or bracketed", "[scene][reader]") {
    const registry types = test_types();
    scene_reader in(types);
    in.open_text("1 2 3   at 1 2 3 2   point (1, 2, 3, 4)  (4, 5, 6)  red 0.5 0.25 0 1", "t");
    CHECK(in.read_point("a") == point(1, 2, 3));
    const point p = in.read_point("b");
    CHECK(p.w == 2);
    CHECK(p == point(0.5, 1, 1.5));  // homogenized equality
    const vector v = in.read_vector("c");
    CHECK(v == vector(1, 2, 3, 4));
    CHECK(in.read_vector("d") == vector(4, 5, 6, 0));
    CHECK(in.read_color("e") == color(0.5, 0.25, 0, 1));
    CHECK(in.at_end());
}

TEST_CASE("scene_reader: what << writes for a tuple, the reader reads back", "[scene][reader]") {
    const registry types = test_types();
    scene_reader in(types);
    std::ostringstream out;
    out << point(0.1, -2, 3e-7, 1) << ' ' << color(0.2, 0.4, 0.6, 0);
    in.open_text(out.str(), "t");
    CHECK(in.read_point("p") == point(0.1, -2, 3e-7, 1));
    CHECK(in.read_color("c") == color(0.2, 0.4, 0.6, 0));
}

TEST_CASE("scene_reader: include reads another file relative to the including one", "[scene][reader]") {
    test::temp_dir dir;
    dir.write("parts/probe.ray_trace", "PROBE { t 2 }\n");
    dir.write("parts/more.ray_trace", "include \"probe.ray_trace\"\nPROBE { t 3 }\n");
    const auto main_file = dir.write("main.ray_trace", "size 8 8\ninclude \"parts/more.ray_trace\"\nPROBE { t 1 }\n");
    const registry types = test_types();
    const scene s = read_scene(main_file, types);
    CHECK(s.width == 8);
    REQUIRE(s.root->num_children() == 3);
    CHECK(dynamic_cast<const test::probe&>(*s.root->children()[0]).t() == 2);
    CHECK(dynamic_cast<const test::probe&>(*s.root->children()[2]).t() == 1);
}

TEST_CASE("scene_reader: an error inside an included file names that file", "[scene][reader][errors]") {
    test::temp_dir dir;
    dir.write("part.ray_trace", "\n  PROBE { t -1 }\n");
    const auto main_file = dir.write("main.ray_trace", "include \"part.ray_trace\"\n");
    const registry types = test_types();
    CHECK_THROWS_WITH(read_scene(main_file, types), Catch::Contains("part.ray_trace:2:13: t of PROBE must be 0 or more"));
}

TEST_CASE("scene_reader: an include cycle is an error at the include, not a hang", "[scene][reader][errors]") {
    test::temp_dir dir;
    dir.write("a.ray_trace", "PROBE { t 1 }\ninclude \"b.ray_trace\"\n");
    dir.write("b.ray_trace", "include \"a.ray_trace\"\n");
    const registry types = test_types();
    CHECK_THROWS_WITH(read_scene(dir.path() / "a.ray_trace", types),
                      Catch::Contains("b.ray_trace:1:9: cannot include \"") && Catch::Contains("include cycle"));
}

TEST_CASE("scene_reader: a file that includes itself is a cycle", "[scene][reader][errors]") {
    test::temp_dir dir;
    const auto self = dir.write("self.ray_trace", "include \"self.ray_trace\"\n");
    const registry types = test_types();
    CHECK_THROWS_WITH(read_scene(self, types), Catch::Contains("self.ray_trace:1:9") && Catch::Contains("include cycle"));
}

TEST_CASE("scene_reader: a missing include file is named with the place that asked for it", "[scene][reader][errors]") {
    test::temp_dir dir;
    const auto f = dir.write("main.ray_trace", "PROBE { t 1 }\ninclude \"nowhere.ray_trace\"\n");
    const registry types = test_types();
    CHECK_THROWS_WITH(read_scene(f, types), Catch::Contains("main.ray_trace:2:9: cannot include") &&
                                                Catch::Contains("no such file"));
}

TEST_CASE("scene_reader: a missing scene file says so", "[scene][reader][errors]") {
    const registry types = test_types();
    CHECK_THROWS_WITH(read_scene("/nonexistent/dir/scene.ray_trace", types),
                      "/nonexistent/dir/scene.ray_trace: no such file");
}

TEST_CASE("scene_reader: a directory is not a scene", "[scene][reader][errors]") {
    test::temp_dir dir;
    const registry types = test_types();
    CHECK_THROWS_WITH(read_scene(dir.path(), types), Catch::Contains("is a directory"));
}

TEST_CASE("scene_reader: binary garbage is refused with a message, not parsed", "[scene][reader][errors]") {
    test::temp_dir dir;
    std::string garbage = "PROBE";
    for (int k = 0; k < 256; ++k) garbage += static_cast<char>(k * 37 % 256);
    const auto f = dir.write("garbage.ray_trace", garbage);
    const registry types = test_types();
    CHECK_THROWS_WITH(read_scene(f, types), Catch::Contains("garbage.ray_trace: this looks like a binary file"));
}

// Each row: a malformed scene and the start of the message it must give.
TEST_CASE("scene_reader: every malformed scene gets FILE:LINE:COL and what was expected", "[scene][reader][errors]") {
    const std::pair<const char*, const char*> cases[] = {
        // empty or truncated
        {"", "bad.ray_trace:1:1: the scene is empty"},
        {"# only a comment\n", "bad.ray_trace:2:1: the scene is empty"},
        {"PROBE { t 1", "bad.ray_trace:1:12: expected '}' to close PROBE, found the end of the file"},
        {"PROBE {", "bad.ray_trace:1:8: expected '}' to close PROBE"},
        {"PROBE", "bad.ray_trace:1:6: expected '{' after PROBE, found the end of the file"},
        {"PROBE { t }", "bad.ray_trace:1:11: expected a number for t of PROBE, found '}'"},
        {"camera { eye 0 0 }", "bad.ray_trace:1:18: expected a number for z of eye of camera, found '}'"},
        {"LIST { PROBE { t 1 }", "bad.ray_trace:1:21: expected '}' to close LIST, found the end of the file"},
        // unknown or malformed names
        {"SPHEER { }", "bad.ray_trace:1:1: unknown object type 'SPHEER'; the types this program knows are: BOUNDED, LIST, NEARONLY, PROBE"},
        {"ABCDEFGHIJK { }", "bad.ray_trace:1:1: 'ABCDEFGHIJK' is not an object type: type names are 1 to 10 upper-case letters"},
        {"Probe { }", "bad.ray_trace:1:1: unknown setting 'Probe'"},
        {"PROBE { radius 1 }", "bad.ray_trace:1:9: PROBE has no property 'radius'; its properties are: t, color, kdr"},
        {"PROBE { t 1 t 2 }", "bad.ray_trace:1:13: PROBE t is given twice (first at bad.ray_trace:1:9)"},
        {"size 8 8\nsize 9 9\nPROBE { t 1 }", "bad.ray_trace:2:1: size is given twice (first at bad.ray_trace:1:1)"},
        {"tracer phong\nPROBE { }", "bad.ray_trace:1:8: tracer 'phong' is not registered in this build; choose one of: flat, normals, sky"},
        {"tracer whitted\nPROBE { }", "bad.ray_trace:1:8: tracer 'whitted' is not registered in this build; choose one of: flat, normals, sky"},
        {"sampler grid\nPROBE { }", "bad.ray_trace:1:9: sampler 'grid' is not registered in this build; choose one of: center, jittered"},
        {"sampler 4\nPROBE { }", "bad.ray_trace:1:9: expected sampler name (center, jittered), found the number 4"},
        // bad numbers
        {"PROBE { t nan }", "bad.ray_trace:1:11: expected a number for t of PROBE, found 'nan'"},
        {"PROBE { t inf }", "bad.ray_trace:1:11: expected a number for t of PROBE, found 'inf'"},
        {"PROBE { t 1e999 }", "bad.ray_trace:1:11: the number 1e999 is out of range"},
        {"PROBE { t 1.2.3 }", "bad.ray_trace:1:11: '1.2.3' is not a number"},
        {"PROBE { t 12abc }", "bad.ray_trace:1:11: '12abc' is not a number"},
        {"PROBE { t -1 }", "bad.ray_trace:1:11: t of PROBE must be 0 or more, found -1"},
        {"PROBE { ior 0 }", "bad.ray_trace:1:13: ior (index of refraction) of PROBE must be greater than 0, found 0"},
        {"size 0 10\nPROBE { }", "bad.ray_trace:1:6: image width must be from 1 to 16384, found 0"},
        {"size 100000 10\nPROBE { }", "bad.ray_trace:1:6: image width must be from 1 to 16384, found 100000"},
        {"size 10.5 10\nPROBE { }", "bad.ray_trace:1:6: image width must be a whole number, found 10.5"},
        {"samples 1e300\nPROBE { }", "bad.ray_trace:1:9: samples per pixel must be from 1 to 4096, found 1e300"},
        {"camera { fov 180 }\nPROBE { }", "bad.ray_trace:1:14: fov of camera must be less than 180 degrees"},
        {"camera { eye 1 2 3 look_at 1 2 3 }\nPROBE { }", "bad.ray_trace:1:8: camera eye and look_at are the same point"},
        {"camera { up 0 0 1 }\nPROBE { }", "bad.ray_trace:1:8: camera up is parallel to the view direction"},
        {"camera { eye look_at 0 0 0 }\nPROBE { }", "bad.ray_trace:1:14: expected a number for x of eye of camera, found 'look_at'"},
        // bad tokens, strings and includes
        {"PROBE { t 1 } @", "bad.ray_trace:1:15: unexpected character '@'"},
        {"PROBE { t 1 }\n\x01", "bad.ray_trace:2:1: unexpected character byte 0x1"},
        {"include \"unterminated\nPROBE { }", "bad.ray_trace:1:9: unterminated string"},
        {"include", "bad.ray_trace:1:8: expected a file name in double quotes after include, found the end of the file"},
        {"include PROBE", "bad.ray_trace:1:9: expected a file name in double quotes after include, found 'PROBE'"},
        {"PROBE { t (1) }", "bad.ray_trace:1:11: expected a number for t of PROBE, found '('"},
        {"light { position (1, 2) }\nPROBE { }", "bad.ray_trace:1:23: expected ',' between the components of position of light, found ')'"},
        {"} PROBE { }", "bad.ray_trace:1:1: expected a setting (camera, light, size, ...) or an object type, found '}'"},
    };
    for (const auto& [text, expected] : cases) {
        INFO("scene text: " << text);
        const std::string message = error_for(text);
        CHECK_THAT(message, Catch::StartsWith(expected));
    }
}

TEST_CASE("scene_reader: a deeply nested scene is read, and deep includes stop at a limit", "[scene][reader][errors]") {
    std::string nested;
    for (int k = 0; k < 200; ++k) nested += "LIST { ";
    nested += "PROBE { t 1 }";
    for (int k = 0; k < 200; ++k) nested += " }";
    const registry types = test_types();
    CHECK_NOTHROW(parse_scene(nested, "deep.ray_trace", types));

    test::temp_dir dir;
    for (int k = 0; k < 20; ++k)
        dir.write("f" + std::to_string(k) + ".ray_trace", "include \"f" + std::to_string(k + 1) + ".ray_trace\"\n");
    dir.write("f20.ray_trace", "PROBE { t 1 }\n");
    CHECK_THROWS_WITH(read_scene(dir.path() / "f0.ray_trace", types), Catch::Contains("nested deeper than 16 files"));
}

TEST_CASE("scene_reader: a child its composite refuses is reported at the child's place", "[scene][reader][errors]") {
    const std::string message = error_for("NEARONLY {\n  PROBE { t 1 }\n  PROBE { t 20 }\n}\n");
    INFO(message);
    CHECK(message == "bad.ray_trace:3:3: NEARONLY cannot hold a PROBE at t 10 or more");
    CHECK(error_for("NEARONLY { PROBE { t 1 } PROBE { t 2 } }\n").empty());
}
