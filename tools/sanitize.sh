#!/usr/bin/env bash
# The test suite under sanitizers (docs/robustness.md).
#
#   bash tools/sanitize.sh address       AddressSanitizer + UndefinedBehaviorSanitizer:
#                                        the law, the ABI adapters and every test of
#                                        theirs: law, abi, property (build-asan/; CI)
#   bash tools/sanitize.sh address-all   the same over every test of the suite, the
#                                        harness and the command line included
#                                        (build-asan-all/; about twice the time)
#   bash tools/sanitize.sh thread        ThreadSanitizer: the concurrency tests of the
#                                        ABI adapters, both precisions (build-tsan/; CI)
#   bash tools/sanitize.sh               address and thread (CI's two stages)
#
# CI's address stage leaves the harness out: the sanitizers must see the code
# that runs inside the user's Abaqus analysis, and its tests, on every change;
# the harness (mock solvers, files, command line, calibration, scenes) runs
# outside it and doubled the stage's time (docs/robustness.md).
#
# Built with GCC at -O2 -g1 (line tables: reports name file and line; full
# debug information would cost compile time, not report quality) without
# NDEBUG (assertions, Eigen's included, stay on), libstdc++ assertions in the
# ASan build, and -fno-sanitize-recover=all: any report fails the test that
# triggered it. A run that matches no test fails (ctest --no-tests=error,
# Catch2 -w NoTests).
set -euo pipefail
cd "$(dirname "$0")/.."
what=${1:-all}
case "$what" in
  all | address | address-all | thread) ;;
  *) echo "sanitize.sh: unknown stage '$what' (address, address-all, thread or none for address and thread)"; exit 2 ;;
esac
bash tools/install-deps.sh
jobs=$(nproc 2>/dev/null || echo 2)

configure() {  # build-dir sanitizers [cmake options...]
  mkdir -p "$1"
  cmake -S . -B "$1" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -g1" \
    -DCMAKE_Fortran_FLAGS_RELWITHDEBINFO="-O2 -g1" -DMJ_SANITIZE="$2" -DMJ_BUILD_TESTS=ON -DMJ_WARNINGS_AS_ERRORS=ON "${@:3}" > "$1/configure.log" 2>&1 \
    || { cat "$1/configure.log"; exit 1; }
}

address() {  # build-dir [cmake options...]
  configure "$1" address,undefined "${@:2}"
  cmake --build "$1" -j"$jobs"
  export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1:detect_stack_use_after_return=1:check_initialization_order=1:strict_init_order=1}
  export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
  # The property tests at a tenth of their parameter sets (tests/property/abi_block.hpp).
  export MJ_PROPERTY_SCALE=${MJ_PROPERTY_SCALE:-0.1}
  # Every test of the build; the longest (ctest COST) start first.
  ctest --test-dir "$1" --output-on-failure --no-tests=error -j"$jobs"
}

if [ "$what" = all ] || [ "$what" = address ]; then
  address build-asan -DMJ_BUILD_HARNESS=OFF
fi
if [ "$what" = address-all ]; then
  address build-asan-all -DMJ_BUILD_HARNESS=ON
fi

if [ "$what" = all ] || [ "$what" = thread ]; then
  configure build-tsan thread
  cmake --build build-tsan -j"$jobs" --target abi_tests_double abi_tests_single
  export TSAN_OPTIONS=${TSAN_OPTIONS:-halt_on_error=1:second_deadlock_stack=1}
  for precision in double single; do
    # Every test tagged [threads] ("concurrent calls on disjoint blocks give the
    # single-thread results"); -w NoTests fails if the tag matches nothing.
    echo "tsan: abi_tests_$precision [threads]"
    build-tsan/tests/abi/abi_tests_$precision "[threads]" -w NoTests
  done
fi
