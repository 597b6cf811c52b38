#pragma once
/// \file
/// \brief The grader's subcommands, one function each (main.cc's table runs them), and what
/// their command lines share: taking options out of the arguments, the options every
/// grading command takes, grading into a folder and where a grade goes without --out.
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "command_line.hh"
#include "grade.hh"
#include "install.hh"

namespace vl::grader {

/// A subcommand's arguments, the command's name not among them.
using arguments = std::vector<std::string>;

/// A mistake on the command line (the framework's programs' kind): printed with the
/// command's usage, exit status 2.
using vl::apps::command_line_error;

/// Takes `--flag VALUE` out of `args`; empty when absent.
std::string take_option(arguments& args, const std::string& flag);

/// Takes `--flag` out of `args`; whether it was there.
bool take_flag(arguments& args, const std::string& flag);

/// The options every grading command takes.
grade_options take_grade_options(arguments& args);

/// Throws command_line_error unless `args` are `n` arguments and no option.
void expect_count(const arguments& args, std::size_t n);

/// Grades and writes results.json and report.html into `out`.
graded_submission grade_into(const installation& in, const std::string& assignment,
                             const std::filesystem::path& submission, const std::filesystem::path& out,
                             grade_options options);

/// Where a grade goes without --out: build/grader-out/NN-name-NAME-HASH, NAME the
/// submission's file name and HASH (FNV-1a) of its absolute path, so two students'
/// folders of the same name never share one, and the build folder (ignored by git) holds it.
std::filesystem::path default_out(const installation& in, const std::string& assignment, const std::string& submission);

/// The CPUs this process may use (a cluster's allocation, taskset), at least 1.
/// How many items (tests, scenes) a grade runs at once by default when `grades_at_once`
/// grades share this process's CPUs: one per two CPUs of its share, 1 to 4.
int default_item_jobs(int grades_at_once);
int usable_cpus();

/// This program, for the roster to run once per submission.
std::filesystem::path own_program();

/// `text` as a whole number from 1 to 1024; else a command_line_error naming `what`.
int positive_number(const std::string& text, const std::string& what);

// The subcommands (grader/README.md says what each does), in commands.cc and, by what
// they are about, calibration.cc, roster_commands.cc and image_commands.cc.
int grade_command(const installation& in, arguments args);
int export_kit_command(const installation& in, const arguments& args);
int gradescope_command(const installation& in, const arguments& args);
int list_command(const installation& in, const arguments& args);
int calibrate_command(const installation& in, arguments args);
int roster_command(const installation& in, arguments args);
int roster_collect_command(const installation& in, const arguments& args);
int demo_command(const installation& in, arguments args);
int calibrate_thresholds_command(const installation& in, arguments args);
int imgdiff_command(arguments args);
int tradeoff_command(arguments args);

}  // namespace vl::grader
