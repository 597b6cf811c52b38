# The oracle test of the reference's BVH against Embree 3 (label embree), included from the
# top level so that it is built wherever the framework's own tests are (also in the asan
# preset, which builds no benchmarks). It needs Embree (Debian's libembree-dev) and the
# reference's stages 02 and 03; without either it is left out.
find_package(embree 3 QUIET)
set(vl_embree_oracle_pieces ON)
foreach(library vl_stage_02 vl_stage_03)
  get_target_property(from_reference ${library} VL_FROM_REFERENCE)
  if(NOT from_reference)
    set(vl_embree_oracle_pieces OFF)
  endif()
endforeach()
if(embree_FOUND AND VL_BUILD_FRAMEWORK_TESTS AND vl_embree_oracle_pieces)
  vl_add_tests(embree_oracle_test LABEL embree LIBS vl_pieces embree SOURCES ${CMAKE_CURRENT_LIST_DIR}/embree_oracle_test.cc)
endif()
