# Checks a relocatable object for Abaqus's `user=` (run as: cmake
# -DOBJECT=<o> -DNM=<nm> "-DENTRIES=vuinteraction_;vuinter_" -P
# check_linux_object.cmake):
#   - it defines its entry points;
#   - no symbol asks for a GLIBC_ version above 2.28 (an object binds to the
#     C library of the machine that links it, unless a .symver names one);
#   - the C++ runtime symbols it leaves undefined are listed: the linking
#     side provides them (docs/abaqus.md, "Which Linux").
cmake_policy(VERSION 3.25)
execute_process(COMMAND ${NM} ${OBJECT} OUTPUT_VARIABLE symbols RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "nm failed on ${OBJECT}")
endif()
set(failures "")
foreach(entry ${ENTRIES})
  if(NOT symbols MATCHES " T ${entry}\n")
    list(APPEND failures "does not define ${entry}")
  endif()
endforeach()
string(REGEX MATCHALL "@+GLIBC_[0-9.]+" versions "${symbols}")
foreach(v ${versions})
  string(REGEX MATCH "GLIBC_([0-9.]+)" _ "${v}")
  if(CMAKE_MATCH_1 VERSION_GREATER "2.28")
    list(APPEND failures "asks for GLIBC_${CMAKE_MATCH_1}")
  endif()
endforeach()
string(REGEX MATCHALL " U (_Z|__cxa_|__gxx_)[^\n]+" cxx "${symbols}")
list(LENGTH versions nversions)
list(LENGTH cxx ncxx)
message(STATUS "${OBJECT}: ${nversions} versioned references; ${ncxx} C++ runtime symbols for the linking side")
if(failures)
  list(JOIN failures "\n  " text)
  message(FATAL_ERROR "${OBJECT}:\n  ${text}")
endif()
