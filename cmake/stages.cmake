# The stages: which implementation of each stage this build links, and the one list of
# stages that everything else is generated from.
#
# Every stage NN has a contract header in assignments/NN-name/ and two implementations of
# it: the student's (the .cc files beside the contract, stubs until a student fills them
# in) and the instructor's (reference/NN-name/*.cc). Because both implement the same
# contract behind the framework's interfaces, any mix links.
#
#   -DVL_PIECES=student            every stage from assignments/ (what a student builds)
#   -DVL_PIECES=reference          every stage from reference/ (the default when it exists)
#   -DVL_PIECES_02=student         override one stage
#   -DVL_SOURCE_DIR_02=/some/dir   take stage 02's .cc files from another folder
#
# The top level declares each stage with one line, vl_stage(NN name). That line builds the
# library vl_stage_NN and adds "NN-name" to the list of stages (the global property
# VL_STAGES). Nothing else names a stage: pieces/ generates from that list the aggregate
# vl::register_all_pieces() that rt, vfbsh and the stages' public tests use, and the
# grader (grader/CMakeLists.txt) generates its lists of stages from it too. A stage must
# follow the convention that makes this possible: its contract header is
# assignments/NN-name/stage_NN.hh and declares
#
#   namespace vl::stageNN { void register_stage_NN(vl::registry& r); }

if(EXISTS ${PROJECT_SOURCE_DIR}/reference)
  set(vl_default_pieces reference)
else()
  set(vl_default_pieces student)
endif()
set(VL_PIECES ${vl_default_pieces} CACHE STRING "Which pieces to build: reference or student")
set_property(CACHE VL_PIECES PROPERTY STRINGS reference student)
set_property(GLOBAL PROPERTY VL_STAGES "")

# vl_stage_registration(NN-name OUT): assignments/NN-name/register.cc, the one copy of the
# stage's scene-file names (vl::stageNN::register_stage_NN), or "" when the stage has none.
# The stubs hold it; the reference, the grader's reference and oracle libraries and every
# graded submission compile that same file (the grader replaces a submission's copy).
function(vl_stage_registration stage out)
  set(file ${PROJECT_SOURCE_DIR}/assignments/${stage}/register.cc)
  if(EXISTS ${file})
    set(${out} ${file} PARENT_SCOPE)
  else()
    set(${out} "" PARENT_SCOPE)
  endif()
endfunction()

