#pragma once
/// \file
/// \brief Grading a course: every submission in a folder, several at once, each by its own
/// `grader grade` process (so each in its own sandboxes, and a grader failure on one
/// submission costs only that one), resumable after a crash, summed up in a CSV and a
/// leaderboard (grader/README.md, "Grading a course").
///
/// The output folder:
///
///     OUT/roster.json               the assignment and the submissions' folder
///     OUT/results/NAME.json         one record per student, written whole or not at all
///     OUT/grades/NAME-HASH/         that grade's results.json, report.html, renders/, grader.log
///     OUT/roster.csv                one line per student (roster_csv)
///     OUT/leaderboard.csv           where the rubric has a [[leaderboard]]
///     OUT/.work/                    grades under way (a killed roster's are cleared)
///
/// A record is the only proof that a student was graded: it is written (temporary file,
/// then rename) after the grade's folder is complete and in place, and names the content
/// hash of what was graded. A rerun skips a student whose record names the hash the
/// submission has now; everyone else is graded again.
#include <filesystem>
#include <string>
#include <vector>

#include "install.hh"

namespace vl::grader {

/// \brief One student's submission in the roster's folder.
struct roster_entry {
    std::string name;                  ///< the folder's or the archive's name without .zip, .tar.gz, .tgz, .tar
    std::filesystem::path submission;  ///< absolute
};

/// \brief Options of `grader/run roster`.
struct roster_options {
    std::filesystem::path out;
    int jobs = 1;                        ///< grades at once
    std::vector<std::string> regrade;    ///< students graded again whatever their record says
    int shard = 0, shards = 1;           ///< grade only the entries k with k % shards == shard
    bool weaker_sandbox = false;
    bool progress_bar = false;           ///< redraw one line on stderr (a terminal)
    std::filesystem::path grader_program;  ///< this program, run as `grade` once per student
};

/// The submissions in `dir`: each folder and each .zip, .tar.gz, .tgz or .tar, by name;
/// hidden entries (a leading '.') are skipped, other files are listed in `skipped`. Two
/// entries of one name (alice/ and alice.zip) are an error that names both. An entry that
/// is or holds `out` (the roster's own output folder, absolute) is skipped too.
std::vector<roster_entry> list_submissions(const std::filesystem::path& dir, std::vector<std::string>& skipped,
                                           const std::filesystem::path& out = {});

/// The content hash of a submission (16 hex digits of FNV-1a 64 over its files' paths,
/// kinds and bytes, in sorted order; links by their target, never followed). It tells a
/// changed submission from an unchanged one; it is no defence against a forger.
std::string content_hash(const std::filesystem::path& submission);

/// The hash of what grades a submission of `stage`: the grader program, the trusted
/// programs and libraries, and every file of grader/hidden/NN-name (rubric, tests, scenes).
/// A record made with another is graded again: a CSV never mixes two rubrics.
std::string setup_hash(const installation& in, const stage_info& stage, const std::filesystem::path& grader_program);

/// Grades the roster's submissions into options.out; returns the process's exit status
/// (0: every student in this shard has a grade; 1: some grades failed through the grader,
/// each named, and a rerun tries them again).
int run_roster(const installation& in, const stage_info& stage, const std::filesystem::path& dir,
               const roster_options& options);

/// Writes OUT/roster.csv and, where the rubric has one, OUT/leaderboard.csv from the
/// records in OUT/results/ (after a roster, or after a cluster's array tasks); prints
/// where they are and who has no grade yet. Returns 0 when every submission of the
/// roster's folder has a grade, 1 otherwise. It refuses while a roster grades into OUT
/// (`locked`: the caller is that roster).
int collect_roster(const std::filesystem::path& out, bool quiet = false, bool locked = false);

}  // namespace vl::grader
