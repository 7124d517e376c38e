// One block of interface points as Abaqus/Explicit hands it to
// VUINTERACTION: every argument array in Fortran (column-major) layout with
// the block index last, owned here, and the call through the C ABI entry
// point `vuinteraction_` (double precision, MJ_DOUBLE_PRECISION).
//
// The mock contact scene is the simplest one the routine can see in general
// contact: node-to-face contact (nNodState = 1) of a slave node on a
// four-node master face, local directions equal to the global axes, unit
// slave area, no temperatures or field variables.
#pragma once

#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "abi/call_time.hpp"

namespace mortar::harness {

struct AbiSetup {
  int n_dir = 3;              // 2: one slip component, 3: two
  int n_states = 0;           // DEPVAR; at least the law's layout (mortar::kStateCount)
  std::vector<double> props;  // props(1..nProps)
  double stiffness_default = 0;  // stiffDflt handed to the routine (Abaqus's penalty guide)
};

class AbiBlock {
 public:
  AbiBlock(const AbiSetup& setup, int n_block, int first_point);

  int size() const { return n_block_; }
  int n_dir() const { return setup_.n_dir; }
  int n_states() const { return setup_.n_states; }

  // Read/write arguments (hold the start values on entry, end values on exit).
  double* stress(int k) { return &stress_[index(k, setup_.n_dir)]; }
  double* state(int k) { return &state_[index(k, setup_.n_states)]; }
  const double* stress(int k) const { return &stress_[index(k, setup_.n_dir)]; }
  const double* state(int k) const { return &state_[index(k, setup_.n_states)]; }
  double& sed(int k) { return sed_[k]; }
  double sed(int k) const { return sed_[k]; }
  std::vector<double>& stress_array() { return stress_; }
  std::vector<double>& state_array() { return state_; }
  std::vector<double>& sed_array() { return sed_; }
  // Write-only outputs.
  double spd(int k) const { return spd_[k]; }
  double sfd(int k) const { return sfd_[k]; }
  double scd(int k) const { return scd_[k]; }
  double svd(int k) const { return svd_[k]; }
  // Read-only kinematic inputs.
  double& penetration(int k) { return penetration_[k]; }
  double* dr_disp(int k) { return &dr_disp_[index(k, setup_.n_dir)]; }

  // Point k's kinematic inputs from law quantities (abi/vuinteraction_signs.hpp):
  // the opening at the end of the increment and the separation increment.
  void set_separation_increment(int k, double opening_end, const Eigen::Vector3d& d);
  // Point k's place in a scene of many joints (the wall, scenes/wall.hpp):
  // its tributary area (areaSlv), its local frame as Abaqus gives it in
  // dircos (column 1 the normal, column 2 the tangent, global components; the
  // adapter does not read it in 2D, but a caller must hand what Abaqus
  // would), and its coordinates. nDir = 2 only.
  void set_joint_point(int k, double area, const double normal[2], const double tangent[2], const double x[2]);
  // Point k's traction after a call, law signs (zero beyond nDir).
  Eigen::Vector3d traction(int k) const;

  // Calls vuinteraction_ once for the whole block.
  void invoke(const CallTime& time);

 private:
  static long index(int k, int stride) { return static_cast<long>(k) * stride; }

  AbiSetup setup_;
  int n_block_;
  int n_nod_slv_ = 1, n_nod_mst_ = 4, n_block_anal_, n_block_edge_ = 1;
  // read/write
  std::vector<double> stress_, flux_slv_, flux_mst_, state_, sed_;
  // write only
  std::vector<double> sfd_, scd_, spd_, svd_;
  // read only
  std::vector<int> j_con_slv_uid_, j_con_mst_uid_;
  std::vector<double> penetration_, dr_disp_, d_rot_, dircos_, stiff_dflt_, cond_dflt_, area_slv_, dircos_sl_,
      shape_slv_, shape_mst_, coord_slv_, coord_mst_, vel_slv_, vel_mst_, temp_slv_, temp_mst_, field_slv_,
      field_mst_;
  std::array<char, 80> surf_int_{}, surf_slv_{}, surf_mst_{};
};

}  // namespace mortar::harness
