// A roster's records, summary CSV and leaderboard (roster_results.hh): what an instructor
// opens in a spreadsheet must say exactly what each grade said.
#include "vl/catch.hh"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

#include "roster_results.hh"

using namespace vl::grader;
namespace fs = std::filesystem;

namespace {

roster_record graded(const std::string& student, double score, std::vector<leaderboard_value> board = {}) {
    roster_record r;
    r.student = student;
    r.status = "graded";
    r.verdict = "graded";
    r.hash = "00000000000000aa";
    r.grade = "grades/" + student + "-00000000000000aa";
    r.score = score;
    r.max_score = 100;
    r.built = true;
    r.categories = {{"sphere", score * 0.6, 60}, {"planes", score * 0.4, 40}};
    r.passed = 10;
    r.leaderboard = std::move(board);
    return r;
}

std::vector<std::string> lines(const std::string& csv) {
    std::vector<std::string> out;
    std::size_t start = 0;
    while (start < csv.size()) {
        const std::size_t end = csv.find("\r\n", start);
        out.push_back(csv.substr(start, end - start));
        start = end + 2;
    }
    return out;
}

struct temp_dir {
    fs::path path = fs::temp_directory_path() / ("vl-roster-results-" + std::to_string(getpid()));
    temp_dir() { fs::create_directories(path / "results"); }
    ~temp_dir() { fs::remove_all(path); }
};

}  // namespace

TEST_CASE("roster csv: one row per student by name, categories in rubric order, counts and the report") {
    const std::string csv = roster_csv({graded("bob", 50), graded("alice", 100)}, {"carol"});
    const auto l = lines(csv);
    REQUIRE(l.size() == 4);
    CHECK(l[0] == R"c("student","verdict","score","max_score","percent","sphere","planes","passed","failed","crashed",)c"
                  R"c("timed_out","refused","not_run","hash","report","message")c");
    CHECK(l[1] == R"c("alice","graded",100,100,100,60,40,10,0,0,0,0,0,"00000000000000aa",)c"
                  R"c("grades/alice-00000000000000aa/report.html","")c");
    CHECK(l[2] == R"c("bob","graded",50,100,50,30,20,10,0,0,0,0,0,"00000000000000aa",)c"
                  R"c("grades/bob-00000000000000aa/report.html","")c");
    CHECK(l[3].starts_with(R"c("carol","not graded",,,,,,,,,,,,,,)c"));
    CHECK(l[3].ends_with(R"c("no grade yet: grade it with the roster again")c"));
}

TEST_CASE("roster csv: a grader error has no score, and its message is there") {
    roster_record r;
    r.student = "dan";
    r.status = "grader error";
    r.hash = "1";
    r.message = "the grader failed: bubblewrap cannot run";
    const auto l = lines(roster_csv({r}, {}));
    REQUIRE(l.size() == 2);
    CHECK(l[1] == R"c("dan","grader error",,,,,,,,,,"1",,"the grader failed: bubblewrap cannot run")c");
}

