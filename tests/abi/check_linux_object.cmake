# Checks a relocatable object for Abaqus's `user=` (run as: cmake
# -DOBJECT=<o> -DNM=<nm> "-DENTRIES=vuinteraction_;vuinter_" -P
# check_linux_object.cmake):
#   - it defines its entry points;
#   - no symbol asks for a GLIBC_ version above 2.28 (an object binds to the
#     C library of the machine that links it, unless a .symver names one);
#   - it leaves no C++ runtime symbol undefined (it carries its own), and
#     defines no global symbol but its entry points (the runtime it carries
#     is local to it; GNU-unique ones the dynamic linker shares by design).
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
foreach(u ${cxx})
  list(APPEND failures "leaves the C++ runtime symbol${u} for the linking side")
endforeach()
string(REGEX MATCHALL "[0-9a-f]+ [A-TV-Z] [^\n]+" globals "${symbols}")
foreach(g ${globals})
  string(REGEX REPLACE "^[0-9a-f]+ . " "" name "${g}")
  if(NOT name IN_LIST ENTRIES)
    list(APPEND failures "defines the global symbol ${name}")
  endif()
endforeach()
list(LENGTH versions nversions)
message(STATUS "${OBJECT}: ${nversions} versioned references, no C++ runtime symbol left undefined")
if(failures)
  list(JOIN failures "\n  " text)
  message(FATAL_ERROR "${OBJECT}:\n  ${text}")
endif()
