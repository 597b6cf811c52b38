#include "catch_runner.hh"

#include <sys/socket.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <pugixml.hpp>
#include <thread>

#include "../remote/channel.hh"
#include "install.hh"

namespace vl::grader {

namespace fs = std::filesystem;
static_assert(remote_channel_fd == remote::channel_fd, "the grader hands over the connection where both ends look");

namespace {

std::vector<std::string> split_tags(const std::string& tags) {
    std::vector<std::string> out;
    std::size_t at = 0;
    while ((at = tags.find('[', at)) != std::string::npos) {
        const std::size_t end = tags.find(']', at);
        if (end == std::string::npos) break;
        out.push_back(tags.substr(at + 1, end - at - 1));
        at = end + 1;
    }
    return out;
}

/// `s` without surrounding space, and cut to 500 characters: values and exception
/// messages come from student code, and a report is not a channel for bulk data.
std::string trim(std::string s) {
    const auto first = s.find_first_not_of(" \t\n\r");
    if (first == std::string::npos) return {};
    const auto last = s.find_last_not_of(" \t\n\r");
    s = s.substr(first, last - first + 1);
    if (s.size() > 500) s = s.substr(0, 500) + " [... " + std::to_string(s.size() - 500) + " more characters]";
    return s;
}

/// `s` without the blanks around it (Catch2 indents the text of an element).
std::string trim_all(const std::string& s) {
    const auto first = s.find_first_not_of(" \t\n\r");
    if (first == std::string::npos) return {};
    return s.substr(first, s.find_last_not_of(" \t\n\r") - first + 1);
}

/// Where a failure is, for the student: a public test's file and line (they have that
/// file), nothing for a hidden test (they do not; the test's name says which it is).
std::string where(const pugi::xml_node& n) {
    const fs::path file = n.attribute("filename").as_string();
    if (!is_public_test_file(file.string())) return {};
    return "tests/" + file.filename().string() + ":" + n.attribute("line").as_string() + ": ";
}

/// Every failure under `node` (sections nest), each with the INFO messages Catch2 wrote
/// for it (the ones in scope at that check; they come just before it).
void collect_failures(const pugi::xml_node& node, std::string& out, int& count) {
    std::string infos;
    auto report = [&](const std::string& text) {
        if (++count <= 6) out += text + infos;
        infos.clear();
    };
    for (const pugi::xml_node& c : node.children()) {
        const std::string kind = c.name();
        if (kind == "Info") {
            infos += "  with: " + trim(c.text().as_string()) + "\n";
        } else if (kind == "Expression" && !c.attribute("success").as_bool(true)) {
            const std::string original = trim(c.child("Original").text().as_string());
            const std::string expanded = trim(c.child("Expanded").text().as_string());
            std::string text = where(c) + c.attribute("type").as_string() + "( " + original + " )\n";
            if (!expanded.empty() && expanded != original) text += "  with values: " + expanded + "\n";
            for (const pugi::xml_node& e : c.children("Exception")) text += "  threw: " + trim(e.text().as_string()) + "\n";
            report(text);
        } else if (kind == "Exception") {
            report(where(c) + "threw an exception: " + trim(c.text().as_string()) + "\n");
        } else if (kind == "FatalErrorCondition") {
            report(where(c) + "crashed: " + trim(c.text().as_string()) + "\n");
        } else if (kind == "Failure") {
            report(where(c) + trim(c.text().as_string()) + "\n");
        } else if (kind == "Section") {
            infos.clear();
            collect_failures(c, out, count);
        }
    }
}

}  // namespace

bool is_public_test_file(const std::string& file) { return file.find("/assignments/") != std::string::npos; }

const test_case_info& named_test(const std::vector<test_case_info>& tests, const std::string& name) {
    const auto t = std::find_if(tests.begin(), tests.end(), [&](const test_case_info& x) { return x.name == name; });
    if (t == tests.end()) throw grader_error("the rubric names the hidden test '" + name + "', which does not exist");
    return *t;
}

std::string exact_test_spec(const std::string& name) {
    std::string spec;
    for (const char c : name) {
        if (c == '\\' || c == ',' || c == '[' || c == ']' || c == '"' || c == '~' || c == '*') spec += '\\';
        spec += c;
    }
    return spec;
}

namespace {

/// Runs every test of a trusted program (outside the sandbox: the grader's own code) and
/// returns its XML report; throws grader_error when it does not report.
void run_trusted(const fs::path& program, const fs::path& work, const sandbox_capabilities& caps,
                 pugi::xml_document& doc) {
    fs::create_directories(work);
    run_request rq;
    rq.argv = {program.string(), "-r", "xml", "-o", "/dev/fd/3"};
    rq.cwd = work.string();
    rq.environment = child_environment(work.string());
    rq.limits.wall_seconds = 300;
    rq.report_fd = true;
    rq.sandboxed = false;
    const run_result r = run(rq, caps);
    if (!r.started || r.timed_out || !doc.load_buffer(r.report.data(), r.report.size()) ||
        !doc.select_node("/*/OverallResults"))
        throw grader_error("the trusted test program " + program.string() + " did not report (" + r.describe(300) +
                           "); rebuild with tools/setup");
}

}  // namespace

std::vector<test_case_info> list_trusted_tests(const fs::path& program, const fs::path& work,
                                               const sandbox_capabilities& caps) {
    pugi::xml_document doc;
    run_trusted(program, work, caps, doc);
    std::vector<test_case_info> tests;
    std::string broken;
    for (const pugi::xpath_node& x : doc.select_nodes("//TestCase")) {
        const pugi::xml_node t = x.node();
        tests.push_back({t.attribute("name").as_string(), split_tags(t.attribute("tags").as_string()),
                         t.attribute("tags").as_string(), t.attribute("filename").as_string(),
                         t.attribute("line").as_string()});
        if (!t.child("OverallResult").attribute("success").as_bool(false)) {
            std::string message;
            int count = 0;
            collect_failures(t, message, count);
            broken += "  " + tests.back().name + "\n" + message;
        }
    }
    if (!broken.empty())
        throw grader_error("graded tests fail with the reference, so they cannot grade anyone:\n" + broken +
                           "fix the test or the reference first");
    if (tests.empty()) throw grader_error(program.string() + " holds no test cases");
    return tests;
}

std::set<std::string> tests_passing_on_stubs(const fs::path& program, const fs::path& work,
                                             const sandbox_capabilities& caps) {
    pugi::xml_document doc;
    run_trusted(program, work, caps, doc);
    std::set<std::string> passing;
    for (const pugi::xpath_node& x : doc.select_nodes("//TestCase"))
        if (x.node().child("OverallResult").attribute("success").as_bool(false))
            passing.insert(x.node().attribute("name").as_string());
    return passing;
}

namespace {

/// How the test `expected` went, from the run of the program that ran it and wrote its report.
test_outcome outcome_of(const run_result& r, const test_case_info& expected, const run_limits& limits) {
    const std::string& name = expected.name;
    test_outcome o;
    o.seconds = r.seconds;
    if (r.timed_out) {
        o.result = item_result::timed_out;
        o.message = "the test " + r.describe(limits.wall_seconds);
        return o;
    }
    if (r.report_overflow) {
        o.result = item_result::failed;
        o.message = "the test's report grew past " + std::to_string(limits.report_bytes >> 20) + " MiB";
        return o;
    }
    // Only the report counts: a report of exactly this test case, finished (its own result
    // and the run's totals written), from a process that then exited cleanly.
    pugi::xml_document doc;
    pugi::xml_node test;
    int reported = 0;
    const bool parsed = doc.load_buffer(r.report.data(), r.report.size());
    if (parsed) {
        for (const pugi::xpath_node& x : doc.select_nodes("//TestCase")) {
            ++reported;
            if (x.node().attribute("name").as_string() == name) test = x.node();
        }
    }
    const bool genuine = test && expected.raw_tags == test.attribute("tags").as_string() &&
                         expected.file == test.attribute("filename").as_string() &&
                         expected.line == test.attribute("line").as_string();
    const bool finished = parsed && test && test.child("OverallResult") &&
                          doc.select_node("/*/OverallResults") && reported == 1 && genuine;
    std::string message;
    int count = 0;
    if (test) collect_failures(test, message, count);
    if (count > 6) message += "[... " + std::to_string(count - 6) + " more failures]\n";
    const bool success = finished && test.child("OverallResult").attribute("success").as_bool(false);
    if (finished)
        for (const pugi::xpath_node& w : test.select_nodes(".//Warning")) o.warnings.push_back(trim_all(w.node().text().as_string()));
    if (success && r.succeeded()) {
        o.result = item_result::passed;
    } else if (r.signal != 0 || !finished || test.child("FatalErrorCondition") ||
               test.select_node(".//FatalErrorCondition")) {
        o.result = item_result::crashed;
        if (r.signal != 0 || r.exit_code != 0)
            o.message = message + "the test program was " + r.describe(limits.wall_seconds) +
                        (finished ? "" : " before the test finished");
        else if (test && !genuine)
            o.message = message + "the report is not one Catch2 wrote for this test";
        else
            o.message = message + "the test program ended before the test finished";
    } else {
        o.result = item_result::failed;
        o.message = message.empty() ? "the test program ended with " + r.describe(limits.wall_seconds) : message;
    }
    return o;
}

/// A Catch2 program's run of the one test case `name`, reporting to fd 3.
run_request test_request(const fs::path& program, const std::string& inside, const std::string& name,
                         const run_limits& limits) {
    run_request rq;
    rq.mounts = {{program, inside, false}};
    rq.argv = {inside, exact_test_spec(name), "-r", "xml", "-o", "/dev/fd/3"};
    rq.environment = child_environment("/scratch");
    rq.limits = limits;
    rq.report_fd = true;
    return rq;
}

}  // namespace

test_outcome run_test_case(const fs::path& program, const test_case_info& expected, const run_limits& limits,
                           const sandbox_capabilities& caps) {
    const run_result r = run(test_request(program, "/vl/bin/hidden_tests", expected.name, limits), caps);
    if (!r.started) throw grader_error("the sandbox could not run the hidden tests: " + r.error);
    return outcome_of(r, expected, limits);
}

test_outcome run_judged_test_case(const fs::path& judge, const fs::path& subject, const test_case_info& expected,
                                  const run_limits& limits, const sandbox_capabilities& caps) {
    int ends[2];
    if (socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, ends) != 0)
        throw grader_error(std::string("socketpair: ") + std::strerror(errno));
    // The subject: the student's code and nothing else, serving the judge's calls.
    run_request sq;
    sq.mounts = {{subject, "/vl/bin/subject", false}};
    sq.argv = {"/vl/bin/subject"};
    sq.environment = child_environment("/scratch");
    sq.limits = limits;
    // A thread of the subject serves each thread of the judge that calls, beside the
    // threads of the student's own code.
    sq.limits.processes = 2 * limits.processes;
    sq.channel = ends[1];
    // The judge: the test, its expected values and its verdict, in a sandbox of its own.
    run_request jq = test_request(judge, "/vl/bin/judge", expected.name, limits);
    jq.environment.push_back("VL_SUBJECT_FD=" + std::to_string(remote_channel_fd));
    jq.channel = ends[0];
    run_result s;
    std::thread subject_thread([&] { s = run(sq, caps); });
    const run_result j = run(jq, caps);
    subject_thread.join();
    if (!j.started) throw grader_error("the sandbox could not run the judge: " + j.error);
    if (!s.started) throw grader_error("the sandbox could not run the submission's code: " + s.error);

