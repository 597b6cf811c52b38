# The stages' pieces: which implementation of each stage this build links.
#
# Every stage NN has a contract header in assignments/NN-name/ and two implementations of
# it: the student's (the .cc files beside the contract, stubs until a student fills them
# in) and the instructor's (reference/NN-name/*.cc). Because both implement the same
# contract behind the framework's interfaces, any mix links.
#
#   -DVL_PIECES=student            every stage from assignments/ (what a student builds)
#   -DVL_PIECES=reference          every stage from reference/ (the default when it exists)
#   -DVL_PIECES_02=student         override one stage
#   -DVL_SOURCE_DIR_02=/some/dir   take stage 02's .cc files from another folder (the grader
#                                  points this at a copy of a submission)
#
# Each stage becomes a library vl_stage_NN; vl_pieces (framework/apps) links them all and
# register_all_pieces() calls every stage's register_stage_NN().

if(EXISTS ${PROJECT_SOURCE_DIR}/reference)
  set(vl_default_pieces reference)
else()
  set(vl_default_pieces student)
endif()
set(VL_PIECES ${vl_default_pieces} CACHE STRING "Which pieces to build: reference or student")
set_property(CACHE VL_PIECES PROPERTY STRINGS reference student)

# vl_stage(NN name [LIBS libs...]): the library vl_stage_NN and the stage's public tests.
function(vl_stage number name)
  cmake_parse_arguments(S "" "" "LIBS" ${ARGN})
  set(stage_dir ${PROJECT_SOURCE_DIR}/assignments/${number}-${name})
  set(VL_PIECES_${number} "" CACHE STRING "Pieces for stage ${number} (reference or student; empty: VL_PIECES)")
  set(VL_SOURCE_DIR_${number} "" CACHE PATH "Take stage ${number}'s .cc files from this folder")
  set(pieces ${VL_PIECES_${number}})
  if(NOT pieces)
    set(pieces ${VL_PIECES})
  endif()
  if(VL_SOURCE_DIR_${number})
    set(source_dir ${VL_SOURCE_DIR_${number}})
  elseif(pieces STREQUAL "student")
    set(source_dir ${stage_dir})
  elseif(pieces STREQUAL "reference")
    set(source_dir ${PROJECT_SOURCE_DIR}/reference/${number}-${name})
  else()
    message(FATAL_ERROR "VL_PIECES_${number}='${pieces}': use reference or student")
  endif()
  file(GLOB sources CONFIGURE_DEPENDS ${source_dir}/*.cc)
  if(NOT sources)
    message(FATAL_ERROR "stage ${number}: no .cc files in ${source_dir}")
  endif()
  add_library(vl_stage_${number} STATIC ${sources})
  # The contract header comes first, so a copy of it in source_dir is never used.
  target_include_directories(vl_stage_${number} BEFORE PUBLIC ${stage_dir})
  target_link_libraries(vl_stage_${number} PUBLIC vl_framework ${S_LIBS} PRIVATE vl_warnings)
  message(STATUS "stage ${number}-${name}: ${pieces} pieces from ${source_dir}")
  set(vl_stage_pieces_${number} ${pieces} PARENT_SCOPE)
endfunction()

# vl_stage_tests(NN name): the stage's public tests, labelled NN-name, against this build's
# pieces (called after vl_pieces exists).
function(vl_stage_tests number name)
  set(stage_dir ${PROJECT_SOURCE_DIR}/assignments/${number}-${name})
  file(GLOB tests CONFIGURE_DEPENDS ${stage_dir}/tests/*.cc)
  if(tests)
    vl_add_tests(stage_${number}_public_test LABEL ${number}-${name} LIBS vl_pieces SOURCES ${tests})
  endif()
endfunction()
