# Fails unless FILE exists and its text matches the regular expression
# EXPECT_OUTPUT: for what a command writes into a file (a chart's script).
#   cmake -DFILE=path "-DEXPECT_OUTPUT=regex" -P file_matches.cmake
if(NOT EXISTS "${FILE}")
  message(FATAL_ERROR "${FILE}: no such file")
endif()
file(READ "${FILE}" text)
if(NOT text MATCHES "${EXPECT_OUTPUT}")
  message(FATAL_ERROR "${FILE} does not match '${EXPECT_OUTPUT}':\n${text}")
endif()
message(STATUS "${FILE} matches '${EXPECT_OUTPUT}'")