# vl_stage(NN name [LIBS libs...]): declares stage NN-name and builds its library
# vl_stage_NN from the pieces this build uses for it (linked with LIBS), compiled once as
# the object library vl_stage_NN_objects; its code may use the contracts of every stage
# declared before it. The library's property VL_FROM_REFERENCE is ON when those are the
# reference's: then the grader makes the stage's reference library from the same objects
# instead of compiling the same files again.
function(vl_stage number name)
  cmake_parse_arguments(S "" "" "LIBS" ${ARGN})
  if(NOT number MATCHES "^[0-9][0-9]$" OR NOT name MATCHES "^[a-z][a-z0-9_-]*$")
    message(FATAL_ERROR "vl_stage(${number} ${name}): want a two-digit number and a lower-case name, "
                        "as in vl_stage(03 composites)")
  endif()
  set(stage_dir ${PROJECT_SOURCE_DIR}/assignments/${number}-${name})
  if(NOT EXISTS ${stage_dir}/stage_${number}.hh)
    message(FATAL_ERROR "stage ${number}-${name}: no contract header ${stage_dir}/stage_${number}.hh "
                        "(it declares vl::stage${number}::register_stage_${number}(vl::registry&))")
  endif()
  set(VL_PIECES_${number} "" CACHE STRING "Pieces for stage ${number} (reference or student; empty: VL_PIECES)")
  set(VL_SOURCE_DIR_${number} "" CACHE PATH "Take stage ${number}'s .cc files from this folder")
  set(pieces ${VL_PIECES_${number}})
  if(NOT pieces)
    set(pieces ${VL_PIECES})
  endif()
  set(reference_dir ${PROJECT_SOURCE_DIR}/reference/${number}-${name})
  if(VL_SOURCE_DIR_${number})
    set(source_dir ${VL_SOURCE_DIR_${number}})
  elseif(pieces STREQUAL "student")
    set(source_dir ${stage_dir})
  elseif(pieces STREQUAL "reference")
    set(source_dir ${reference_dir})
  else()
    message(FATAL_ERROR "VL_PIECES_${number}='${pieces}': use reference or student")
  endif()
  file(GLOB sources CONFIGURE_DEPENDS ${source_dir}/*.cc)
  if(NOT sources)
    message(FATAL_ERROR "stage ${number}: no .cc files in ${source_dir}")
  endif()
  # The stage's registration (assignments/NN-name/register.cc) is part of what is handed
  # out: pieces without their own copy (the reference) use it.
  vl_stage_registration(${number}-${name} registration)
  if(registration AND NOT EXISTS ${source_dir}/register.cc)
    list(APPEND sources ${registration})
  endif()
  add_library(vl_stage_${number}_objects OBJECT ${sources})
  # The contract header comes first, so a copy of it in source_dir is never used.
  target_include_directories(vl_stage_${number}_objects BEFORE PUBLIC ${stage_dir})
  target_link_libraries(vl_stage_${number}_objects PUBLIC vl_framework ${S_LIBS} PRIVATE vl_warnings)
  # A stage builds on the stages before it (stage 03's box is made of stage 02's polygons):
  # it sees their contracts. It does not link their libraries, so that any mix of a
  # stage's code with the others' links (the grader puts a submission or the stubs of one
  # stage beside the reference of the rest); programs link every stage, the later first.
  get_property(earlier GLOBAL PROPERTY VL_STAGES)
  foreach(stage IN LISTS earlier)
    target_include_directories(vl_stage_${number}_objects PUBLIC ${PROJECT_SOURCE_DIR}/assignments/${stage})
  endforeach()
  add_library(vl_stage_${number} STATIC)
  target_link_libraries(vl_stage_${number} PUBLIC vl_stage_${number}_objects)
  get_filename_component(real_source_dir ${source_dir} REALPATH)
  get_filename_component(real_reference_dir ${reference_dir} REALPATH)
  if(real_source_dir STREQUAL real_reference_dir)
    set_target_properties(vl_stage_${number} PROPERTIES VL_FROM_REFERENCE ON)
  else()
    set_target_properties(vl_stage_${number} PROPERTIES VL_FROM_REFERENCE OFF)
  endif()
  message(STATUS "stage ${number}-${name}: ${pieces} pieces from ${source_dir}")
  get_property(stages GLOBAL PROPERTY VL_STAGES)
  if(stages MATCHES "(^|;)${number}-")
    message(FATAL_ERROR "vl_stage(${number} ${name}): stage ${number} is declared twice")
  endif()
  set_property(GLOBAL APPEND PROPERTY VL_STAGES ${number}-${name})
endfunction()

# vl_generate_for_stages(TEMPLATE OUTPUT [STAGES NN-name...]): writes OUTPUT from
# TEMPLATE for the declared stages (or for those STAGES names). A line of TEMPLATE that
# holds @NN@ is written once per stage, in order, with @NN@ replaced by the stage's number
# and @NAME@ by its name; every other line is copied as it is. So this template line
#
#   stage@NN@::register_stage_@NN@(r);
#
# becomes one call per stage. OUTPUT is rewritten only when its text changes.
function(vl_generate_for_stages template output)
  cmake_parse_arguments(G "" "" "STAGES" ${ARGN})
  if("STAGES" IN_LIST ARGN)
    set(stages ${G_STAGES})
  else()
    get_property(stages GLOBAL PROPERTY VL_STAGES)
  endif()
  file(READ ${template} text)
  file(RELATIVE_PATH from ${PROJECT_SOURCE_DIR} ${template})
  set(out "// Generated by the build from ${from} (vl_generate_for_stages in\n// cmake/stages.cmake): edit the template, not this file.\n")
  # Line by line, without CMake lists: the lines are C++, full of ';'.
  while(NOT text STREQUAL "")
    string(FIND "${text}" "\n" end)
    if(end EQUAL -1)
      set(line "${text}")
      set(text "")
    else()
      string(SUBSTRING "${text}" 0 ${end} line)
      math(EXPR end "${end} + 1")
      string(SUBSTRING "${text}" ${end} -1 text)
    endif()
    string(FIND "${line}" "@NN@" per_stage)
    if(per_stage EQUAL -1)
      string(APPEND out "${line}\n")
      continue()
    endif()
    foreach(stage IN LISTS stages)
      string(SUBSTRING ${stage} 0 2 number)
      string(SUBSTRING ${stage} 3 -1 name)
      string(REPLACE "@NN@" "${number}" one "${line}")
      string(REPLACE "@NAME@" "${name}" one "${one}")
      string(APPEND out "${one}\n")
    endforeach()
  endwhile()
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${template})
  set(old "")
  if(EXISTS ${output})
    file(READ ${output} old)
  endif()
  if(NOT old STREQUAL out)
    file(WRITE ${output} "${out}")
  endif()
endfunction()
