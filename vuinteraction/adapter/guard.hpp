// The skeleton every entry point runs: argument checks, props, then the law;
// an error is reported, coded in SDV 21 and followed by the product's exit
// utility. Nothing is thrown across the C ABI and every output is left finite
// (docs/robustness.md).
#pragma once

#include <cstdio>
#include <type_traits>

#include "adapter/arguments.hpp"
#include "adapter/report.hpp"
#include "adapter/status_codes.hpp"

namespace mj_adapter {

// Abaqus's exit utility (XPLB_EXIT, XIT), resolved when Abaqus loads the
// library; nullptr in the standalone build (MJ_STANDALONE), where there is
// nothing to stop and the caller reads SDV 21 instead.
using ExitUtility = void (*)();

inline void stop_analysis(ExitUtility exit_utility) {
  if (!exit_utility) return;
  std::fflush(stderr);
  exit_utility();
}

// What differs between the routines around the same skeleton.
struct Routine {
  const char* name;         // "VUINTERACTION", "VUINTER", "UINTER": messages
  ArgumentNames arguments;  // how its argument list spells the checked arguments
  Defaults defaults;        // what props(15) = 0 and props(20) = 0 mean
  const char* unit;         // "block" or "point": what keeps its start values
  ExitUtility exit_utility;
};

// Inlined into each entry point, so that the call's block (a local there)
// keeps its fields in registers through the points' loop; called through a
// reference, the loop spilled its array offsets (docs/decisions.md).
#if defined(__GNUC__)
#define MJ_ENTRY_INLINE inline __attribute__((always_inline))
#else
#define MJ_ENTRY_INLINE inline
#endif

// One call of one routine, as the skeleton sees it (a deck with a cap: its
// state count once props are read, check_cap_state_count). `Call` provides
//   Counts counts;  const Real* props;
//   void reject(int code)          finite outputs, `code` in SDV 21 as far as
//                                  the declared arrays reach;
//   int check_points(const Caller&, const ArgumentNames&)
//                                  the per-point arguments' rules (dRot):
// The rest: docs/adapters.md, section 4.
template <class Call>
MJ_ENTRY_INLINE void run_call(const Routine& routine, const char* surf_int, int surf_int_length, Call& call) noexcept {
  const Caller who = make_caller(routine.name, surf_int, surf_int_length);
  const ExitUtility exit_utility = routine.exit_utility;
  try {
    const ArgumentError a = check_counts(call.counts, routine.arguments);
    if (a.code != 0) {
      report_argument(who, a);
      call.reject(a.code);
      stop_analysis(exit_utility);
      return;
    }
    const int point_code = call.check_points(who, routine.arguments);
    if (point_code != 0) {
      call.reject(point_code);
      stop_analysis(exit_utility);
      return;
    }
    mortar::ValidationError e;
    const Setup* setup = cached_setup(call.props, call.counts.n_props, routine.defaults, e);
    if (!setup) {
      report_property(who, e);
      call.reject(kBadProperty);
      stop_analysis(exit_utility);
      return;
    }
    using Real = std::remove_const_t<std::remove_pointer_t<decltype(call.props)>>;
    const ArgumentError c = check_cap_state_count(call.counts, setup->model.cap.on(),
                                                  std::is_same_v<Real, float>, routine.arguments);
    if (c.code != 0) {
      report_argument(who, c);
      call.reject(c.code);
      stop_analysis(exit_utility);
      return;
    }
    if (!call.integrate(who, *setup)) stop_analysis(exit_utility);
  } catch (...) {
    char what[160];
    std::snprintf(what, sizeof what, "internal error: an exception escaped the law; the %s keeps its start values",
                  routine.unit);
    report(who, what);
    call.reject(kInternalError);
    stop_analysis(exit_utility);
  }
}

}  // namespace mj_adapter
