#pragma once
/// \file
/// \brief How each stage's scenes_test.cc checks its public scenes: every scene renders
/// like the reference image stored beside it. You need not read this file: when a scene
/// fails, render it with rt and look at it next to its .png.

#include "vl/catch.hh"

#include <filesystem>

#include "all_pieces.hh"
#include "image_compare.hh"

namespace vl::testing {

/// Renders each scene file (`*.ray_trace`) of the folder `scenes` (not of its subfolders,
/// which hold pieces the scenes include) with this build's pieces, in a section of its own,
/// and compares the image with the .png of the same name beside it; then checks that the
/// folder held at least `at_least` scenes.
inline void check_each_scene_renders_like_its_png(const std::filesystem::path& scenes, int at_least) {
    int rendered = 0;
    for (const auto& entry : std::filesystem::directory_iterator(scenes)) {
        if (entry.path().extension() != ".ray_trace") continue;
        const std::filesystem::path png = std::filesystem::path(entry.path()).replace_extension(".png");
        DYNAMIC_SECTION(entry.path().filename().string()) {
            if (!std::filesystem::exists(png))
                FAIL(entry.path().filename().string() << " has no reference image " << png.filename().string());
            const image_difference d = compare_render(entry.path(), png, all_pieces());
            INFO(entry.path().filename().string() << ": " << d.summary);
            INFO("to see the difference, render the scene with rt (the handout's section \"Render and look\") and look at "
                 "your image beside " << png.filename().string() << ", e.g. in the vfb viewer");
            CHECK(renders_match(d));
        }
        ++rendered;
    }
    CHECK(rendered >= at_least);
}

}  // namespace vl::testing
