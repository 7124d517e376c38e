#include "abi/status.hpp"

#include "adapter/status_codes.hpp"

namespace mortar::harness {

// SDV 21 comes back as a real of the routine's precision; its codes are whole
// numbers (docs/model.md 9), so the conversion is exact.
std::string status_meaning(double status) { return mj_adapter::status_meaning(static_cast<int>(status)); }

}  // namespace mortar::harness
