#include "vl/scene.hh"

#include <algorithm>
#include <map>

#include "vl/registry.hh"
#include "vl/scene_reader.hh"

namespace vl {

namespace {

std::string one_of(const std::vector<std::string>& names) {
    std::string out;
    for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
    return out.empty() ? "none is registered in this build" : out;
}

/// A sampler's or tracer's name, which must be one of `names`: what the program's registry
/// binds. The reader knows no other list; a name another build binds (a stage this one
/// does not have) is as unknown here as a typing mistake.
std::string read_name(scene_reader& in, std::string_view what, const std::vector<std::string>& names) {
    const token t = in.peek();
    const std::string name = in.read_word(std::string(what) + " name (" + one_of(names) + ")");
    if (std::find(names.begin(), names.end(), name) == names.end())
        in.fail(t.where, std::string(what) + " '" + name + "' is not registered in this build; " +
                             (names.empty() ? "it registers none" : "choose one of: " + one_of(names)));
    return name;
}

/// Reads every statement; returns how many there were.
int read_statements(scene_reader& in, scene& s, const registry& types) {
    int statements = 0;
    std::map<std::string, source_location> seen;  // settings given once only
    auto once = [&](const token& key) {
        const auto [it, fresh] = seen.emplace(key.text, key.where);
        if (!fresh) in.fail(key.where, key.text + " is given twice (first at " + it->second.str() + ")");
    };
    for (; !in.at_end(); ++statements) {
        const token key = in.peek();
        if (key.type != token::kind::word) in.fail_expected("a setting (camera, light, size, ...) or an object type");
        // Upper-case words are object types; read_object() explains a malformed one.
        if (std::all_of(key.text.begin(), key.text.end(), [](char c) { return c >= 'A' && c <= 'Z'; })) {
            s.root->insert(in.read_object());
            continue;
        }
        in.next();
        if (key.text == "light") {
            color c = WHITE;
            point p{0, 10, 0};
            in.read_block("light", {{"color", [&] { c = in.read_color("color of light"); }},
                                    {"position", [&] { p = in.read_point("position of light"); }}});
            s.lights.emplace_back(c, p);
            continue;
        }
        once(key);
        if (key.text == "camera") {
            camera_settings& cam = s.camera;
            const token open = in.peek();
            in.read_block("camera", {
                {"eye", [&] { cam.eye = in.read_point("eye of camera"); }},
                {"look_at", [&] { cam.look_at = in.read_point("look_at of camera"); }},
                {"up", [&] { cam.up = in.read_vector("up of camera"); }},
                {"fov", [&] {
                     const token t = in.peek();
                     cam.fov_degrees = in.read_positive("fov of camera (degrees)");
                     if (cam.fov_degrees >= 180) in.fail(t.where, "fov of camera must be less than 180 degrees, found " + t.text);
                 }},
            });
            if (cam.eye == cam.look_at)
                in.fail(open.where, "camera eye and look_at are the same point: the camera looks nowhere");
            if ((cam.look_at - cam.eye) % cam.up == vector(0, 0, 0, 0))
                in.fail(open.where, "camera up is parallel to the view direction (or zero), so the image has no sideways "
                        "direction: give an up that is not parallel to look_at - eye, such as 0 1 0 unless the "
                        "camera looks straight up or down");
        } else if (key.text == "size") {
            s.width = in.read_int("image width", 1, max_image_side);
            s.height = in.read_int("image height", 1, max_image_side);
        } else if (key.text == "samples") {
            s.samples_per_pixel = in.read_int("samples per pixel", 1, 4096);
        } else if (key.text == "sampler") {
            s.sampler = read_name(in, "sampler", types.sampler_names());
        } else if (key.text == "depth") {
            s.max_depth = in.read_int("recursion depth", 0, 64);
        } else if (key.text == "tracer") {
            s.tracer = read_name(in, "tracer", types.tracer_names());
        } else if (key.text == "ambient") {
            s.ambient = in.read_color("ambient");
        } else if (key.text == "background") {
            s.background = in.read_color("background");
        } else {
            in.fail(key.where, "unknown setting '" + key.text +
                                   "'; a scene holds camera, light, size, samples, sampler, depth, tracer, ambient, "
                                   "background, include \"FILE\", and objects whose type names are upper case (SPHERE)");
        }
    }
    return statements;
}

// A scene without objects is fine (the sky tracer shows what the camera sees); a file
// without any statement is almost certainly the wrong file.
scene finish(scene_reader& in, scene s, const registry& types) {
    if (read_statements(in, s, types) == 0) {
        const token end = in.peek();
        in.fail(end.where, "the scene is empty: add settings and objects, such as SPHERE { center 0 0 0 radius 1 }");
    }
    return s;
}

}  // namespace

scene read_scene(const std::filesystem::path& file, const registry& types) {
    scene_reader in(types);
    in.open(file);
    scene s;
    s.source = file.string();
    return finish(in, std::move(s), types);
}

scene parse_scene(std::string text, const std::string& name, const registry& types) {
    scene_reader in(types);
    in.open_text(std::move(text), name);
    scene s;
    s.source = name;
    return finish(in, std::move(s), types);
}

}  // namespace vl
