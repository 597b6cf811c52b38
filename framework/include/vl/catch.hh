#pragma once
/// \file
/// \brief Catch2, the test framework of every test in the project: the one file that
/// includes it.
///
/// Tests include this header, never Catch2's own: what a test uses of Catch2 (TEST_CASE,
/// SECTION, REQUIRE, CHECK, INFO, `Approx`, the string matchers `Catch::Contains` and
/// `Catch::StartsWith`) is then named here once. The project builds with Catch2 2.13
/// (Debian 12's package catch2; `find_package(Catch2 2.13)` in the top-level
/// CMakeLists.txt). Moving to Catch2 3 (Debian 13) changes this file and the build, not
/// the tests: include <catch2/catch_all.hpp> here, bring `Catch::Approx` into the global
/// namespace, define `Catch::Contains` and `Catch::StartsWith` as the matchers
/// `Catch::Matchers::ContainsSubstring` and `Catch::Matchers::StartsWith`, and link
/// `Catch2::Catch2WithMain` instead of compiling framework/tests/catch_main.cc.

#include <catch2/catch.hpp>
