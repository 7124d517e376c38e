// What a scene asks of one interface point at the end of one increment: each
// component of the separation (n, s1, s2) either displacement-controlled (its
// separation is given) or traction-controlled (its traction is given, its
// separation is the solver's unknown). Law signs throughout (docs/model.md 1:
// sigma_n > 0 tension, delta_n > 0 opening).
#pragma once

#include <array>

namespace mortar::harness {

enum class Control { displacement, traction };
inline const char* control_name(Control c) { return c == Control::traction ? "traction" : "displacement"; }

inline constexpr const char* kComponentNames[3] = {"n", "s1", "s2"};

struct PointTargets {
  std::array<Control, 3> kind{};
  std::array<double, 3> value{};  // separation [mm] or traction [MPa]
};

// True when component j's separation is an unknown of the mixed-control solve.
inline bool free_component(const PointTargets& t, int j) { return t.kind[j] == Control::traction; }

}  // namespace mortar::harness