TEST_CASE("roster csv: commas, quotes and line breaks are quoted, and a formula is made text") {
    const auto l = lines(roster_csv({graded("o\"neil, jr", 10), graded("=HYPERLINK(\"x\")", 20), graded("-2+3", 30)}, {}));
    REQUIRE(l.size() == 4);
    CHECK(l[1].starts_with(R"c("'-2+3","graded",30,)c"));  // not the number 1, and not run as a formula
    CHECK(l[2].starts_with(R"c("'=HYPERLINK(""x"")","graded",20,)c"));
    CHECK(l[3].starts_with(R"c("o""neil, jr","graded",10,)c"));
    const auto broken = roster_csv({graded("two\nlines", 1)}, {});
    CHECK(broken.find("\"two\nlines\",\"graded\"") != std::string::npos);
}

namespace {

/// The fields a spreadsheet that ignores quotes sees when it splits a line at `sep`.
std::vector<std::string> naive_fields(const std::string& line, char sep) {
    std::vector<std::string> out(1);
    for (const char c : line) {
        if (c == sep || c == '\n') out.emplace_back();
        else if (c != '"') out.back() += c;
    }
    return out;
}

}  // namespace

TEST_CASE("roster csv: no field starts a formula for readers that split at commas, semicolons, tabs or bars and ignore quotes") {
    // Folder names and messages as a student could choose them.
    const std::vector<std::string> names = {"a;=1+1",       "x, =cmd|' /C calc'!A0", "t\t@SUM(A1)", "p|+1",
                                            "q;  -2",       "r\n=HYPERLINK(\"u\")",  "\r=1",       " =1",
                                            "ok;fine, too"};
    std::vector<roster_record> records;
    for (const auto& n : names) {
        records.push_back(graded(n, 1));
        records.back().message = n;
    }
    const std::string csv = roster_csv(records, {names[0]}) + leaderboard_csv({graded(names[1], 1, {{names[2], "asc", 1}})});
    for (const char sep : {',', ';', '\t', '|'})
        for (const std::string& field : naive_fields(csv, sep)) {
            const auto start = field.find_first_not_of(" \r");
            INFO("separator '" << sep << "', field [" << field << "]");
            CHECK((start == std::string::npos || std::string("=+-@").find(field[start]) == std::string::npos));
        }
    // What the quotes keep together reads back as written, less the apostrophes.
    CHECK(csv.find(R"c("a;'=1+1")c") != std::string::npos);
    CHECK(csv.find(R"c("ok;fine, too")c") != std::string::npos);
}

TEST_CASE("leaderboard: ascending values rank first, equal values share a rank, no value is last and unranked") {
    const auto value = [](double v) { return std::vector<leaderboard_value>{{"BVH tests per ray", "asc", v}}; };
    const std::string csv = leaderboard_csv(
        {graded("ann", 90, value(80)), graded("ben", 100, value(60)), graded("cy", 100, value(80)), graded("di", 40),
         graded("ed", 100, value(95))});
    const auto l = lines(csv);
    REQUIRE(l.size() == 6);
    CHECK(l[0] == R"c("rank","student","BVH tests per ray (lower is better)","score")c");
    CHECK(l[1] == R"c(1,"ben",60,100)c");
    CHECK(l[2] == R"c(2,"ann",80,90)c");
    CHECK(l[3] == R"c(2,"cy",80,100)c");
    CHECK(l[4] == R"c(4,"ed",95,100)c");
    CHECK(l[5] == R"c(,"di",,40)c");
}

TEST_CASE("leaderboard: descending order, and none at all when no grade has a value") {
    const auto value = [](double v) { return std::vector<leaderboard_value>{{"speed", "desc", v}}; };
    const auto l = lines(leaderboard_csv({graded("ann", 1, value(2)), graded("ben", 1, value(3))}));
    REQUIRE(l.size() == 3);
    CHECK(l[1] == R"c(1,"ben",3,1)c");
    CHECK(l[2] == R"c(2,"ann",2,1)c");
    CHECK(leaderboard_csv({graded("ann", 1), graded("ben", 2)}).empty());
}

TEST_CASE("roster records: written whole, read back the same, and a results.json becomes a record") {
    temp_dir t;
    const roster_record r = graded("alice", 87.5, {{"BVH tests per ray", "asc", 83.255}});
    write_record(t.path, r);
    roster_record back;
    REQUIRE(read_record(t.path, "alice", back));
    CHECK(back.score == 87.5);
    CHECK(back.categories.size() == 2);
    CHECK(back.leaderboard.size() == 1);
    CHECK(back.leaderboard[0].value == 83.255);
    CHECK_FALSE(read_record(t.path, "bob", back));
    {
        std::ofstream(t.path / "results" / "broken.json") << "{ not json";
    }
    CHECK(read_records(t.path).size() == 1);  // the broken file is no record

    const fs::path results = t.path / "results.json";
    std::ofstream(results) << R"({"score": 40.5, "execution_time": 5,
        "leaderboard": [{"name": "BVH tests per ray", "value": 70.0, "order": "asc"}],
        "tests": [{"number": "0", "extra_data": {"result": "passed"}},
                  {"number": "1.1", "extra_data": {"result": "failed"}},
                  {"number": "1.2", "extra_data": {"result": "timed out"}},
                  {"number": "1.3", "extra_data": {"result": "crashed"}},
                  {"number": "1.4", "extra_data": {"result": "passed"}}],
        "extra_data": {"assignment": "03-composites", "max_score": 100, "built": true,
                       "categories": [{"name": "bvh", "score": 40.5, "max_score": 100}]}})";
    const roster_record g = record_from_results(results, "eve", "/x/eve.zip", "ff", "grades/eve-ff");
    CHECK(g.verdict == "graded");
    CHECK(g.score == 40.5);
    CHECK(g.passed == 2);
    CHECK(g.failed == 1);
    CHECK(g.timed_out == 1);
    CHECK(g.crashed == 1);
    CHECK(g.leaderboard.size() == 1);
    CHECK(g.assignment == "03-composites");
}

TEST_CASE("roster records: a refused build is the verdict refused, a failed one did not build") {
    temp_dir t;
    const fs::path results = t.path / "results.json";
    std::ofstream(results) << R"({"score": 0, "tests": [{"number": "0", "extra_data": {"result": "refused"}}],
        "extra_data": {"max_score": 100, "built": false, "categories": []}})";
    CHECK(record_from_results(results, "x", "x", "1", "g").verdict == "refused");
    std::ofstream(results) << R"({"score": 0, "tests": [{"number": "0", "extra_data": {"result": "failed"}}],
        "extra_data": {"max_score": 100, "built": false, "categories": []}})";
    CHECK(record_from_results(results, "x", "x", "1", "g").verdict == "did not build");
    std::ofstream(results) << "no json";
    CHECK_THROWS_WITH(record_from_results(results, "x", "x", "1", "g"), Catch::Contains("not a results.json"));
}

TEST_CASE("roster file names: a long name is cut and told apart by a hash") {
    CHECK(roster_file_stem("alice") == "alice");
    const std::string a(300, 'a');
    std::string b = a;
    b.back() = 'b';
    CHECK(roster_file_stem(a).size() <= 200);
    CHECK(roster_file_stem(a) != roster_file_stem(b));
}
