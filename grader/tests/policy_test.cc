// The grader's policy (grader/src/policy.hh): what it refuses in object symbols and in a
// student's preprocessed lines, and what it must let through (ordinary code, system
// headers, words in strings). A false refusal scores honest work 0, so both sides matter.
#include "vl/catch.hh"

#include <set>
#include <string>
#include <vector>

#include "policy.hh"

using vl::grader::check_preprocessed;
using vl::grader::check_raw_source;
using vl::grader::check_symbols;
using vl::grader::object_symbol;
using vl::grader::parse_nm;
using vl::grader::policy_finding;

namespace {

std::vector<policy_finding> undefined(const std::string& name, const std::string& demangled = "") {
    return check_symbols("a.cc", {{name, demangled.empty() ? name : demangled, 'U'}}, {}, {});
}

std::string reasons(const std::vector<policy_finding>& found) {
    std::string s;
    for (const policy_finding& f : found) s += f.describe() + "\n";
    return s;
}

/// A preprocessed file: a line marker for the student's file, then `body`.
std::string student(const std::string& body) { return "# 1 \"/submission/a.cc\"\n" + body; }

}  // namespace

TEST_CASE("policy: nm lines parse with trailing blanks, spaces in demangled names, values and sizes", "[grader][policy]") {
    const std::string mangled = "/in/a.o: exit U         \n/in/a.o: _ZN2vl1fEv T 0000000000000000 0000000000000010\n";
    const std::string demangled = "/in/a.o: exit U         \n/in/a.o: vl::f() T 0000000000000000 0000000000000010\n";
    const auto symbols = parse_nm(mangled, demangled);
    REQUIRE(symbols.size() == 2);
    CHECK(symbols[0].first == "/in/a.o");
    CHECK(symbols[0].second.name == "exit");
    CHECK(symbols[0].second.type == 'U');
    CHECK(symbols[1].second.name == "_ZN2vl1fEv");
    CHECK(symbols[1].second.demangled == "vl::f()");
    CHECK(symbols[1].second.type == 'T');
}

TEST_CASE("policy: calls that leave the computation are refused, each with its reason", "[grader][policy]") {
    CHECK(reasons(undefined("fopen")).find("opens or writes files") != std::string::npos);
    CHECK(reasons(undefined("__open_2")).find("opens or writes files") != std::string::npos);  // fortified open
    CHECK(reasons(undefined("__read_chk")).find("opens or writes files") != std::string::npos);
    CHECK(reasons(undefined("dprintf")).find("opens or writes files") != std::string::npos);
    CHECK(reasons(undefined("_ZNSt14basic_ofstreamIcSt11char_traitsIcEEC1EPKcSt13_Ios_Openmode",
                            "std::basic_ofstream<char, std::char_traits<char> >::basic_ofstream(char const*, "
                            "std::_Ios_Openmode)"))
              .find("opens or writes files") != std::string::npos);
    CHECK(reasons(undefined("_ZNSt10filesystem6removeERKNS_7__cxx114pathE", "std::filesystem::remove(std::filesystem::__cxx11::path const&)"))
              .find("opens or writes files") != std::string::npos);
    CHECK(reasons(undefined("_exit")).find("ends the process") != std::string::npos);
    CHECK(reasons(undefined("quick_exit")).find("ends the process") != std::string::npos);
    CHECK(reasons(undefined("posix_spawn")).find("starts processes") != std::string::npos);
    CHECK(reasons(undefined("kill")).find("sends signals") != std::string::npos);
    CHECK(reasons(undefined("connect")).find("uses the network") != std::string::npos);
    CHECK(reasons(undefined("dlsym")).find("loads code at run time") != std::string::npos);
    CHECK(reasons(undefined("_r_debug")).find("loads code at run time") != std::string::npos);
    CHECK(reasons(undefined("mprotect")).find("maps memory") != std::string::npos);
    CHECK(reasons(undefined("syscall")).find("makes raw system calls") != std::string::npos);
    CHECK(reasons(undefined("__libc_write")).find("makes raw system calls") != std::string::npos);
    CHECK(reasons(undefined("setenv")).find("changes the environment") != std::string::npos);
    CHECK(reasons(undefined("getenv")).find("reads or changes the environment") != std::string::npos);
    CHECK(reasons(undefined("__environ")).find("the environment") != std::string::npos);
    CHECK(reasons(undefined("program_invocation_name")).find("the environment") != std::string::npos);
    CHECK(reasons(undefined("_ZN2vl17reference_stage0211make_sphereERKNS_5pointEd",
                            "vl::reference_stage02::make_sphere(vl::point const&, double)"))
              .find("calls the reference solution") != std::string::npos);
    CHECK(reasons(undefined("_ZN5Catch9SessionC1Ev", "Catch::Session::Session()")).find("test framework") != std::string::npos);
    // glibc's public aliases of the same calls
    CHECK(reasons(undefined("__write")).find("opens or writes files") != std::string::npos);
    CHECK(reasons(undefined("__open64")).find("opens or writes files") != std::string::npos);
    CHECK(reasons(undefined("__fork")).find("starts processes") != std::string::npos);
    CHECK(reasons(undefined("__connect")).find("uses the network") != std::string::npos);
}

