// Why an increment failed: the codes of state slot 21 (SDV 21), one table for
// the law, the adapters and the harness (docs/model.md 9).
#pragma once

#include <array>

namespace mortar {

enum class Failure : int {
  none = 0,
  too_many_substeps = 1,     // substeps + relaxation steps (or segment restarts) exceeded Controls::max_substeps
  relaxation_failed = 2,     // return at fixed separation found no surface point
  too_many_switches = 3,     // more open/closed switches (regime segments) in one increment than allowed
  non_finite_increment = 4,  // the separation increment holds NaN or infinity
  invalid_state = 5,         // the incoming state breaks a rule (see check_state)
  non_finite_result = 6,     // a result (traction, energy, state) beyond the floating-point range: start state kept
  local_solve_failed = 7,    // implicit scheme: Newton failed at the smallest substep, or spent its budget
};

// One row of the SDV-21 table.
struct FailureInfo {
  Failure failure;
  int code;             // the value in SDV 21
  const char* name;     // identifier, e.g. "too_many_substeps"
  const char* message;  // what a log line says (failure_name)
};
inline constexpr int kFailureCount = 8;
extern const std::array<FailureInfo, kFailureCount> kFailureTable;

// The row of a code, or nullptr for a code the law does not produce (the
// adapters' negative argument errors, garbage in a restart).
const FailureInfo* failure_info(int code);
// The message of a failure ("unknown" for a value outside the table).
const char* failure_name(Failure f);

}  // namespace mortar
