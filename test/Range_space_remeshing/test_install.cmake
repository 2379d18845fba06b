# Installs the package from the build tree into a scratch prefix, then configures,
# builds and runs a program outside the tree against it with find_package:
#   cmake -DBUILD_DIR=... -DCONSUMER_DIR=... -DWORK_DIR=... -DVERSION=... [-DCGAL_DIR=...]
#         [-DPROGRAM=range_space_remesh] -P test_install.cmake
# CGAL_DIR: the CGAL the package was built against (scripts/test_cgal6.sh's CGAL 6),
# which the consumer's find_dependency(CGAL) must find rather than the system's.
# VERSION: project()'s; the consumer asks for its MAJOR.MINOR (find_package(... 1.0)),
# and asking for the next major version must fail.
# PROGRAM: the command-line program, which the build has and must install in bin/.
cmake_minimum_required(VERSION 3.19)
file(REMOVE_RECURSE ${WORK_DIR})

include(${CMAKE_CURRENT_LIST_DIR}/consumer_support.cmake)

set(prefix ${WORK_DIR}/prefix)
step("installing" ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})
foreach(expected include/CGAL/Range_space_remeshing/remesh.h
                 include/CGAL/Range_space_remeshing/internal/Grid_tracer.h)
  if(NOT EXISTS ${prefix}/${expected})
    message(FATAL_ERROR "not installed: ${expected}")
  endif()
endforeach()
if(PROGRAM)
  set(program ${prefix}/bin/${PROGRAM})
  if(NOT EXISTS ${program})
    message(FATAL_ERROR "not installed: bin/${PROGRAM}")
  endif()
  step("running the installed program" ${program} --version)
  if(NOT out MATCHES "^${PROGRAM} ${VERSION} \\(CGAL ")
    message(FATAL_ERROR "bin/${PROGRAM} --version printed: ${out}")
  endif()
  message(STATUS "installed: ${out}")
endif()
file(GLOB_RECURSE config ${prefix}/*/Range_space_remeshingConfig.cmake)
if(NOT config)
  message(FATAL_ERROR "no Range_space_remeshingConfig.cmake under ${prefix}")
endif()

string(REGEX MATCH "^[0-9]+\\.[0-9]+" requested ${VERSION})
step("configuring the consumer" ${CMAKE_COMMAND} -S ${CONSUMER_DIR} -B ${WORK_DIR}/build
     -DCMAKE_PREFIX_PATH=${prefix} -DRSR_REQUESTED_VERSION=${requested} ${consumer_options})
step("building the consumer" ${CMAKE_COMMAND} --build ${WORK_DIR}/build)
step("running the consumer" ${WORK_DIR}/build/consumer)
message(STATUS "${out}")

# the next major version is not this one (ConfigVersion: SameMajorVersion)
string(REGEX MATCH "^[0-9]+" major ${VERSION})
math(EXPR next_major "${major} + 1")
execute_process(COMMAND ${CMAKE_COMMAND} -S ${CONSUMER_DIR} -B ${WORK_DIR}/build_next_major
                        -DCMAKE_PREFIX_PATH=${prefix} -DRSR_REQUESTED_VERSION=${next_major}.0
                        ${consumer_options}
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(code EQUAL 0 OR NOT err MATCHES "Range_space_remeshingConfig\\.cmake, version: ${VERSION}")
  message(FATAL_ERROR "find_package(Range_space_remeshing ${next_major}.0) did not refuse version ${VERSION} "
                      "(${code}):\n${out}\n${err}")
endif()
message(STATUS "find_package(Range_space_remeshing ${next_major}.0) refused ${VERSION}, as it should")
