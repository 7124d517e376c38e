# Cross toolchain for the Windows DLLs (tools/windows.sh): Debian's MinGW-w64
# (packages g++-mingw-w64-x86-64-win32, gfortran-mingw-w64-x86-64-win32).
# Test programs run under Wine (package wine64).
set(CMAKE_SYSTEM_NAME Windows)
set(CMAKE_SYSTEM_PROCESSOR x86_64)
set(CMAKE_CXX_COMPILER x86_64-w64-mingw32-g++)
set(CMAKE_Fortran_COMPILER x86_64-w64-mingw32-gfortran)
set(CMAKE_RC_COMPILER x86_64-w64-mingw32-windres)
set(CMAKE_FIND_ROOT_PATH /usr/x86_64-w64-mingw32)
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
# Eigen is headers only: the host's package serves.
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE BOTH)
find_program(MJ_WINE NAMES wine64 wine PATHS /usr/lib/wine NO_CMAKE_FIND_ROOT_PATH)
if(MJ_WINE)
  set(CMAKE_CROSSCOMPILING_EMULATOR ${MJ_WINE})
endif()
