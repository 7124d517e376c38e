#include "abi/status.hpp"

#include "mortar/integrator.hpp"

namespace mortar::harness {

std::string status_meaning(double status) {
  if (status > 0) return failure_name(static_cast<Failure>(static_cast<int>(status)));
  switch (static_cast<int>(status)) {
    case -1: return "nDir is not 2 or 3";
    case -2: return "fewer than 23 state variables";
    case -3: return "fewer than 14 properties";
    case -4: return "a property breaks its rule (the routine's message on stderr names it)";
    case -5: return "nNodState < 1";
    default: return "the routine's internal error";
  }
}

}  // namespace mortar::harness
