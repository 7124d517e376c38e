# Runs a command and checks its exit status and output (stdout + stderr):
#   cmake -DEXPECT_EXIT=2 "-DEXPECT_OUTPUT=regex" -DCOMMAND=a;b;c -P expect.cmake
# CTest's PASS_REGULAR_EXPRESSION alone ignores the exit status, and a bad
# input must both fail and say why.
execute_process(COMMAND ${COMMAND}
  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
set(all "${out}${err}")
if(NOT status STREQUAL "${EXPECT_EXIT}")
  message(FATAL_ERROR "exit status ${status}, expected ${EXPECT_EXIT}; output:\n${all}")
endif()
if(DEFINED EXPECT_OUTPUT AND NOT all MATCHES "${EXPECT_OUTPUT}")
  message(FATAL_ERROR "output does not match '${EXPECT_OUTPUT}':\n${all}")
endif()
message(STATUS "exit ${status} as expected; output:\n${all}")
