// One contact point as Abaqus/Standard hands it to UINTER: every argument
// owned here, in Fortran layout (DDSDDR column-major), and the call through
// the C ABI entry point `uinter_` (always double precision). Abaqus/Standard
// calls UINTER once per contact point and equilibrium iteration, so there is
// no block: the implicit mock solver (solvers/implicit_solver.hpp) owns one of these
// per point.
//
// The scene is the simplest one a contact pair gives: local directions equal
// to the global axes, unit area, no temperatures or predefined fields, no
// linear perturbation.
//
// The harness's conversions between the law's signs and UINTER's arguments
// are all in `uinter_signs` below; they follow vuinteraction/uinter.cpp and
// docs/abaqus.md ("Using it in Abaqus/Standard").
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "abi/call_time.hpp"

namespace mortar::harness {

namespace uinter_signs {

// RDISP(1) is the relative position in the normal direction at the end of the
// increment, > 0 a penetration. The routine measures the law's opening from
// the position at the start of the first increment it sees (SDV 22), so
// delta_n = reference - RDISP(1). The harness starts every point at
// kReferencePosition, a bonded joint just in contact.
inline constexpr double kReferencePosition = 0.0;
inline double rdisp_normal_for_opening(double opening) { return kReferencePosition - opening; }
inline double opening_from_rdisp_normal(double rdisp1) { return kReferencePosition - rdisp1; }

// RDISP(2..NDIR) are the accumulated slips, which the routine takes as the
// law's slips: RDISP(1+i) = delta_s_i.
inline constexpr double kSlipSign = 1.0;

// STRESS(1) = -sigma_n (pressure positive); STRESS(2..) = s * tau with the
// adapter's Standard default s = +1 (props(20) absent or 0; the harness never
// passes props(20)).
inline constexpr double kShearSign = 1.0;

// STRESS = C sigma and RDISP = D delta + const, componentwise; so DDSDDR =
// C T D with T = d sigma / d delta the law's tangent, and the law's value of
// a target traction sigma_j is the Abaqus value C_j sigma_j.
inline constexpr std::array<double, 3> kStressFactor = {-1.0, kShearSign, kShearSign};  // C
inline constexpr std::array<double, 3> kRdispFactor = {-1.0, kSlipSign, kSlipSign};     // D

// RDISP(j) of a separation component (law signs), and back.
inline double rdisp_of(int j, double separation) {
  return j == 0 ? rdisp_normal_for_opening(separation) : kRdispFactor[static_cast<size_t>(j)] * separation;
}
inline double separation_of(int j, double rdisp) {
  return j == 0 ? opening_from_rdisp_normal(rdisp) : rdisp / kRdispFactor[static_cast<size_t>(j)];
}

}  // namespace uinter_signs

struct UinterSetup {
  int n_dir = 3;              // 2: one slip, 3: two
  int n_states = 0;           // NSTATV; at least the law's layout (mortar::kStateCount)
  std::vector<double> props;  // props(1..NPROPS)
};

class UinterPoint {
 public:
  UinterPoint(const UinterSetup& setup, int node);

  int n_dir() const { return setup_.n_dir; }
  int n_states() const { return setup_.n_states; }

  // Read/write: hold the start of the increment on entry (the caller loads
  // them before every call), the end on exit.
  double* state() { return state_.data(); }
  const double* state() const { return state_.data(); }
  double* stress() { return stress_.data(); }
  const double* stress() const { return stress_.data(); }
  double& sed() { return sed_; }
  double sed() const { return sed_; }
  // Write-only outputs.
  double spd() const { return spd_; }
  double pnewdt() const { return pnewdt_; }
  // DDSDDR(i, j) (0-based): d STRESS(i) / d RDISP(j).
  double ddsddr(int i, int j) const { return ddsddr_[static_cast<size_t>(i + j * setup_.n_dir)]; }
  // Read-only kinematic inputs.
  double* rdisp() { return rdisp_.data(); }
  double* drdisp() { return drdisp_.data(); }

  // Calls uinter_ once. PNEWDT is set large before the call, as Abaqus does.
  void invoke(const CallTime& time);

 private:
  UinterSetup setup_;
  int node_;
  // to be defined
  std::array<double, 3> stress_{};
  std::array<double, 9> ddsddr_{}, amki_{}, amski_{};
  std::array<double, 2> flux_{};
  std::array<double, 4> ddfddt_{};
  std::array<double, 6> ddsddt_{}, ddfddr_{};
  // can be defined
  std::vector<double> state_;
  double sed_ = 0, sfd_ = 0, spd_ = 0, svd_ = 0, scd_ = 0, pnewdt_ = 0;
  // for information
  std::array<double, 3> rdisp_{}, drdisp_{}, coords_{};
  std::array<double, 9> alocaldir_{};
  std::array<double, 4> drot_{};
  std::array<double, 2> temp_{}, dtemp_{}, predef_{}, dpred_{};
  std::array<char, 80> ciname_{}, slname_{}, msname_{};
};

}  // namespace mortar::harness
