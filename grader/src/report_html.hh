#pragma once
/// \file
/// \brief report.html: one self-contained page (styles inline, images as data: URIs, no
/// script, nothing fetched) with the score by category, each failing item's message and
/// the hidden scenes side by side with the reference and their difference.
#include <filesystem>
#include <string>

#include "grade.hh"

namespace vl::grader {

/// The page for `g`.
std::string report_html(const graded_submission& g);

/// Writes report_html(g) to `file`.
void write_report_html(const graded_submission& g, const std::filesystem::path& file);

}  // namespace vl::grader
