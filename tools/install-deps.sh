#!/usr/bin/env bash
# Installs the Debian packages the project needs, when any is missing.
# Extra packages a script needs may be named as arguments
# (tools/fuzz.sh: bash tools/install-deps.sh clang libclang-rt-14-dev).
set -euo pipefail
packages=(cmake g++ gfortran make libeigen3-dev catch2 libcli11-dev libtoml11-dev gnuplot-nox "$@")
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "installing: ${missing[*]}"
  SUDO=""
  [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq "${missing[@]}" > /dev/null
fi
