#pragma once
/// \file
/// \brief How one item of a grade ended (the build, a hidden test, a scene, a sweep), and
/// the words for it that results.json, report.html, the terminal summary and the roster's
/// records use: one list, so they can never disagree.
#include <optional>
#include <string_view>

namespace vl::grader {

/// \brief An item's result; a test case's outcome is one of them too (never `refused`,
/// which only the build's source and symbol policy gives).
enum class item_result { passed, failed, crashed, timed_out, refused, not_run };

/// "passed", "failed", "crashed", "timed out", "refused", "not run".
inline const char* to_string(item_result r) {
    switch (r) {
        case item_result::passed: return "passed";
        case item_result::failed: return "failed";
        case item_result::crashed: return "crashed";
        case item_result::timed_out: return "timed out";
        case item_result::refused: return "refused";
        case item_result::not_run: break;
    }
    return "not run";
}

/// The result whose to_string is `text`; nothing for any other text.
inline std::optional<item_result> from_string(std::string_view text) {
    for (const item_result r : {item_result::passed, item_result::failed, item_result::crashed, item_result::timed_out,
                                item_result::refused, item_result::not_run})
        if (text == to_string(r)) return r;
    return std::nullopt;
}

}  // namespace vl::grader
