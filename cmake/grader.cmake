# The grader's half of the build (included by grader/CMakeLists.txt).
#
# The main build compiles, once, everything a submission's build can reuse: each stage's
# reference as its own library, each stage's hidden tests and the renderer as object
# files, the trusted test programs (hidden tests + reference) and the reference renders
# of the hidden scenes. It then writes grader.toml next to the grader: where everything
# is, and how a submission is compiled and linked with these parts (the same compiler and
# flags), which the grader mounts into each sandbox under neutral names.
# Stages are not listed here: every stage the top level declares with vl_stage(NN name)
# (cmake/stages.cmake) whose folder reference/NN-name has .cc files is gradable;
# grader/hidden/NN-name adds its hidden tests, scenes and rubric.

# vl_grader_find_stages(OUT): "NN-name" for every gradable stage, in order.
function(vl_grader_find_stages out)
  get_property(declared GLOBAL PROPERTY VL_STAGES)
  set(stages)
  foreach(stage IN LISTS declared)
    file(GLOB sources ${PROJECT_SOURCE_DIR}/reference/${stage}/*.cc)
    if(sources)
      list(APPEND stages ${stage})
    endif()
  endforeach()
  set(${out} ${stages} PARENT_SCOPE)
endfunction()

# vl_grader_contract_dirs(OUT): every stage's contract folder (assignments/NN-name), which
# a stage's code may include (stage 03's box is made of stage 02's polygons).
function(vl_grader_contract_dirs out)
  file(GLOB dirs LIST_DIRECTORIES true ${PROJECT_SOURCE_DIR}/assignments/[0-9][0-9]-*)
  list(SORT dirs)
  set(${out} ${dirs} PARENT_SCOPE)
endfunction()

# vl_grader_reference_sources(NN-name OUT): the reference's .cc files and the stage's
# registration, which the reference shares with the stubs (vl_stage_registration).
function(vl_grader_reference_sources stage out)
  file(GLOB sources CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/reference/${stage}/*.cc)
  vl_stage_registration(${stage} registration)
  if(registration AND NOT EXISTS ${PROJECT_SOURCE_DIR}/reference/${stage}/register.cc)
    list(APPEND sources ${registration})
  endif()
  set(${out} ${sources} PARENT_SCOPE)
endfunction()

# vl_grader_reference_library(NN-name): vl_grader_reference_NN, the stage's reference,
# whatever VL_PIECES this build uses for vl_stage_NN. When vl_stage_NN is built from the
# reference, this library is made of its objects (the same files are not compiled twice);
# otherwise the reference is compiled here. Either way it links only the framework, not
# the other stages vl_stage_NN may link (LIBS): a grader program picks each stage's code.
function(vl_grader_reference_library stage)
  string(SUBSTRING ${stage} 0 2 number)
  get_target_property(from_reference vl_stage_${number} VL_FROM_REFERENCE)
  if(from_reference)
    set(sources $<TARGET_OBJECTS:vl_stage_${number}_objects>)
  else()
    vl_grader_reference_sources(${stage} sources)
  endif()
  add_library(vl_grader_reference_${number} STATIC ${sources})
  target_include_directories(vl_grader_reference_${number} BEFORE PUBLIC ${PROJECT_SOURCE_DIR}/assignments/${stage})
  vl_grader_contract_dirs(contracts)  # a stage builds on the earlier stages' contracts
  target_include_directories(vl_grader_reference_${number} PUBLIC ${contracts})
  target_link_libraries(vl_grader_reference_${number} PUBLIC vl_framework PRIVATE vl_warnings)
endfunction()

# vl_grader_oracle_library(NN-name): the stage's oracle, its reference compiled a second
# time into namespace vl::reference_stageNN instead of vl::stageNN, so that it links beside
# a submission's code of the same stage: the grader's render program takes from it every
# piece of the stage a graded scene does not take from the submission. A render must link
# no reference code of the pieces its scene grades, so the oracle comes in parts:
#   vl_grader_oracle_NN               the reference's .cc files (OBJECT), one object each
#   vl_grader_oracle_registration_NN  the stage's registration and the oracle's entry
#                                     vl::graded::register_reference_pieces (OBJECT), which
#                                     every render links
#   vl_grader_oracle_map_NN           oracle/NN-name.json: for each piece, the objects of
#                                     the first that hold its code, which a render grading
#                                     it leaves out (grader/src/oracle_probe.cc derives
#                                     them from the compiled code: no table to keep)
# The map is made by vl_grader_oracle_probe_NN, the registration linked without the
# pieces, whose functions are traps that name themselves (cmake/grader_oracle_traps.cmake
# writes them).
function(vl_grader_oracle_library stage)
  string(SUBSTRING ${stage} 0 2 number)
  set(reference_dir ${PROJECT_SOURCE_DIR}/reference/${stage})
  file(GLOB sources CONFIGURE_DEPENDS ${reference_dir}/*.cc)
  file(GLOB headers CONFIGURE_DEPENDS ${reference_dir}/*.hh ${reference_dir}/*.h)
  vl_stage_registration(${stage} registration)
  if(EXISTS ${reference_dir}/register.cc)
    set(registration ${reference_dir}/register.cc)
    list(REMOVE_ITEM sources ${registration})
  endif()
  if(NOT registration)
    message(FATAL_ERROR "stage ${stage}: no assignments/${stage}/register.cc (nor reference/${stage}/register.cc): "
                        "the grader's render program needs the stage's registration apart from its pieces")
  endif()
  set(dir ${CMAKE_CURRENT_BINARY_DIR}/oracle)
  vl_generate_for_stages(${PROJECT_SOURCE_DIR}/grader/hidden/common/reference_pieces.cc.in
                         ${dir}/reference_pieces_${number}.cc STAGES ${stage})
  add_library(vl_grader_oracle_${number} OBJECT ${sources})
  add_library(vl_grader_oracle_registration_${number} OBJECT ${registration} ${dir}/reference_pieces_${number}.cc)
  vl_grader_contract_dirs(contracts)
  foreach(part IN ITEMS vl_grader_oracle_${number} vl_grader_oracle_registration_${number})
    target_compile_definitions(${part} PRIVATE stage${number}=reference_stage${number})
    target_include_directories(${part} BEFORE PUBLIC ${PROJECT_SOURCE_DIR}/assignments/${stage})
    target_include_directories(${part} PUBLIC ${contracts})
    target_link_libraries(${part} PUBLIC vl_framework PRIVATE vl_warnings)
  endforeach()

  set(traps ${dir}/probe_traps_${number}.cc)
  add_custom_command(OUTPUT ${traps}
    COMMAND ${CMAKE_COMMAND} -DNM=${CMAKE_NM} -DSTAGE=${stage}
            "-DREGISTRATION=$<TARGET_OBJECTS:vl_grader_oracle_registration_${number}>"
            "-DPIECES=$<TARGET_OBJECTS:vl_grader_oracle_${number}>" -DOUT=${traps}
            -P ${PROJECT_SOURCE_DIR}/cmake/grader_oracle_traps.cmake
    DEPENDS $<TARGET_OBJECTS:vl_grader_oracle_registration_${number}> $<TARGET_OBJECTS:vl_grader_oracle_${number}>
            ${PROJECT_SOURCE_DIR}/cmake/grader_oracle_traps.cmake
    COMMENT "Finding the functions stage ${stage}'s registration takes from its reference"
    VERBATIM)
  add_executable(vl_grader_oracle_probe_${number} ${PROJECT_SOURCE_DIR}/grader/src/oracle_probe.cc ${traps}
                 $<TARGET_OBJECTS:vl_grader_oracle_registration_${number}>)
  target_include_directories(vl_grader_oracle_probe_${number} PRIVATE ${PROJECT_SOURCE_DIR}/grader/src)
  target_link_libraries(vl_grader_oracle_probe_${number} PRIVATE vl_framework nlohmann_json::nlohmann_json vl_warnings)
  set(map ${dir}/${stage}.json)
  add_custom_command(OUTPUT ${map}
    COMMAND vl_grader_oracle_probe_${number} --stage ${stage} --reference ${reference_dir} --nm ${CMAKE_NM} --out ${map}
            --registration $<TARGET_OBJECTS:vl_grader_oracle_registration_${number}>
            --pieces $<TARGET_OBJECTS:vl_grader_oracle_${number}>
    DEPENDS vl_grader_oracle_probe_${number} $<TARGET_OBJECTS:vl_grader_oracle_${number}> ${sources} ${headers}
    COMMENT "Mapping stage ${stage}'s pieces to the reference's objects that hold them"
    COMMAND_EXPAND_LISTS VERBATIM)
  add_custom_target(vl_grader_oracle_map_${number} DEPENDS ${map})
endfunction()

# Renders `scene` with `renderer` into `png` at build time (the reference renders).
function(vl_grader_reference_render renderer scene png)
  add_custom_command(OUTPUT ${png}
    COMMAND ${CMAKE_COMMAND} -E make_directory ${CMAKE_CURRENT_BINARY_DIR}/reference-renders
    COMMAND $<TARGET_FILE:${renderer}> ${scene} -o ${png} --threads 1
    DEPENDS ${renderer} ${scene}
    COMMENT "Rendering the reference image of ${scene}"
    VERBATIM)
endfunction()
