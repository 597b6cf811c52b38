# cmake -P cmake/check_test_names.cmake ROOT
#
# Fails when a Catch2 TEST_CASE name holds a character that breaks catch_discover_tests:
# ';' (CMake splits the name into two tests) or '[' and ']' (Catch2 reads them as tags),
# or when two test cases of one file share a name. Either fault makes a test vanish from
# ctest, or pass without running, with no other sign. In a test a student runs (the
# public tests in assignments/, the hidden ones in grader/hidden/) a ',' fails too: Catch2
# reads it as "or", so a student who pastes the name runs other tests or none (the built
# programs are checked the same way by tools/check-test-names).
cmake_minimum_required(VERSION 3.25)
set(root ${CMAKE_ARGV3})
file(GLOB_RECURSE files ${root}/framework/*.cc ${root}/pieces/*.cc ${root}/assignments/*.cc ${root}/grader/hidden/*.cc ${root}/grader/tests/*.cc ${root}/bench/*.cc)
list(FILTER files EXCLUDE REGEX "/submissions/")
set(bad "")
foreach(f ${files})
  file(STRINGS ${f} lines REGEX "TEST_CASE\\(\"")
  set(seen "")
  foreach(line IN LISTS lines)
    string(REGEX MATCH "TEST_CASE\\(\"([^\"]*)\"" m "${line}")
    set(name "${CMAKE_MATCH_1}")
    if(name MATCHES "[][]")
      string(APPEND bad "${f}: test name has '[' or ']': ${name}\n")
    endif()
    string(FIND "${name}" "," comma)
    if(NOT comma EQUAL -1 AND f MATCHES "/(assignments|grader/hidden)/")
      string(APPEND bad "${f}: test name has ',' (Catch2 reads it as \"or\"): ${name}\n")
    endif()
    string(FIND "${name}" ";" semicolon)
    if(NOT semicolon EQUAL -1)
      string(APPEND bad "${f}: test name has ';': ${name}\n")
    endif()
    if("${name}" IN_LIST seen)
      string(APPEND bad "${f}: two test cases are called: ${name}\n")
    endif()
    list(APPEND seen "${name}")
  endforeach()
endforeach()
if(bad)
  message(FATAL_ERROR "Rename these test cases (ctest would split, merge or lose them):\n${bad}")
endif()
