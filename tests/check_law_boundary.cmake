# The law's boundary (docs/architecture.md): outside src/mortar/, a file may
# include of the law only the boundary's headers (src/include/mortar/) and
# the SDV module's (src/sdv/mortar/). The law's unit tests (tests/law/) are
# the one exception: they test its internals.
#   cmake -DROOT=<source tree> -P check_law_boundary.cmake
if(NOT ROOT)
  message(FATAL_ERROR "check_law_boundary: ROOT not set")
endif()
# The source folders only: build trees (fuzz corpora, install prefixes) are
# large and hold no source of ours.
set(candidates "")
foreach(folder src vuinteraction harness tests examples tools)
  file(GLOB_RECURSE found LIST_DIRECTORIES false RELATIVE ${ROOT}
       ${ROOT}/${folder}/*.cpp ${ROOT}/${folder}/*.hpp ${ROOT}/${folder}/*.h ${ROOT}/${folder}/*.cc)
  list(APPEND candidates ${found})
endforeach()
set(violations "")
set(scanned 0)
foreach(file ${candidates})
  if(file MATCHES "^(src/mortar/|tests/law/|build[^/]*/|\\.)")
    continue()
  endif()
  math(EXPR scanned "${scanned} + 1")
  file(STRINGS ${ROOT}/${file} lines REGEX "^[ \t]*#[ \t]*include[ \t]*[<\"]mortar/")
  foreach(line ${lines})
    string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]*[<\"](mortar/[^>\"]*)[>\"].*" "\\1" header "${line}")
    if(NOT EXISTS ${ROOT}/src/include/${header} AND NOT EXISTS ${ROOT}/src/sdv/${header})
      list(APPEND violations "${file}: ${header}")
    endif()
  endforeach()
endforeach()
if(scanned EQUAL 0)
  message(FATAL_ERROR "check_law_boundary: no source file found under ${ROOT}")
endif()
if(violations)
  list(JOIN violations "\n  " text)
  message(FATAL_ERROR "files outside src/mortar/ include the law's internals:\n  ${text}")
endif()
message(STATUS "check_law_boundary: ${scanned} files include only the law's boundary")
