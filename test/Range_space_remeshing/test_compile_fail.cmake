# Builds TARGET in BUILD_DIR, which must fail with MESSAGE in the first error, and
# CONTROL, the same source with RSR_CONTROL defined, which must build: the failure is
# then the package's refusal, not a broken test.
#   cmake -DBUILD_DIR=... -DTARGET=... -DCONTROL=... -DMESSAGE=... [-DMAXIMUM_ERRORS=n] -P test_compile_fail.cmake
execute_process(COMMAND ${CMAKE_COMMAND} --build ${BUILD_DIR} --target ${CONTROL}
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "the control ${CONTROL} does not build:\n${out}\n${err}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${BUILD_DIR} --target ${TARGET}
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(code EQUAL 0)
  message(FATAL_ERROR "${TARGET} builds: it must be refused")
endif()
string(REGEX MATCHALL "error: [^\n]*" errors "${out}\n${err}")
list(LENGTH errors number_of_errors)
list(GET errors 0 first)
if(NOT first MATCHES "${MESSAGE}")
  message(FATAL_ERROR "${TARGET}: the first error is not the package's refusal '${MESSAGE}':\n${first}")
endif()
if(MAXIMUM_ERRORS AND number_of_errors GREATER MAXIMUM_ERRORS)
  message(FATAL_ERROR "${TARGET}: ${number_of_errors} errors, at most ${MAXIMUM_ERRORS} expected:\n${errors}")
endif()
message(STATUS "${TARGET}: refused with '${first}' (${number_of_errors} error lines)")
