#pragma once
// Tests' helper: run a program through the shell and keep what it printed.
#include <sys/wait.h>

#include "vl/catch.hh"

#include <cstdio>
#include <string>

namespace vl::test {

struct run_result {
    int status;          // the exit status
    std::string output;  // stdout and stderr
};

/// Runs `program args` (args as the shell reads them), stderr into stdout.
inline run_result run_program(const std::string& program, const std::string& args) {
    const std::string command = program + " " + args + " 2>&1";
    FILE* pipe = popen(command.c_str(), "r");
    REQUIRE(pipe);
    std::string out;
    char buffer[4096];
    while (const std::size_t n = std::fread(buffer, 1, sizeof buffer, pipe)) out.append(buffer, n);
    const int status = pclose(pipe);
    return {WEXITSTATUS(status), out};
}

}  // namespace vl::test
