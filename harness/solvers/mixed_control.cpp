#include "solvers/mixed_control.hpp"

namespace mortar::harness {

std::string failure_location(int point, int step, long increment) {
  return "point " + std::to_string(point + 1) + ", step " + std::to_string(step) + ", increment " +
         std::to_string(increment) + ": ";
}

}  // namespace mortar::harness
