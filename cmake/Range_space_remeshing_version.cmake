# The package's version as include/CGAL/Range_space_remeshing/version.h says it:
#   range_space_remeshing_header_version(HEADER OUT_VAR)
# sets OUT_VAR to "MAJOR.MINOR.PATCH" from the header's macros, or to a message that
# says what is wrong (a macro missing, or the string macro disagreeing with the
# numbers). CMakeLists.txt compares it with project()'s version;
# test/Range_space_remeshing/test_version.cmake checks that a disagreement is seen.
function(range_space_remeshing_header_version header out_var)
  file(STRINGS ${header} lines REGEX "^#define RANGE_SPACE_REMESHING_VERSION_(MAJOR|MINOR|PATCH|STR) ")
  set(numbers "")
  foreach(part MAJOR MINOR PATCH)
    if(NOT lines MATCHES "RANGE_SPACE_REMESHING_VERSION_${part} +([0-9]+)")
      set(${out_var} "no RANGE_SPACE_REMESHING_VERSION_${part} in ${header}" PARENT_SCOPE)
      return()
    endif()
    list(APPEND numbers ${CMAKE_MATCH_1})
  endforeach()
  list(JOIN numbers "." version)
  if(NOT lines MATCHES "RANGE_SPACE_REMESHING_VERSION_STR +\"([^\"]*)\"")
    set(${out_var} "no RANGE_SPACE_REMESHING_VERSION_STR in ${header}" PARENT_SCOPE)
  elseif(NOT CMAKE_MATCH_1 STREQUAL version)
    set(${out_var} "RANGE_SPACE_REMESHING_VERSION_STR \"${CMAKE_MATCH_1}\" is not ${version} in ${header}"
        PARENT_SCOPE)
  else()
    set(${out_var} ${version} PARENT_SCOPE)
  endif()
endfunction()