TEST_CASE("policy: printing, maths, threads, abort and the standard library are allowed", "[grader][policy]") {
    for (const char* name : {"printf", "__printf_chk", "__fprintf_chk", "puts", "fwrite", "sqrt", "abort", "malloc",
                             "pthread_create", "__cxa_atexit", "__cxa_throw", "memcpy", "__stack_chk_fail", "stderr",
                             "__libc_single_threaded"})  // read by std::shared_ptr's inline code
        CHECK(undefined(name).empty());
    CHECK(undefined("_ZNSolsEd", "std::ostream::operator<<(double)").empty());
    CHECK(undefined("_ZNSt6thread15_M_start_threadESt10unique_ptrINS_6_StateESt14default_deleteIS1_EEPFvvE",
                    "std::thread::_M_start_thread(std::unique_ptr<std::thread::_State, std::default_delete<std::thread::_State> >, void (*)())")
              .empty());
}

TEST_CASE("policy: a definition may not take the place of the runtime's or the framework's", "[grader][policy]") {
    const std::set<std::string> protected_symbols = {"open", "malloc", "_ZN2vl6renderEv", "_ZNKSs4sizeEv", "_ZN2vl3fooEv",
                                                     "DW.ref.__gxx_personality_v0"};
    // a framework function defined out of line, and the runtime's C functions
    const std::set<std::string> strong = {"_ZN2vl6renderEv", "open", "malloc"};
    auto defines = [&](const char* name, char type) {
        return check_symbols("a.cc", {{name, name, type}}, protected_symbols, strong);
    };
    CHECK(reasons(defines("open", 'T')).find("defines 'open'") != std::string::npos);
    CHECK(!defines("open", 'W').empty());        // a weak C function would interpose too
    CHECK(!defines("main", 'T').empty());
    CHECK(!defines("_ZN2vl6renderEv", 'T').empty());
    CHECK(!defines("_ZN2vl6renderEv", 'W').empty());  // an inline body in place of the framework's
    CHECK(defines("_ZNKSs4sizeEv", 'W').empty());     // an inline std:: member: a normal weak copy
    CHECK(defines("_ZN2vl3fooEv", 'W').empty());      // an inline framework function, weak everywhere
    CHECK(defines("DW.ref.__gxx_personality_v0", 'V').empty());  // the compiler's own weak helper
    CHECK(defines("_ZN2vl7stage026sphereEv", 'T').empty());  // the student's own function
    CHECK(defines("helper_counter", 'B').empty());    // a global of the student's own
    CHECK(defines("open", 't').empty());              // local symbols replace nothing
}

TEST_CASE("policy: only the student's own lines of the preprocessed source are checked", "[grader][policy]") {
    const std::string header = "# 1 \"/usr/include/x86_64-linux-gnu/sys/cdefs.h\" 1 3\nasm(\"nop\");\n";
    CHECK(check_preprocessed(header, "/submission/").empty());
    const auto found = check_preprocessed(student("int a;\n\nvoid f() { asm(\"nop\"); }\n"), "/submission/");
    REQUIRE(found.size() == 1);
    CHECK(found[0].file == "a.cc");
    CHECK(found[0].line == 3);
    CHECK(found[0].reason == "uses inline assembly");
    // back in the student's file after a header, the line count follows the marker
    const auto after = check_preprocessed(student("int a;\n# 7 \"/submission/a.cc\" 2\n__asm__(\"nop\");\n"), "/submission/");
    REQUIRE(after.size() == 1);
    CHECK(after[0].line == 7);
    // a student header reached by another spelling of its path is still the student's
    for (const char* alias : {"/./submission/x.hh", "//submission/x.hh", "/proc/self/root/submission/x.hh"})
        CHECK(check_preprocessed("# 1 \"" + std::string(alias) + "\" 1\nasm(\"nop\");\n", "/submission/").size() == 1);
    CHECK(check_preprocessed("# 1 \"/./vl/framework/vl/tuples.hh\" 1\nasm(\"nop\");\n", "/submission/").empty());
}

