#pragma once
/// \file
/// \brief A roster's records (OUT/results/NAME.json, roster.hh) and what is made of them:
/// the summary CSV and the leaderboard. Shared by `roster`, which writes records, and
/// `roster-collect`, which only reads them (after a cluster's array tasks).
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "rubric.hh"

namespace vl::grader {

/// \brief What the roster knows of one student: the record in OUT/results/NAME.json.
struct roster_record {
    std::string student, submission, hash, assignment;
    std::string setup;         ///< what graded it: the grader, the hidden tests, the rubric (roster.hh)
    std::string status;        ///< "graded" or "grader error"
    std::string grade;         ///< the grade's folder, relative to OUT: grades/NAME-HASH
    std::string verdict;       ///< graded, did not build, refused (graded ones); grader error
    std::string message;       ///< a grader error: what went wrong (one line)
    double score = 0, max_score = 0, seconds = 0;
    bool built = false;
    struct category {
        std::string name;
        double score = 0, max_score = 0;
    };
    std::vector<category> categories;
    int passed = 0, failed = 0, crashed = 0, timed_out = 0, refused = 0, not_run = 0;
    std::vector<leaderboard_value> leaderboard;
};

/// \brief FNV-1a, 64 bits: the roster's hash of contents, of the grading setup and of long names.
struct fnv1a64 {
    std::uint64_t h = 14695981039346656037ull;
    void add(const void* data, std::size_t n) {
        const auto* p = static_cast<const unsigned char*>(data);
        for (std::size_t k = 0; k < n; ++k) h = (h ^ p[k]) * 1099511628211ull;
    }
    void add(const std::string& s) { add(s.data(), s.size() + 1); }  ///< with its terminating zero
    /// 16 hex digits.
    std::string hex() const;
};

/// The file name for student `name` in results/ and grades/: the name itself, or for a
/// name over 200 bytes its first 180 and a hash of the rest.
std::string roster_file_stem(const std::string& name);

/// The record of a finished grade, from its results.json (grade: its folder relative to OUT).
roster_record record_from_results(const std::filesystem::path& results_json, const std::string& student,
                                  const std::string& submission, const std::string& hash, const std::string& grade);

/// Writes `r` to OUT/results/STEM.json whole or not at all.
void write_record(const std::filesystem::path& out, const roster_record& r);

/// The record of `student` in OUT/results/, when there is a readable one.
bool read_record(const std::filesystem::path& out, const std::string& student, roster_record& r);

/// Every readable record in OUT/results/, by student name.
std::vector<roster_record> read_records(const std::filesystem::path& out);

/// The summary CSV (RFC 4180; a cell that a spreadsheet would take for a formula gets a
/// leading apostrophe): student, verdict, score, max_score, percent, one column per
/// category, the counts of passed, failed, crashed, timed out, refused and not run items,
/// hash, report, message. `missing`: students of the folder without a record ("not graded").
std::string roster_csv(const std::vector<roster_record>& records, const std::vector<std::string>& missing);

/// The leaderboard CSV: rank, student, one column per leaderboard value, score; ordered by
/// the first value (its order), then the next ones, then the name; students without values
/// last, unranked. Empty when no record has a value.
std::string leaderboard_csv(const std::vector<roster_record>& records);

}  // namespace vl::grader
