# The check that version.h and project() agree (cmake/Range_space_remeshing_version.cmake,
# called by the top-level CMakeLists.txt) reads the header's version, and sees headers
# that disagree with it or with themselves:
#   cmake -DMODULE=... -DHEADER=... -DVERSION=<project()'s> -DWORK_DIR=... -P test_version.cmake
cmake_minimum_required(VERSION 3.19)
include(${MODULE})
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})

range_space_remeshing_header_version(${HEADER} version)
if(NOT version STREQUAL VERSION)
  message(FATAL_ERROR "version.h reads as '${version}', project() says ${VERSION}")
endif()
message(STATUS "version.h: ${version}")

# copies of the header with one thing changed must not read as project()'s version
file(READ ${HEADER} text)
string(REPLACE "." ";" parts ${VERSION})
list(GET parts 2 patch)
math(EXPR next_patch "${patch} + 1")
set(cases
    "_PATCH ${patch}\n=_PATCH ${next_patch}\n"         # a number changed, not the string
    "_STR \"${VERSION}\"=_STR \"${VERSION}.1\""        # the string changed, not the numbers
    "_STR \"${VERSION}\"=_STR \"v${VERSION}\""
    "#define RANGE_SPACE_REMESHING_VERSION_MINOR=#define OTHER_MINOR") # a macro missing
set(number 0)
foreach(case IN LISTS cases)
  string(FIND "${case}" "=" at)
  string(SUBSTRING "${case}" 0 ${at} from)
  math(EXPR at "${at} + 1")
  string(SUBSTRING "${case}" ${at} -1 to)
  string(FIND "${text}" "${from}" found)
  if(found EQUAL -1)
    message(FATAL_ERROR "'${from}' is not in ${HEADER}: update this test")
  endif()
  string(REPLACE "${from}" "${to}" changed "${text}")
  math(EXPR number "${number} + 1")
  file(WRITE ${WORK_DIR}/version_${number}.h "${changed}")
  range_space_remeshing_header_version(${WORK_DIR}/version_${number}.h changed_version)
  if(changed_version STREQUAL VERSION)
    message(FATAL_ERROR "'${from}' -> '${to}' still reads as ${VERSION}")
  endif()
  message(STATUS "'${from}' -> '${to}': ${changed_version}")
endforeach()
