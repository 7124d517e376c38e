#include "abi/props.hpp"

namespace mortar::harness {

std::vector<double> props_for(const Parameters& p, Scheme scheme, double stol, int max_substeps) {
  Controls c;
  c.scheme = scheme;
  if (stol != 0) c.stol = stol;
  if (max_substeps > 0) c.max_substeps = max_substeps;
  const auto props = to_props(p, c);
  return {props.begin(), props.end()};
}

}  // namespace mortar::harness
