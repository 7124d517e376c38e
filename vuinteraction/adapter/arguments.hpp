// The checks every entry point makes before the law runs: the array sizes its
// caller declared (nDir, nNodState, the state count, nProps) and props(1..24) read
// into the law's model (its compression cap from props(21..24)) and the
// adapter's shear sign (docs/abaqus.md, "props"; docs/model.md 2 and 12 for
// the law's rules, enforced by mortar::read_props and mortar::read_cap).
#pragma once

#include <algorithm>
#include <cstring>

#include "adapter/report.hpp"
#include "adapter/status_codes.hpp"
#include "mortar/integrator.hpp"
#include "mortar/state_layout.hpp"

namespace mj_adapter {

// props(15..19) are the law's integration controls (mortar::read_props);
// props(20) is the adapter's shear sign; props(21..24) the law's compression
// cap (mortar::read_cap); anything after them is ignored.
constexpr int kLawPropCount = mortar::kPropsWithControls;  // 19
constexpr int kSchemeIndex = 14;                           // 0-based: props(15)
constexpr int kShearSignIndex = 19;                        // 0-based: props(20)
constexpr int kReadPropCount = mortar::kCapFirstProp + mortar::kCapCount;  // 24

// Penetrations at or below this mean "no opposite surface found" (the manual
// gives -1e36 for unpaired points in UINTER; VUINTER is assumed to do the same).
constexpr double kUnpairedPenetration = -1e30;

// The sizes of one call's arrays, as its caller declared them.
struct Counts {
  int n_dir = 0;
  int n_node_states = 1;  // VUINTERACTION's nNodState; 1 where the routine has none
  int n_states = 0;
  int n_props = 0;
};

// How the routine's own argument list spells them (messages quote it).
struct ArgumentNames {
  const char* n_dir;
  const char* n_dir_rule;
  const char* n_states;
  const char* n_props;
  const char* rotation;  // dRot, drot, DROT
};

inline ArgumentError check_counts(const Counts& n, const ArgumentNames& names) {
  if (n.n_dir != 2 && n.n_dir != 3) return {kBadDirections, names.n_dir, n.n_dir, names.n_dir_rule};
  if (n.n_node_states < 1) return {kBadNodeStates, "nNodState", n.n_node_states, "nNodState >= 1"};
  if (n.n_states < mortar::kStateCount)
    return {kBadStateCount, names.n_states, n.n_states,
            "at least 23 state variables (DEPVAR=35 on *SURFACE INTERACTION: 23 for the law, 11 more for single "
            "precision's float pairs, SDV 35 the integration flags)"};
  if (n.n_props < mortar::kParameterCount)
    return {kBadPropCount, names.n_props, n.n_props, "at least the 14 parameters of Table 1 (PROPERTIES=14 or more)"};
  return {};
}

// A deck with a cap keeps kappa_c in SDV 36 (and its low part in SDV 37 in
// single precision): its state count, checked once props are read.
inline ArgumentError check_cap_state_count(const Counts& n, bool cap, bool single, const ArgumentNames& names) {
  if (!cap) return {};
  if (single && n.n_states < mortar::kCappedStateCountSingle)
    return {kBadStateCount, names.n_states, n.n_states,
            "at least 37 state variables with the compression cap (props(21) = fc > 0): DEPVAR=37 on *SURFACE "
            "INTERACTION (SDV 36-37 hold kappa_c as a float pair in single precision)"};
  if (!single && n.n_states < mortar::kCappedStateCountDouble)
    return {kBadStateCount, names.n_states, n.n_states,
            "at least 36 state variables with the compression cap (props(21) = fc > 0): DEPVAR=36 on *SURFACE "
            "INTERACTION in double precision (SDV 36 holds kappa_c; 37 in single precision)"};
  return {};
}

// The law's model and the adapter's own control, read from props.
struct Setup {
  mortar::Model model;
  double shear_sign = -1;  // Abaqus stress(2..nDir) = shear_sign * tau
};

// Per product: what a 0 (or missing) props(15) and props(20) mean.
struct Defaults {
  mortar::Scheme scheme;
  double shear_sign;
  const char* shear_sign_rule;
};

// props(1..min(n_props, 24)), in the routine's precision, into `setup`.
template <class Real>
mortar::ValidationError read_setup(const Real* props, int n_props, const Defaults& defaults, Setup& setup) {
  double p[kReadPropCount] = {};
  const int n = std::min(n_props, kReadPropCount);
  for (int i = 0; i < n; ++i) p[i] = double(props[i]);
  mortar::Parameters parameters;
  mortar::Controls controls;
  mortar::ValidationError e = mortar::read_props(p, std::min(n, kLawPropCount), parameters, controls);
  if (!e.ok()) return e;
  if (n <= kSchemeIndex || p[kSchemeIndex] == 0) controls.scheme = defaults.scheme;
  const double sign = n > kShearSignIndex ? p[kShearSignIndex] : 0.0;
  if (sign != 0 && sign != 1 && sign != -1) return {kShearSignIndex, "shear_sign", sign, defaults.shear_sign_rule};
  mortar::CompressionCap cap;
  e = mortar::read_cap(p, n, parameters, cap);
  if (!e.ok()) return e;
  setup.shear_sign = sign == 0 ? defaults.shear_sign : sign;
  setup.model = mortar::make_model(parameters, controls, cap);
  return {};
}

// read_setup through the last props this thread read with the same defaults:
// Abaqus calls an interaction's routine with one props array increment after
// increment, and reading it anew (Table 1's rules, make_model's tangents)
// costs as much as a good share of a block's elastic updates
// (docs/decisions.md). Only props that passed are kept, so a bad array
// is read and reported at every call; the key is their bits (props(1..24))
// and the defaults, on which the setup alone depends. Per thread: Abaqus/
// Explicit's threads call the routine at once.
template <class Real>
const Setup* cached_setup(const Real* props, int n_props, const Defaults& defaults, mortar::ValidationError& e) {
  struct Entry {
    Real props[kReadPropCount];
    int n = -1;  // props(1..n) are the key; -1: empty
    Defaults defaults{};
    Setup setup;
  };
  static thread_local Entry last;
  const int n = std::min(n_props, kReadPropCount);
  if (n == last.n && defaults.scheme == last.defaults.scheme && defaults.shear_sign == last.defaults.shear_sign &&
      std::memcmp(props, last.props, sizeof(Real) * static_cast<size_t>(n)) == 0)
    return &last.setup;
  last.n = -1;
  e = read_setup(props, n_props, defaults, last.setup);
  if (!e.ok()) return nullptr;
  std::memcpy(last.props, props, sizeof(Real) * static_cast<size_t>(n));
  last.n = n;
  last.defaults = defaults;
  return &last.setup;
}

}  // namespace mj_adapter
