#!/usr/bin/env bash
# Builds everything and runs the main job: the validation of the three test
# series (the README's main command). Output goes to out/validation/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install-deps.sh
jobs=$(nproc 2>/dev/null || echo 2)
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DMJ_BUILD_TESTS=OFF
cmake --build build -j"$jobs" --target masonry-joint
./build/harness/masonry-joint validate --out out/validation
