# Configures a parent project that adds the package with add_subdirectory, checks that
# the package added no test (ctest -N) and none of its test, example or benchmark
# targets, then builds and runs the parent's program:
#   cmake -DSOURCE_DIR=... -DPARENT_DIR=... -DWORK_DIR=... [-DCGAL_DIR=...] -P test_subdirectory.cmake
cmake_minimum_required(VERSION 3.19)
file(REMOVE_RECURSE ${WORK_DIR})

include(${CMAKE_CURRENT_LIST_DIR}/consumer_support.cmake)

set(build ${WORK_DIR}/build)
step("configuring the parent" ${CMAKE_COMMAND} -S ${PARENT_DIR} -B ${build} -G "Unix Makefiles"
     -DRSR_SOURCE_DIR=${SOURCE_DIR} ${consumer_options})

step("listing the parent's tests" ${CMAKE_COMMAND} -E chdir ${build} ${CMAKE_CTEST_COMMAND} -N)
if(NOT out MATCHES "Total Tests: 0")
  message(FATAL_ERROR "the package added tests to its parent project:\n${out}")
endif()
step("listing the parent's targets" ${CMAKE_COMMAND} --build ${build} --target help)
foreach(target test_headers_compile test_dual rsr_test_programs fuzz_remesh_replay range_space_remesh
               primal_remesh_example contour_benchmark table1)
  if(out MATCHES "\\.\\.\\. ${target}\n")
    message(FATAL_ERROR "the package added the target ${target} to its parent project")
  endif()
endforeach()
if(NOT out MATCHES "\\.\\.\\. parent\n")
  message(FATAL_ERROR "no target 'parent' in:\n${out}")
endif()

step("building the parent" ${CMAKE_COMMAND} --build ${build} --target parent)
step("running the parent" ${build}/parent)
message(STATUS "${out}")
