// State of one interface point: the value type the law works on
// (docs/model.md 3). Its layout over the solver's flat array is the SDV
// module's (mortar/state_layout.hpp).
#pragma once

#include <Eigen/Core>

namespace mortar {

using Vec3 = Eigen::Vector3d;  // (n, s1, s2) components
using Mat3 = Eigen::Matrix3d;

// The value type the law works on (always double precision).
struct State {
  Vec3 plastic = Vec3::Zero();     // delta_p
  Vec3 crack = Vec3::Zero();       // delta_cr
  double wI = 0, wII = 0, wIII = 0;
  double dn = 0, ds = 0;
  Vec3 separation = Vec3::Zero();  // delta, since the reference state
  bool open = false;               // unilateral regime h (Eq. 13)
  double dissipation_plastic = 0;
  double dissipation_damage = 0;
  double energy_unilateral = 0;
  int substeps_accepted = 0;
  int substeps_rejected = 0;
  int status = 0;
  // SDV 35: every integration_flag an increment of this point has raised
  // (OR'd; outside SDV 1-23, so load_state/store_state leave it).
  int integration_flags = 0;
  // The compression cap's hardening variable: the plastic closure of
  // crushing, sigma_c kappa_c' = sigma . delta_p' of the cap flow
  // (docs/model.md 12) [mm]. 0 without a cap.
  double kappa_c = 0;

  Vec3 elastic_separation() const { return separation - plastic; }
};

}  // namespace mortar
