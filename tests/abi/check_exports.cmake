# Checks that a shared library exports exactly its Abaqus entry points
# (run as: cmake -DLIBRARY=<lib> -DNM=<nm> "-DENTRIES=vuinteraction_;vuinter_"
# -P check_exports.cmake).
execute_process(COMMAND ${NM} -D --defined-only ${LIBRARY}
                OUTPUT_VARIABLE symbols RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "nm -D failed on ${LIBRARY}")
endif()
message(STATUS "nm -D --defined-only ${LIBRARY}:\n${symbols}")
foreach(entry ${ENTRIES})
  if(NOT symbols MATCHES " T ${entry}\n")
    message(FATAL_ERROR "${LIBRARY} does not export ${entry}")
  endif()
endforeach()
string(REGEX MATCHALL " [TDBRVWi] [^\n]+" exported "${symbols}")
list(LENGTH exported count)
list(LENGTH ENTRIES expected)
if(NOT count EQUAL expected)
  message(FATAL_ERROR "${LIBRARY} exports ${count} symbols, expected only the entry points ${ENTRIES}")
endif()
