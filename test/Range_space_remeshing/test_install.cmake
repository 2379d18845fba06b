# Installs the package from the build tree into a scratch prefix, then configures,
# builds and runs a program outside the tree against it with find_package:
#   cmake -DBUILD_DIR=... -DCONSUMER_DIR=... -DWORK_DIR=... [-DCGAL_DIR=...] -P test_install.cmake
# CGAL_DIR: the CGAL the package was built against (scripts/test_cgal6.sh's CGAL 6),
# which the consumer's find_dependency(CGAL) must find rather than the system's.
cmake_minimum_required(VERSION 3.19)
file(REMOVE_RECURSE ${WORK_DIR})

macro(step what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "${what} failed (${code}):\n${out}\n${err}")
  endif()
endmacro()

set(prefix ${WORK_DIR}/prefix)
step("installing" ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})
foreach(expected include/CGAL/Range_space_remeshing/remesh.h
                 include/CGAL/Range_space_remeshing/internal/Grid_tracer.h)
  if(NOT EXISTS ${prefix}/${expected})
    message(FATAL_ERROR "not installed: ${expected}")
  endif()
endforeach()
file(GLOB_RECURSE config ${prefix}/*/Range_space_remeshingConfig.cmake)
if(NOT config)
  message(FATAL_ERROR "no Range_space_remeshingConfig.cmake under ${prefix}")
endif()

set(cgal "")
if(CGAL_DIR)
  set(cgal -DCGAL_DIR=${CGAL_DIR})
endif()
set(launcher "")
find_program(ccache ccache)
if(ccache)
  set(launcher -DCMAKE_CXX_COMPILER_LAUNCHER=${ccache})
endif()
step("configuring the consumer" ${CMAKE_COMMAND} -S ${CONSUMER_DIR} -B ${WORK_DIR}/build
     -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH=${prefix} ${cgal} ${launcher})
step("building the consumer" ${CMAKE_COMMAND} --build ${WORK_DIR}/build)
step("running the consumer" ${WORK_DIR}/build/consumer)
message(STATUS "${out}")
