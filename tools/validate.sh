#!/usr/bin/env bash
# Builds the command line and runs the main job: the validation of the three test
# series (the README's main command). Output goes to out/validation/.
#
# Shares build/ with tools/test.sh and leaves its configuration alone (the
# test suite stays configured), so the two commands work in either order;
# only the command line is built here.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install-deps.sh
jobs=$(nproc 2>/dev/null || echo 2)
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$jobs" --target masonry-joint
./build/harness/masonry-joint validate --out out/validation
