#include "abi/props.hpp"

#include "mortar/state_layout.hpp"

namespace mortar::harness {

std::vector<double> props_for(const Parameters& p, Scheme scheme, double stol, int max_substeps,
                              const CompressionCap& cap) {
  Controls c;
  c.scheme = scheme;
  if (stol != 0) c.stol = stol;
  if (max_substeps > 0) c.max_substeps = max_substeps;
  const auto props = to_props(p, c);
  std::vector<double> out(props.begin(), props.end());
  if (cap.on()) {
    out.resize(kCapFirstProp + kCapCount, 0.0);
    for (int i = 0; i < kCapCount; ++i) out[static_cast<size_t>(kCapFirstProp + i)] = cap_parameter_at(cap, i);
  }
  return out;
}

int state_count_for(const CompressionCap& cap) {
  return cap.on() ? kCappedStateCountDouble : kFlaggedStateCount;
}

}  // namespace mortar::harness
