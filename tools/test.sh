#!/usr/bin/env bash
# Builds everything and runs the whole test suite (the README's test command):
#   1. the normal build (build/): every test;
#   2. AddressSanitizer + UndefinedBehaviorSanitizer (build-asan/): every test;
#   3. ThreadSanitizer (build-tsan/): the concurrency tests of the ABI adapters;
#   4. libFuzzer (build-fuzz/): vuinteraction_ for 60 s from the seed corpus.
# Stages 2-4 are tools/sanitize.sh and tools/fuzz.sh (docs/robustness.md);
# MJ_TEST_QUICK=1 runs stage 1 only (for a quick local check).
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install-deps.sh
jobs=$(nproc 2>/dev/null || echo 2)
summary=()
stage() {  # name command...
  local name=$1 start=$SECONDS
  shift
  echo "=== test.sh: $name"
  "$@"
  summary+=("$name: $((SECONDS - start)) s")
}
normal() {
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
  cmake --build build -j"$jobs"
  ctest --test-dir build --output-on-failure -j"$jobs"
}
stage "normal build and tests" normal
if [ "${MJ_TEST_QUICK:-0}" != 1 ]; then
  stage "ASan + UBSan build and tests" bash tools/sanitize.sh address
  stage "TSan build and concurrency tests" bash tools/sanitize.sh thread
  stage "fuzz vuinteraction_ for 60 s" bash tools/fuzz.sh 60
fi
printf 'test.sh: %s\n' "${summary[@]}"
echo "test.sh: ${#summary[@]} passed, 0 failed"
