// Renders each public scene of stage 02 with this build's pieces and compares it with the
// reference image stored beside it (the instructor's reference pieces rendered it). When one fails, render the scene with rt and look at it next to the
// .png. (The grader renders these scenes too, as graded scenes of their own.)
#include "vl/catch.hh"

#include <filesystem>

#include "scene_renders.hh"

TEST_CASE("scene: each public scene renders like its reference image", "[02][scene][render]") {
    // The scenes and their PNGs are in ../scenes.
    const std::filesystem::path scenes = std::filesystem::path(__FILE__).parent_path().parent_path() / "scenes";
    vl::testing::check_each_scene_renders_like_its_png(scenes, 4);
}
