#pragma once
/// \file
/// \brief The reference's side of a grade: the hidden tests as the trusted program lists
/// them, those the untouched stubs already pass, and the reference's points of every
/// sweep and chart. They are the same for every submission of a build, so the first grade
/// after a build measures them and keeps them in `grader_build_dir/reference-cache/`;
/// later grades, and a roster's grades side by side, only read that file. It is the
/// grader's own (no sandbox can write there), written whole or not at all, and stale as
/// soon as a trusted program or the rubric changes.
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "catch_runner.hh"
#include "install.hh"
#include "rubric.hh"
#include "sweeps.hh"

namespace vl::grader {

/// \brief What a grade needs of the reference.
struct reference_side {
    std::vector<test_case_info> tests;                ///< every graded test, as the trusted program lists it
    std::set<std::string> kit_passes;                 ///< the tests the untouched stubs pass
    std::map<std::string, measured_points> points;    ///< by test: the reference's sweeps and charts
    bool from_cache = false;                          ///< read from the cache, not measured now
};

/// The reference's side of `stage` under rubric `r`: from the cache when it is current,
/// else measured in `work` (and then kept). Throws grader_error when a hidden test fails
/// with the reference, or a sweep's reference is not stable where the rubric says it is.
reference_side reference_side_of(const installation& in, const stage_info& stage, const rubric& r,
                                 const std::filesystem::path& work, const sandbox_capabilities& caps);

}  // namespace vl::grader
