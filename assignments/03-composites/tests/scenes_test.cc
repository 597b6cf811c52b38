// Renders each public scene of stage 03 with this build's pieces and compares it with the
// reference image stored beside it (the instructor's reference pieces rendered it). When one fails, render the scene with rt and look at it next to the
// .png. (The grader renders these scenes too, as graded scenes of their own.)
#include "vl/catch.hh"

#include <filesystem>

#include "all_pieces.hh"
#include "image_compare.hh"

using namespace vl;

TEST_CASE("scene: each public scene of stage 03 renders like its reference image", "[03][scene][render]") {
    // The scenes and their PNGs are in ../scenes.
    const std::filesystem::path scenes = std::filesystem::path(__FILE__).parent_path().parent_path() / "scenes";
    int rendered = 0;
    for (const auto& entry : std::filesystem::directory_iterator(scenes)) {
        if (entry.path().extension() != ".ray_trace") continue;
        const std::filesystem::path png = std::filesystem::path(entry.path()).replace_extension(".png");
        DYNAMIC_SECTION(entry.path().filename().string()) {
            REQUIRE(std::filesystem::exists(png));
            const image_difference d = compare_render(entry.path(), png, all_pieces());
            INFO(entry.path().filename().string() << ": " << d.summary);
            INFO("to see the difference, render the scene with rt (the handout's section \"Render and look\") and look at "
                 "your image beside " << png.filename().string() << ", e.g. in the vfb viewer");
            CHECK(renders_match(d));
        }
        ++rendered;
    }
    CHECK(rendered >= 4);
}
