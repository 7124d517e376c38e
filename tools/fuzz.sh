#!/usr/bin/env bash
# Fuzzes the VUINTERACTION entry point vuinteraction_ with libFuzzer (Clang),
# built with AddressSanitizer + UndefinedBehaviorSanitizer, starting from the
# committed seed corpus tests/fuzz/corpus (docs/robustness.md). First it
# replays that corpus, every input once, in both precisions.
#
#   bash tools/fuzz.sh                 60 s on the double-precision routine (CI)
#   bash tools/fuzz.sh 3600            one hour
#   bash tools/fuzz.sh 3600 single     the single-precision routine
#
# Build directory build-fuzz/. New inputs the fuzzer finds go to
# build-fuzz/corpus-<precision>/ (the committed seeds are only read); a
# failing input is written to build-fuzz/artifacts/ and the script exits
# non-zero. Reproduce one with:
#   build-fuzz/tests/fuzz/fuzz_vuinteraction_double build-fuzz/artifacts/crash-...
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
precision=${2:-double}
build=build-fuzz

# libFuzzer is in Debian's compiler-rt package (bookworm: clang 14).
bash tools/install-deps.sh clang libclang-rt-14-dev
jobs=$(nproc 2>/dev/null || echo 2)

# -O2 -g1 (line tables for the reports) and no NDEBUG: assertions (Eigen's included) stay on.
# -O2 rather than -O1: Eigen's small expressions inlined, 1.3 times the executions
# per second with the same instrumentation (docs/robustness.md).
mkdir -p "$build"
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -g1" \
  -DCMAKE_CXX_COMPILER=clang++ -DMJ_FUZZ=ON -DMJ_SANITIZE=address,undefined -DMJ_WARNINGS_AS_ERRORS=ON > "$build/configure.log" 2>&1 \
  || { cat "$build/configure.log"; exit 1; }
cmake --build "$build" -j"$jobs" --target fuzz_vuinteraction_double fuzz_vuinteraction_single

mkdir -p "$build/artifacts"
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1:detect_stack_use_after_return=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
common=(-max_len=4096 -timeout=60 -rss_limit_mb=4096 -artifact_prefix="$build/artifacts/")

# The committed seed corpus, every input once, in both precisions: the
# sanitized replay of the corpus (the sanitizer builds do not build their own).
corpus=(tests/fuzz/corpus/*)
for p in double single; do
  replay_log="$build/replay-$p.log"
  "$build/tests/fuzz/fuzz_vuinteraction_$p" "${common[@]}" "${corpus[@]}" > "$replay_log" 2>&1 \
    || { echo "fuzz: seed corpus replay FAILED ($p); full log: $replay_log"; tail -n 60 "$replay_log"; exit 1; }
  executed=$(grep -c "^Executed " "$replay_log" || true)
  if [ "$executed" -ne "${#corpus[@]}" ]; then
    echo "fuzz: seed corpus replay ($p) executed $executed of ${#corpus[@]} inputs; full log: $replay_log"
    exit 1
  fi
  echo "fuzz: seed corpus replay ($p): ${#corpus[@]} inputs, every property holds"
done

target="$build/tests/fuzz/fuzz_vuinteraction_$precision"
work="$build/corpus-$precision"
mkdir -p "$work"
# Inputs scheduled by their execution time too (up to 30 x more often for the
# fast ones): the slow ones run the law to its substep budgets, and they took
# most of a long run without adding coverage (docs/robustness.md).
flags=(-max_total_time="$seconds" -print_final_stats=1 -entropic_scale_per_exec_time=1 "${common[@]}")
log="$build/fuzz-$precision.log"
echo "fuzz: $target for $seconds s, corpus $work + tests/fuzz/corpus; log $log"
"$target" "${flags[@]}" "$work" tests/fuzz/corpus > "$log" 2>&1 || status=$?
status=${status:-0}
# Summary: libFuzzer's final statistics and the target's own counts.
grep -E "^(stat::|fuzz_vuinteraction:|Done [0-9]+ runs|==[0-9]+==ERROR|SUMMARY)|PROPERTY VIOLATED|runtime error" "$log" \
  | grep -v "^stat::(peak_rss|slowest)" || true
if [ "$status" -ne 0 ]; then
  echo "fuzz: FAILED (exit $status); the failing input is in $build/artifacts/; full log: $log"
  tail -n 60 "$log"
  exit 1
fi
executions=$(grep -Eo '^stat::number_of_executed_units: [0-9]+' "$log" | awk '{s+=$2} END {print s+0}')
if [ "$executions" -eq 0 ]; then  # a run that executed nothing has checked nothing
  echo "fuzz: FAILED: no input was executed; full log: $log"
  exit 1
fi
echo "fuzz: passed, $executions executions in $seconds s"
