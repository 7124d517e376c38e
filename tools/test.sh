#!/usr/bin/env bash
# Builds everything and runs the whole test suite (the README's test command):
#   1. the normal build (build/): every test;
#   2. AddressSanitizer + UndefinedBehaviorSanitizer (build-asan/): every test
#      of the law and the ABI adapters (tools/sanitize.sh address-all: all);
#   3. ThreadSanitizer (build-tsan/): the concurrency tests of the ABI adapters;
#   4. libFuzzer (build-fuzz/): vuinteraction_ for 60 s from the seed corpus;
#   5. Windows (build-mingw/): the DLLs cross-built with MinGW-w64, their
#      exports and imports, and the Fortran callers under Wine against the
#      normal build's records (tools/windows.sh, docs/abaqus.md "Windows").
# Stages 2-4 are tools/sanitize.sh and tools/fuzz.sh (docs/robustness.md);
# MJ_TEST_QUICK=1 runs stage 1 only (for a quick local check).
#
# Works before or after tools/validate.sh, which shares build/: the test
# suite is switched on here explicitly. A stage that runs no test fails
# (ctest --no-tests=error, Catch2 -w NoTests, a fuzz run without executions).
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install-deps.sh
jobs=$(nproc 2>/dev/null || echo 2)
logs=build-logs
mkdir -p "$logs"
summary=()
stage() {  # name log command...: runs the stage, its output also to the log
  local name=$1 log=$logs/$2 start=$SECONDS
  shift 2
  echo "=== test.sh: $name"
  "$@" 2>&1 | tee "$log"
  # The runner's closing line (ctest, Catch2, libFuzzer), kept for the summary.
  local closing
  closing=$(grep -E "tests passed|test cases|^fuzz: passed" "$log" | tail -n 1 || true)
  summary+=("$name: $((SECONDS - start)) s${closing:+ ($closing)}")
}
normal() {
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DMJ_BUILD_TESTS=ON -DMJ_WARNINGS_AS_ERRORS=ON
  cmake --build build -j"$jobs"
  ctest --test-dir build --output-on-failure --no-tests=error -j"$jobs"
}
stage "normal build and tests" normal.log normal
if [ "${MJ_TEST_QUICK:-0}" != 1 ]; then
  stage "ASan + UBSan build and tests (law, adapters)" asan.log bash tools/sanitize.sh address
  stage "TSan build and concurrency tests" tsan.log bash tools/sanitize.sh thread
  stage "fuzz vuinteraction_ for 60 s" fuzz.log bash tools/fuzz.sh 60
  stage "Windows DLLs (MinGW-w64) and Fortran callers under Wine" windows.log bash tools/windows.sh
fi
printf 'test.sh: %s\n' "${summary[@]}"
echo "test.sh: all stages: $SECONDS s"
echo "test.sh: ${#summary[@]} passed, 0 failed"
# Last, the runner's closing summary of the full suite (the normal build's
# ctest line, which CI reads).
grep -E "tests passed, [0-9]+ tests failed out of [0-9]+" "$logs/normal.log" | tail -n 1
