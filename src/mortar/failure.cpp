#include "mortar/failure.hpp"

namespace mortar {

const std::array<FailureInfo, kFailureCount> kFailureTable = {{
    {Failure::none, 0, "none", "none"},
    {Failure::too_many_substeps, 1, "too_many_substeps", "too many substeps"},
    {Failure::relaxation_failed, 2, "relaxation_failed", "return at fixed separation did not reach the surface"},
    {Failure::too_many_switches, 3, "too_many_switches", "too many open/closed switches in one increment"},
    {Failure::non_finite_increment, 4, "non_finite_increment", "separation increment is not finite"},
    {Failure::invalid_state, 5, "invalid_state", "invalid state"},
    {Failure::non_finite_result, 6, "non_finite_result", "non-finite result"},
    {Failure::local_solve_failed, 7, "local_solve_failed",
     "implicit return mapping did not converge (smallest substep or Newton budget reached)"},
}};

const FailureInfo* failure_info(int code) {
  for (const FailureInfo& f : kFailureTable)
    if (f.code == code) return &f;
  return nullptr;
}

const char* failure_name(Failure f) {
  const FailureInfo* info = failure_info(static_cast<int>(f));
  return info ? info->message : "unknown";
}

}  // namespace mortar
