# Sanitizer and fuzzing builds (docs/robustness.md). Included by the top-level
# CMakeLists.txt before any target is defined, so the flags reach every
# target: the law, the adapters, the harness and all tests.
#
#   -DMJ_SANITIZE=address,undefined   AddressSanitizer + UndefinedBehaviorSanitizer
#                                     (any report aborts: -fno-sanitize-recover=all)
#   -DMJ_SANITIZE=thread              ThreadSanitizer
#   -DMJ_FUZZ=ON                      libFuzzer coverage instrumentation (Clang only);
#                                     tests/fuzz then builds the fuzz target
#
# tools/sanitize.sh and tools/fuzz.sh configure their own build directories
# with these options; a plain build is unaffected.
set(MJ_SANITIZE "" CACHE STRING "Sanitizers to build with: empty, address,undefined or thread")
option(MJ_FUZZ "Build the libFuzzer target of vuinteraction_ (needs Clang)" OFF)

# Flags for C++ always; for Fortran only when gfortran and the C++ compiler
# share one sanitizer runtime (GCC), so that the Fortran ABI test runs
# sanitized too.
set(mj_san_languages CXX)
if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
  set(mj_san_languages CXX,Fortran)
endif()

if(MJ_SANITIZE)
  set(mj_san_flags -fsanitize=${MJ_SANITIZE} -fno-omit-frame-pointer)
  # Line tables at least, so that every report names file and line. Put
  # before the build type's flags, so that a build type with full debug
  # information (-g, later on the command line) keeps it; -g1 is what
  # tools/sanitize.sh asks for (full debug information costs compile time).
  # The Fortran test callers take theirs from the build type's flags.
  string(PREPEND CMAKE_CXX_FLAGS "-g1 ")
  if(MJ_SANITIZE MATCHES "undefined")
    # A UBSan report must fail the test, not scroll past. GCC leaves
    # float-cast-overflow (a double that does not fit the int it is converted
    # to: e.g. a garbage state slot read as a count) out of "undefined".
    list(APPEND mj_san_flags -fno-sanitize-recover=all -fsanitize=float-cast-overflow)
    if(MJ_SANITIZE MATCHES "address")
      # With ASan, which checks every load and store against the bytes of
      # live objects, UBSan's per-access null, object-size and
      # pointer-overflow checks repeat it (a bad pointer is reported where it
      # is used), and the alignment check guards casts between pointer types,
      # which the law and the adapters do not make (they copy bytes with
      # memcpy). Together they cost a sixth of the law's run time under ASan
      # (docs/robustness.md, Sanitizer builds).
      list(APPEND mj_san_flags -fno-sanitize=null,alignment,object-size,pointer-overflow)
    endif()
  endif()
  if(MJ_SANITIZE MATCHES "address")
    # Bounds-checked std::vector::operator[] and friends as well.
    add_compile_definitions(_GLIBCXX_ASSERTIONS)
  endif()
  add_compile_options("$<$<COMPILE_LANGUAGE:${mj_san_languages}>:${mj_san_flags}>")
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    # GCC 12's instrumentation makes -Wmaybe-uninitialized fire inside
    # libstdc++ (std::function in <regex>, used by Catch2): false positives
    # that -Werror would turn into a failed build. The plain build keeps it.
    add_compile_options("$<$<COMPILE_LANGUAGE:CXX>:-Wno-maybe-uninitialized>")
  endif()
  add_link_options(${mj_san_flags})
  message(STATUS "MJ_SANITIZE=${MJ_SANITIZE}: ${mj_san_flags}")
endif()

if(MJ_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "MJ_FUZZ=ON needs Clang (libFuzzer): configure with -DCMAKE_CXX_COMPILER=clang++")
  endif()
  # Coverage feedback from the law and the adapters, not only from the target.
  # Without libFuzzer's comparison tracing (trace-cmp), which fuzzer-no-link
  # adds to every integer comparison: most of them are Eigen's index
  # assertions on every coefficient access, and their callbacks took 58 % of
  # the fuzz run's time (perf; docs/robustness.md). Edge coverage, the
  # sanitizers and the target's checks are unchanged; the input reaches the
  # law as doubles, whose comparisons were never traced, and its integer
  # fields are single bytes the mutator reaches without a hint.
  add_compile_options("$<$<COMPILE_LANGUAGE:CXX>:-fsanitize=fuzzer-no-link;-fno-sanitize-coverage=trace-cmp>")
  # Eigen's one-line evaluators (coeff, packet, assignCoeff: every operation
  # on a 3-vector) inlined: under the instrumentation Clang at -O2 keeps them
  # as calls, each with its sanitizer prologue, and they took most of the run
  # (perf; docs/robustness.md). Inlined code is instrumented alike: the same
  # checks, assertions included, fewer calls.
  add_compile_definitions("EIGEN_STRONG_INLINE=inline __attribute__((always_inline))")
  # libFuzzer's convention for a fuzzing build: the law's default substep
  # budget is 10^3 there instead of 10^5 (src/mortar/parameters.hpp), the same
  # code with a smaller bound (docs/robustness.md).
  add_compile_definitions(FUZZING_BUILD_MODE_UNSAFE_FOR_PRODUCTION)
  set(MJ_FUZZ_TARGET_FLAGS -fsanitize=fuzzer -fno-sanitize-coverage=trace-cmp)
endif()
