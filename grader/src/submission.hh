#pragma once
/// \file
/// \brief Taking in a submission: a folder (the student's copy of assignments/NN-name, or
/// a whole student kit), or a .zip / .tar.gz of one, copied into a scratch folder with the
/// pristine contract header(s). The submission itself is only read.
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "install.hh"
#include "sandbox.hh"

namespace vl::grader {

/// \brief Something wrong with what the student handed in (not with the grader): it is
/// reported as the failed "builds" item, and the grade goes on.
class submission_error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// \brief A submission, ready to build.
struct prepared_submission {
    std::filesystem::path sources;       ///< scratch copy of the stage's own files
    std::filesystem::path contract;      ///< scratch copy of the pristine contract header(s)
    std::string origin;                  ///< what was found where, for the report
    std::vector<std::string> notes;      ///< e.g. a contract header that was replaced
    std::vector<std::string> kit_stages; ///< a whole kit: the stages with student code in it
};

/// Copies `submission` for `stage` into `scratch` (created). Throws submission_error when
/// it holds nothing to build, grader_error when it does not exist.
prepared_submission prepare_submission(const std::filesystem::path& submission, const stage_info& stage,
                                       const installation& in, const std::filesystem::path& scratch,
                                       const sandbox_capabilities& caps);

}  // namespace vl::grader
