#!/usr/bin/env bash
# The Windows DLLs for Abaqus (explicitU.dll, explicitU-D.dll, standardU.dll),
# cross-built with Debian's MinGW-w64 into build-mingw/abaqus/, and their
# tests run under Wine (tests/windows/CMakeLists.txt): exports and imports of
# each DLL, the Fortran callers of tests/abi calling the DLLs in both
# precisions with records compared line for line with the Linux build's
# (build/tests/abi: run after the normal build's tests, as tools/test.sh
# does), and the exit utilities.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install-deps.sh
jobs=$(nproc 2>/dev/null || echo 2)
linux_records=$PWD/build/tests/abi
for f in abi_records_single.txt abi_records_double.txt uinter_records.txt records_compare; do
  [ -s "$linux_records/$f" ] || { echo "windows.sh: $linux_records/$f missing: run the normal build's tests first" >&2; exit 1; }
done
launcher=()
command -v ccache > /dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
cmake -S . -B build-mingw -DCMAKE_TOOLCHAIN_FILE=cmake/mingw-w64.cmake -DCMAKE_BUILD_TYPE=Release \
  -DMJ_BUILD_TESTS=ON -DMJ_WARNINGS_AS_ERRORS=ON -DMJ_LINUX_RECORDS="$linux_records" "${launcher[@]}"
cmake --build build-mingw -j"$jobs"
ctest --test-dir build-mingw --output-on-failure --no-tests=error -j"$jobs"
