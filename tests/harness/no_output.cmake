# Runs a command that must fail with EXPECT_EXIT and leave no OUT folder
# behind (bad input is found before anything is written):
#   cmake -DEXPECT_EXIT=2 -DOUT=dir -DCOMMAND=a;b;c -P no_output.cmake
file(REMOVE_RECURSE "${OUT}")
execute_process(COMMAND ${COMMAND} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT status STREQUAL "${EXPECT_EXIT}")
  message(FATAL_ERROR "exit status ${status}, expected ${EXPECT_EXIT}; output:\n${out}${err}")
endif()
if(EXISTS "${OUT}")
  message(FATAL_ERROR "${OUT} exists after a failed run; output:\n${out}${err}")
endif()
message(STATUS "exit ${status} and no ${OUT}; output:\n${out}${err}")
