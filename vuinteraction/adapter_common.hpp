// What the Abaqus adapters share (vuinteraction.cpp: Abaqus/Explicit,
// uinter.cpp: Abaqus/Standard): reading props into the law's model and the
// adapter's shear sign, the caller's name, and the one-line reports on
// stderr. Header-only, internal linkage: each adapter source stays a
// self-contained translation unit (what Abaqus's own compile line needs).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "mortar/integrator.hpp"

namespace mj_adapter {
namespace {

// Codes written to SDV 21 (status) for argument and property errors. Negative,
// so that they cannot be mistaken for the law's Failure codes (positive).
enum AdapterCode : int {
  kBadDirections = -1,  // nDir not 2 or 3
  kBadStateCount = -2,  // nStates / nStateVar / NSTATV below the layout's 23
  kBadPropCount = -3,   // nProps below 14
  kBadProperty = -4,    // a property or control breaks its rule
  kBadNodeStates = -5,  // nNodState < 1
  kInternalError = -9,  // an exception escaped the law (never expected)
};

// props(15..19) are the law's integration controls (mortar::read_props);
// props(20) is the adapter's shear sign; anything after it is ignored.
constexpr int kLawPropCount = 19;
constexpr int kSchemeIndex = 14;     // 0-based: props(15)
constexpr int kShearSignIndex = 19;  // 0-based: props(20)
constexpr int kReadPropCount = 20;

// Penetrations at or below this mean "no opposite surface found" (the manual
// gives -1e36 for unpaired points in UINTER; VUINTER is assumed to do the same).
constexpr double kUnpairedPenetration = -1e30;

// Who is calling, for messages.
struct Caller {
  const char* routine;  // "VUINTERACTION", "VUINTER" or "UINTER"
  const char* name;     // the interaction's name, not NUL-terminated
  int name_length;      // trailing blanks removed
};

Caller make_caller(const char* routine, const char* surf_int, int hidden_length) {
  int n = (hidden_length > 0 && hidden_length <= 80) ? hidden_length : 80;
  if (!surf_int) return {routine, "?", 1};
  while (n > 0 && (surf_int[n - 1] == ' ' || surf_int[n - 1] == '\0')) --n;
  return {routine, surf_int, n};
}

void report(const Caller& c, const char* what) {
  char line[640];
  std::snprintf(line, sizeof line, "%s, interaction '%.*s': %s\n", c.routine, c.name_length, c.name, what);
  std::fputs(line, stderr);  // one write per message, so threads do not interleave within it
}

void report_property(const Caller& c, const mortar::ValidationError& e) {
  char what[480];
  std::snprintf(what, sizeof what, "property '%s' (props(%d)) = %.9g violates the rule: %s", e.name, e.index + 1,
                e.value, e.rule);
  report(c, what);
}

// The law's model and the adapter's own control, read from props.
struct Setup {
  mortar::Model model;
  double shear_sign = -1;  // Abaqus stress(2..nDir) = shear_sign * tau
};

// Per adapter: what a 0 (or missing) props(15) and props(20) mean.
struct Defaults {
  mortar::Scheme scheme;
  double shear_sign;
  const char* shear_sign_rule;
};

// props(1..min(n, 20)) in double precision.
mortar::ValidationError read_setup(const double* p, int n, const Defaults& defaults, Setup& setup) {
  mortar::Parameters parameters;
  mortar::Controls controls;
  mortar::ValidationError e = mortar::read_props(p, std::min(n, kLawPropCount), parameters, controls);
  if (!e.ok()) return e;
  if (n <= kSchemeIndex || p[kSchemeIndex] == 0) controls.scheme = defaults.scheme;
  const double sign = n > kShearSignIndex ? p[kShearSignIndex] : 0.0;
  if (sign != 0 && sign != 1 && sign != -1) return {kShearSignIndex, "shear_sign", sign, defaults.shear_sign_rule};
  setup.shear_sign = sign == 0 ? defaults.shear_sign : sign;
  setup.model = mortar::make_model(parameters, controls);
  return {};
}

}  // namespace
}  // namespace mj_adapter