    test_outcome o = outcome_of(j, expected, limits);
    o.seconds = std::max(j.seconds, s.seconds);
    if (o.result == item_result::timed_out || s.timed_out) {
        o.result = item_result::timed_out;
        o.message = "the test " + (j.timed_out ? j : s).describe(limits.wall_seconds);
        o.warnings.clear();
        return o;
    }
    // The verdict is the judge's; the subject's end can only take a pass away. Its process
    // must end cleanly once the judge is done, as a test program had to.
    if (!s.succeeded()) {
        std::string how = "your code's process " + std::string(s.signal != 0 ? "was " : "ended with ") +
                          s.describe(limits.wall_seconds);
        // What it printed last says why, in its own words (an uncaught exception's message).
        if (const std::string tail = s.output_tail(500); !tail.empty())
            how += "; the end of what your code printed:\n" + tail;
        if (o.result == item_result::passed || s.signal != 0) o.result = item_result::crashed;
        o.message += (o.message.empty() || o.message.ends_with("\n") ? "" : "\n") + how;
        o.warnings.clear();
    }
    return o;
}

test_outcome run_graded_test(const test_programs& programs, const test_case_info& test, const run_limits& limits,
                             const sandbox_capabilities& caps) {
    if (programs.empty()) return test_outcome{item_result::failed, "no test program", 0, {}};
    return programs.judge.empty() ? run_test_case(programs.subject, test, limits, caps)
                                  : run_judged_test_case(programs.judge, programs.subject, test, limits, caps);
}

}  // namespace vl::grader
