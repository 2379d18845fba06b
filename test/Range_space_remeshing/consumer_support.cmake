# Shared by test_install.cmake and test_subdirectory.cmake, which configure and build
# a project outside the package's build:
#   step(WHAT COMMAND...)  runs COMMAND, fails with WHAT and its output unless it exits 0
#                          (its output stays in `out` and `err`)
#   consumer_options       the options of that configure: the build's CGAL_DIR (which
#                          the consumer must find rather than the system's CGAL) and
#                          ccache where there is one
macro(step what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "${what} failed (${code}):\n${out}\n${err}")
  endif()
endmacro()

set(consumer_options -DCMAKE_BUILD_TYPE=Release)
if(CGAL_DIR)
  list(APPEND consumer_options -DCGAL_DIR=${CGAL_DIR})
endif()
find_program(ccache ccache)
if(ccache)
  list(APPEND consumer_options -DCMAKE_CXX_COMPILER_LAUNCHER=${ccache})
endif()
