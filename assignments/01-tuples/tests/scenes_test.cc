// Renders each public scene of stage 01 with this build's pieces and compares it with the
// reference image stored beside it (the instructor's reference pieces rendered it). You need not read this file to do the assignment: when one of these
// fails, render the scene with rt and look at it next to the .png.
#include "vl/catch.hh"

#include <filesystem>
#include <string>

#include "all_pieces.hh"
#include "image_compare.hh"

namespace fs = std::filesystem;

namespace {

fs::path scenes_dir() {
    const fs::path here = __FILE__;  // CMake compiles with absolute paths
    if (here.is_absolute()) return here.parent_path().parent_path() / "scenes";
    return "assignments/01-tuples/scenes";  // ctest runs in the project's top folder
}

void check_scene(const std::string& name) {
    const fs::path scene = scenes_dir() / (name + ".ray_trace"), reference = scenes_dir() / (name + ".png");
    INFO("scene " << scene.string() << " against " << reference.string());
    const vl::image_difference d = vl::compare_render(scene, reference, vl::all_pieces());
    INFO(d.summary);
    INFO("to see the difference, render the scene with rt (the handout's section \"Render and look\") and look at "
         "your image beside " << reference.filename().string() << ", e.g. in the vfb viewer");
    CHECK(renders_match(d));
}

}  // namespace

TEST_CASE("scenes: sky.ray_trace (a sky gradient and no objects) matches its reference image", "[01][scenes]") {
    check_scene("sky");
}

TEST_CASE("scenes: sky_rolled.ray_trace (a rolled wide-angle camera) matches its reference image", "[01][scenes]") {
    check_scene("sky_rolled");
}

TEST_CASE("scenes: spheres_on_side.ray_trace (up is +x and it needs stage 02's SPHERE) matches its reference image",
          "[01][scenes]") {
    check_scene("spheres_on_side");
}