TEST_CASE("policy: words in strings, comments and longer names are not code", "[grader][policy]") {
    CHECK(check_preprocessed(student("const char* s = \"asm syscall exit thread_tallies\";\n"), "/submission/").empty());
    CHECK(check_preprocessed(student("const char* r = R\"x(asm \" detail)x\";\nchar c = '\"';\n"), "/submission/").empty());
    CHECK(check_preprocessed(student("int destructor_count = 0; int asmx = 1; struct Catch { int x; };\n"), "/submission/")
              .empty());
    CHECK(check_preprocessed(student("namespace vl::stage02 { namespace detail { int helper; } }\n"), "/submission/").empty());
    CHECK(check_preprocessed(student("int x = 1'000'000;\n"), "/submission/").empty());
}

TEST_CASE("policy: early code, attributes, counters and the test framework are refused in the student's lines", "[grader][policy]") {
    auto reason_of = [](const std::string& body) { return reasons(check_preprocessed(student(body), "/submission/")); };
    CHECK(reason_of("__attribute__((constructor)) void f() {}\n").find("runs code before main") != std::string::npos);
    CHECK(reason_of("[[gnu::constructor]] void f() {}\n").find("runs code before main") != std::string::npos);
    CHECK(reason_of("struct S {} s __attribute__((init_priority(101)));\n").find("runs code before main") != std::string::npos);
    CHECK(reason_of("void f() __attribute__((weak));\n").find("replaces a symbol") != std::string::npos);
    CHECK(reason_of("#pragma weak open\n").find("replaces a symbol") != std::string::npos);
    CHECK(reason_of("void f() { vl::detail::thread_tallies = {}; }\n").find("intersection counters") != std::string::npos);
    CHECK(reason_of("using namespace vl :: detail;\n").find("intersection counters") != std::string::npos);
    CHECK(reason_of("void f() { vl::clear_counts(); }\n").find("intersection counters") != std::string::npos);
    CHECK(reason_of("void f() { Catch::getResultCapture(); }\n").find("test framework") != std::string::npos);
    CHECK(reason_of("long f() { return syscall(39); }\n").find("raw system calls") != std::string::npos);
}

TEST_CASE("policy: a #line directive in a student's file is refused", "[grader][policy]") {
    CHECK(check_raw_source("a.cc", "#include <cmath>\n#define X 1\nint a;\n").empty());
    const auto found = check_raw_source("a.cc", "int a;\n#line 1 \"/usr/include/stdio.h\"\n  #  12 \"x.h\"\n");
    REQUIRE(found.size() == 2);
    CHECK(found[0].line == 2);
    CHECK(found[1].line == 3);
    CHECK(found[0].reason == "hides where its code comes from");
}

TEST_CASE("policy: a #line spelled with a comment, a digraph or a splice is still refused", "[grader][policy]") {
    CHECK(check_raw_source("a.cc", "#/**/line 1 \"x.h\"\n").size() == 1);
    CHECK(check_raw_source("a.cc", "%:line 1 \"x.h\"\n").size() == 1);
    CHECK(check_raw_source("a.cc", "#\\\nline 1 \"x.h\"\n").size() == 1);
    CHECK(check_raw_source("a.cc", "  /* c */ # /* d */ 7 \"x.h\" 3 4\n").size() == 1);
    // not directives: in a comment, in a string, in a raw string, after code on a line
    CHECK(check_raw_source("a.cc", "// #line 1\n/*\n#line 2\n*/\n").empty());
    CHECK(check_raw_source("a.cc", "const char* s = \"#line\";\nauto r = R\"(\n#line 3\n)\";\n").empty());
    CHECK(check_raw_source("a.cc", "int a; # line\n").empty());
    CHECK(check_raw_source("a.cc", "#include <cmath>\n#define LINE 1\n#if 1\n#endif\n").empty());
}
