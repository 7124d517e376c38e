#include "abi/vuinteraction_call.hpp"

#include "abi/fortran_string.hpp"
#include "abi/vuinteraction_signs.hpp"
#include "vuinteraction.h"

static_assert(sizeof(mj_real) == sizeof(double), "the harness drives the double-precision entry point");

namespace mortar::harness {

AbiBlock::AbiBlock(const AbiSetup& setup, int n_block, int first_point)
    : setup_(setup), n_block_(n_block), n_block_anal_(n_block) {
  const int nb = n_block, nd = setup.n_dir;
  stress_.assign(nd * nb, 0.0);
  flux_slv_.assign(nb, 0.0);
  flux_mst_.assign(nb, 0.0);
  state_.assign(static_cast<size_t>(setup.n_states) * nb, 0.0);
  sed_.assign(nb, 0.0);
  sfd_.assign(nb, 0.0);
  scd_.assign(nb, 0.0);
  spd_.assign(nb, 0.0);
  svd_.assign(nb, 0.0);
  penetration_.assign(nb, 0.0);
  dr_disp_.assign(nd * nb, 0.0);
  // Local directions = global axes: no rotation of the tangent directions.
  d_rot_.assign(4 * nb, 0.0);
  dircos_.assign(nd * nd * nb, 0.0);
  for (int k = 0; k < nb; ++k) {
    d_rot_[4 * k] = d_rot_[4 * k + 3] = 1.0;
    for (int i = 0; i < nd; ++i) dircos_[k * nd * nd + i * nd + i] = 1.0;
  }
  stiff_dflt_.assign(nb, setup.stiffness_default);
  cond_dflt_.assign(nb, 0.0);
  area_slv_.assign(nb, 1.0);  // 1 mm^2: tractions and forces coincide
  dircos_sl_.assign(nd * nb, 0.0);
  for (int k = 0; k < nb; ++k) dircos_sl_[k * nd] = 1.0;
  shape_slv_.assign(n_nod_slv_ * n_block_edge_, 1.0);
  shape_mst_.assign(n_nod_mst_ * n_block_anal_, 1.0 / n_nod_mst_);
  // Points one millimetre apart along the second axis (the geometry is not
  // used by the law; it only has to be plausible).
  coord_slv_.assign(nd * n_nod_slv_ * nb, 0.0);
  for (int k = 0; k < nb; ++k) coord_slv_[k * nd + 1] = first_point + k;
  coord_mst_.assign(nd * n_nod_mst_ * n_block_anal_, 0.0);
  vel_slv_.assign(nd * n_nod_slv_ * nb, 0.0);
  vel_mst_.assign(nd * n_nod_mst_ * n_block_anal_, 0.0);
  temp_slv_.assign(nb, 0.0);
  temp_mst_.assign(n_block_anal_, 0.0);
  field_slv_.assign(1, 0.0);  // nFields = 0: never read, but not a null pointer
  field_mst_.assign(1, 0.0);
  j_con_slv_uid_.resize(n_nod_slv_ * nb);
  for (int k = 0; k < nb; ++k) j_con_slv_uid_[k] = first_point + k + 1;  // 1-based node labels
  j_con_mst_uid_.resize(n_nod_mst_ * n_block_anal_);
  for (size_t i = 0; i < j_con_mst_uid_.size(); ++i) j_con_mst_uid_[i] = 1000000 + static_cast<int>(i);
  fortran_string(surf_int_, "MORTAR");
  fortran_string(surf_slv_, "SLAVE");
  fortran_string(surf_mst_, "MASTER");
}

void AbiBlock::set_separation_increment(int k, double opening_end, const Eigen::Vector3d& d) {
  penetration_[k] = abi_signs::penetration_for_opening(opening_end);
  double* dr = dr_disp(k);
  dr[0] = abi_signs::normal_dr_disp(d[0]);
  for (int i = 1; i < setup_.n_dir; ++i) dr[i] = abi_signs::kSlipSign * d[i];
}

void AbiBlock::set_joint_point(int k, double area, const double normal[2], const double tangent[2],
                               const double x[2]) {
  const int nd = setup_.n_dir;  // 2: the caller checks
  area_slv_[k] = area;
  double* d = &dircos_[static_cast<size_t>(k) * nd * nd];
  d[0] = normal[0], d[1] = normal[1];    // dircos(:,1,k)
  d[2] = tangent[0], d[3] = tangent[1];  // dircos(:,2,k)
  dircos_sl_[k * nd] = normal[0], dircos_sl_[k * nd + 1] = normal[1];
  coord_slv_[k * nd] = x[0], coord_slv_[k * nd + 1] = x[1];
}

Eigen::Vector3d AbiBlock::traction(int k) const {
  const double* s = stress(k);
  Eigen::Vector3d t(abi_signs::normal_traction_from_stress(s[0]), 0.0, 0.0);
  for (int i = 1; i < setup_.n_dir; ++i) t[i] = abi_signs::kShearSign * s[i];
  return t;
}

void AbiBlock::invoke(const CallTime& info) {
  const int n_nod_state = 1, n_temp = 0, n_fields = 0;
  const int n_props = static_cast<int>(setup_.props.size());
  const int j_flags[3] = {info.step, info.increment, 0};
  const double r_data[4] = {info.step_time, info.total_time, info.time_increment, 0.0};
  vuinteraction_(stress_.data(), flux_slv_.data(), flux_mst_.data(), state_.data(), sed_.data(), sfd_.data(),
                 scd_.data(), spd_.data(), svd_.data(), &n_block_, &n_block_anal_, &n_block_edge_, &n_nod_state,
                 &n_nod_slv_, &n_nod_mst_, &setup_.n_dir, &setup_.n_states, &n_props, &n_temp, &n_fields,
                 j_flags, r_data, surf_int_.data(), surf_slv_.data(), surf_mst_.data(), j_con_slv_uid_.data(),
                 j_con_mst_uid_.data(), setup_.props.data(), penetration_.data(), dr_disp_.data(),
                 d_rot_.data(), dircos_.data(), stiff_dflt_.data(), cond_dflt_.data(), area_slv_.data(),
                 dircos_sl_.data(), shape_slv_.data(), shape_mst_.data(), coord_slv_.data(), coord_mst_.data(),
                 vel_slv_.data(), vel_mst_.data(), temp_slv_.data(), temp_mst_.data(), field_slv_.data(),
                 field_mst_.data(), 80, 80, 80);
}

}  // namespace mortar::harness
