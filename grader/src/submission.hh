#pragma once
/// \file
/// \brief Taking in a submission: a folder (the student's copy of assignments/NN-name, or
/// a whole student kit), or a .zip / .tar.gz / .tar of one. It is read only inside the
/// sandbox: unpacked into a size-capped tmpfs there, and only its regular source files
/// (no symlinks, no devices, none over 1 MiB) come back, as a tar stream the sandbox's own
/// `tar` writes and the grader reads. So no path in the submission is ever followed by
/// the grader, and a bomb fills only the sandbox's tmpfs.
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
    std::filesystem::path sources;       ///< the stage's own source files, one flat folder
    std::filesystem::path contract;      ///< the pristine contract headers of every stage
    std::vector<std::string> files;      ///< the .cc files in `sources`, by name
    std::string origin;                  ///< what was found where, for the report
    std::vector<std::string> notes;      ///< e.g. a contract header that was replaced
    std::vector<std::string> replaced_contracts;  ///< contract headers the student had changed (the originals were used)
    std::vector<std::string> kit_stages; ///< a whole kit: the stages with student code in it
};

/// Limits on what a submission may hold.
struct intake_limits {
    std::uint64_t unpacked_bytes = std::uint64_t{512} << 20;  ///< the sandbox's tmpfs
    int files = 20000;                                        ///< in the whole submission
    int sources = 100;                                        ///< in the stage's folder
    std::uint64_t source_bytes = std::uint64_t{8} << 20;      ///< the stage's sources together
};

/// Takes `submission` for `stage` into `work` (a fresh folder of the grader's). Throws
/// submission_error when it holds nothing to build or breaks a limit, grader_error when the
/// grader itself cannot work.
prepared_submission prepare_submission(const std::filesystem::path& submission, const stage_info& stage,
                                       const installation& in, const std::filesystem::path& work,
                                       const sandbox_capabilities& caps, double wall_seconds,
                                       const intake_limits& limits = {});

}  // namespace vl::grader
