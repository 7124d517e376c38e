#!/usr/bin/env bash
# Installs the Debian packages the project needs, when any is missing.
# Extra packages a script needs may be named as arguments
# (tools/fuzz.sh: bash tools/install-deps.sh clang libclang-rt-14-dev).
set -euo pipefail
#
# The Windows cross build (tools/windows.sh) needs MinGW-w64's C++ and Fortran
# compilers (the win32 thread model: no winpthread DLL) and Wine to run its
# tests; these are installed without the packages they only recommend (Wine's
# desktop integration, fonts, the 32-bit Wine of another architecture).
packages=(cmake g++ gfortran make binutils libeigen3-dev catch2 libcli11-dev libtoml11-dev gnuplot-nox "$@")
windows_packages=(g++-mingw-w64-x86-64-win32 gfortran-mingw-w64-x86-64-win32 wine64)
missing_of() {
  for p in "$@"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || echo "$p"
  done
}
mapfile -t missing < <(missing_of "${packages[@]}")
mapfile -t missing_windows < <(missing_of "${windows_packages[@]}")
if [ $((${#missing[@]} + ${#missing_windows[@]})) -gt 0 ]; then
  echo "installing: ${missing[*]} ${missing_windows[*]}"
  SUDO=""
  [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update -qq
  if [ ${#missing[@]} -gt 0 ]; then
    DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq "${missing[@]}" > /dev/null
  fi
  if [ ${#missing_windows[@]} -gt 0 ]; then
    DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing_windows[@]}" > /dev/null
  fi
fi
