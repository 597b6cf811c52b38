# The grader's calibration (ctest label `grader`): every case in
# grader/tests/submissions/NN-name/CASE/ is graded and checked against its expected.toml
# (score range, the only categories allowed to lose points, whether it builds).
#
# Under the sanitizers, a sample: each stage's reference, and one case of each other kind
# of grade (the stubs, wrong values, a crash, no end, no build). The sanitizers check the
# grader's and the framework's memory use, which every grade exercises alike; what the
# hidden tests catch is the same in both builds, and the default build grades every case.
# (measures_test.sh grades 01's camera-half-pixel in both builds.)
set(sanitizer_sample 01-tuples/reference 02-sphere/reference 03-composites/reference 04-shading/reference
                     01-tuples/stubs 01-tuples/inverse-no-pivoting 02-sphere/inside-misses 02-sphere/crash-contains
                     02-sphere/endless-write 02-sphere/compile-error)
# Every case here and in the adversarial suite is graded with the rubric's test and render
# time limits halved (calibrate --limits-scale 0.5): an endless loop then ends after 5 s
# instead of 10 (a render after 15 s instead of 30), while the slowest test of the
# reference takes about 0.3 s and of the correct alternatives about 1 s (03's
# alt-incremental-insertion, on a busy machine). A tighter limit can only fail an honest
# case, never pass a bug, and the code that enforces the limits is the same. Not under the sanitizers, whose
# unoptimised code is many times slower: there the rubric's limits (times 5) stand.
# ctest runs two cases at once, so each grades its items one at a time (--jobs 1), as
# the adversarial suite does: the timed tests then see the load they always saw.
if(sanitized)
  set(calibration_limits_scale 1)
else()
  set(calibration_limits_scale 0.5)
endif()
file(GLOB calibration_cases CONFIGURE_DEPENDS LIST_DIRECTORIES true ${CMAKE_CURRENT_LIST_DIR}/submissions/*/*)
list(SORT calibration_cases)
foreach(case_dir IN LISTS calibration_cases)
  if(NOT EXISTS ${case_dir}/expected.toml)
    continue()
  endif()
  get_filename_component(case_name ${case_dir} NAME)
  get_filename_component(stage_dir ${case_dir} DIRECTORY)
  get_filename_component(stage ${stage_dir} NAME)
  if(sanitized AND NOT "${stage}/${case_name}" IN_LIST sanitizer_sample)
    continue()
  endif()
  if(NOT stage IN_LIST grader_stages)
    continue()
  endif()
  add_test(NAME "grader: ${stage} ${case_name}"
           COMMAND vl_grader calibrate ${case_dir} --out ${CMAKE_CURRENT_BINARY_DIR}/calibration/${stage}/${case_name}
                   --limits-scale ${calibration_limits_scale} --jobs 1)
  set_tests_properties("grader: ${stage} ${case_name}" PROPERTIES LABELS grader TIMEOUT 600)
endforeach()

# COST (about the seconds a test takes) makes ctest start the long end-to-end tests first,
# so that none of them is left running alone at the end.
#
# The grader's own failures are its own: an --out it cannot use, no bubblewrap; and a
# fresh 0700 mktemp folder works for every stage (under the sanitizers, for one: the
# sample above grades every stage's reference).
if(sanitized)
  set(own_failure_stages 01-tuples)
else()
  set(own_failure_stages)
endif()
add_test(NAME "grader: its own failures exit non-zero and score no one, and any writable --out works"
         COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/own_failures.sh $<TARGET_FILE:vl_grader> ${PROJECT_SOURCE_DIR}
                 ${own_failure_stages})
set_tests_properties("grader: its own failures exit non-zero and score no one, and any writable --out works"
                     PROPERTIES LABELS grader TIMEOUT 900 COST 100)

# The student kit as a student meets it (kit_test.sh): export-kit refuses to write a kit in
# which any reference line or hidden test name appears (find_leaks); in the kit, the
# README's commands build it as written, its whole ctest fails only stage tests on the
# stubs, and with finished pieces every test and every documented command works. Not under
# the sanitizers: it is a second build of the framework, and the default preset already
# proves the point.
if(NOT sanitized)
  set(name "grader: the student kit leaks nothing, its README's commands work, only stage tests fail on the stubs, and finished pieces pass")
  add_test(NAME "${name}" COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/kit_test.sh $<TARGET_FILE:vl_grader>
                                  ${PROJECT_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/kit-test)
  set_tests_properties("${name}" PROPERTIES LABELS grader TIMEOUT 1500 COST 220)
endif()

# The adversarial suite (grader/tests/adversarial/README.md): every attack is graded as it
# is, and, when its expected.toml has a [sandbox] table, again with the source and symbol
# policy off, so the sandbox alone must hold it; two grades at a time. The suite checks
# that the checkout, the build tree and /tmp are unchanged afterwards, so it runs alone.
# Not under the sanitizers: the sandbox and the policy are the same code there, and their
# address-space limit is off.
file(GLOB attack_cases CONFIGURE_DEPENDS LIST_DIRECTORIES true ${CMAKE_CURRENT_LIST_DIR}/adversarial/*/*/expected.toml)
if(attack_cases AND NOT sanitized)
  set(name "grader: the adversarial suite: each attack is contained, scores no more than honest work, and changes nothing outside its grade")
  add_test(NAME "${name}" COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/adversarial_suite.sh $<TARGET_FILE:vl_grader>
                                  ${CMAKE_CURRENT_BINARY_DIR}/adversarial -s ${calibration_limits_scale})
  set_tests_properties("${name}" PROPERTIES LABELS grader TIMEOUT 2400 RUN_SERIAL TRUE)
endif()
