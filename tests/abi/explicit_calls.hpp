// The two Abaqus/Explicit entry points as the Catch2 tests call them
// (abi_tests.cpp, rotation_tests.cpp): every argument of one VUINTERACTION or
// VUINTER call, in the routine's precision (mj_real from vuinteraction.h).
#pragma once

#include <cstddef>
#include <numeric>
#include <vector>

#include "abi_support.hpp"
#include "mortar/state_layout.hpp"
#include "paper_sets.hpp"
#include "vuinteraction.h"

namespace mj_abi_test {

// Almeida M15 as props(1..14) in the routine's precision, then zeros (the
// defaults of the controls and the shear sign) up to n_props.
inline std::vector<mj_real> paper_props(int n_props = 14) {
  return props_of<mj_real>(mortar::testing::almeida_m15(), n_props);
}

// dRot(2,2,n) = the unit matrix at every point.
template <class Real>
std::vector<Real> unit_rotations(int n) {
  std::vector<Real> r(4 * std::size_t(n), Real(0));
  for (std::size_t k = 0; k < std::size_t(n); ++k) r[4 * k] = r[4 * k + 3] = Real(1);
  return r;
}

using Real = mj_real;

// Everything one VUINTERACTION call takes, with neutral values for the
// arguments the law does not read. Arrays persist across calls; d_rot is the
// unit matrix at every point (the tangent directions do not turn) until a
// test sets it.
struct GeneralContact {
  int n_block, n_dir, n_states, n_props, n_node_states = 1;
  std::vector<Real> stress, flux_slv, flux_mst, state, sed, sfd, scd, spd, svd;
  std::vector<Real> props, penetration, dr_disp, d_rot;
  std::vector<int> slave_nodes;
  Name80 name{"JOINT-A"};

  GeneralContact(int block, int dir, std::vector<Real> p, int states = mortar::kStateCount, int state_padding = 0)
      : n_block(block), n_dir(dir), n_states(states), n_props(int(p.size())),
        stress(dir * block), flux_slv(block), flux_mst(block),
        state(states * block + state_padding), sed(block), sfd(block), scd(block), spd(block), svd(block),
        props(std::move(p)), penetration(block), dr_disp(dir * block), d_rot(unit_rotations<Real>(block)),
        slave_nodes(block) {
    std::iota(slave_nodes.begin(), slave_nodes.end(), 1001);
  }

  Real* state_of(int k) { return &state[k * n_states]; }
  Real* stress_of(int k) { return &stress[k * n_dir]; }

  void call() {
    const int n_nod_slv = 1, n_nod_mst = 4, n_temp = 0, n_fields = 1;
    const int flags[3] = {1, 1, 0};
    const Real r_data[4] = {0, 0, Real(1e-6), 0};
    std::vector<int> master_nodes(n_nod_mst * n_block, 0);
    const std::size_t n = std::size_t(n_block), d = std::size_t(n_dir);
    std::vector<Real> dircos(d * d * n), per_point(n), dircos_sl(d * n), shape_slv(1),
        shape_mst(4 * n), coord_slv(d * n), coord_mst(4 * d * n), field(n);
    const Name80 blank("");
    vuinteraction_(stress.data(), flux_slv.data(), flux_mst.data(), state.data(), sed.data(), sfd.data(),
                   scd.data(), spd.data(), svd.data(), &n_block, &n_block, &n_block, &n_node_states, &n_nod_slv,
                   &n_nod_mst, &n_dir, &n_states, &n_props, &n_temp, &n_fields, flags, r_data, name.text,
                   blank.text, blank.text, slave_nodes.data(), master_nodes.data(), props.data(),
                   penetration.data(), dr_disp.data(), d_rot.data(), dircos.data(), per_point.data(),
                   per_point.data(), per_point.data(), dircos_sl.data(), shape_slv.data(), shape_mst.data(),
                   coord_slv.data(), coord_mst.data(), coord_slv.data(), coord_mst.data(), per_point.data(),
                   per_point.data(), field.data(), field.data(), 80, 80, 80);
  }
};

// The same for VUINTER: rdisp(1,k) is the penetration, drdisp the increments.
struct ContactPair {
  int n_nodes, n_dir, n_state_var, n_props;
  std::vector<Real> stress, flux_slv, flux_mst, sed, statev, sfd, scd, spd, svd;
  std::vector<Real> props, rdisp, drdisp, d_rot;
  std::vector<int> slave_nodes;
  Name80 name{"PAIR-B"};

  ContactPair(int nodes, int dir, std::vector<Real> p, int states = mortar::kStateCount)
      : n_nodes(nodes), n_dir(dir), n_state_var(states), n_props(int(p.size())), stress(dir * nodes),
        flux_slv(nodes), flux_mst(nodes), sed(nodes), statev(states * nodes), sfd(nodes), scd(nodes), spd(nodes),
        svd(nodes), props(std::move(p)), rdisp(dir * nodes), drdisp(dir * nodes), d_rot(unit_rotations<Real>(nodes)),
        slave_nodes(nodes) {
    std::iota(slave_nodes.begin(), slave_nodes.end(), 2001);
  }

  Real* state_of(int k) { return &statev[k * n_state_var]; }
  Real* stress_of(int k) { return &stress[k * n_dir]; }

  void call() {
    const int k_step = 1, k_inc = 1, n_fac = 4, n_mst = 4, n_surf_dir = n_dir - 1, n_temp = 0, n_pred = 1,
              n_def = 1;
    const std::size_t n = std::size_t(n_nodes), d = std::size_t(n_dir);
    std::vector<int> master_nodes(n_mst, 0), connectivity(n_fac * n, 1);
    std::vector<Real> per_node(n), shape(n_fac * n), coord_slv(d * n), coord_mst(d * n_mst),
        local_dir(d * d * n), one(1);
    const Real t = 0, dt = Real(1e-6);
    const Name80 blank("");
    vuinter_(sfd.data(), scd.data(), spd.data(), svd.data(), stress.data(), flux_slv.data(), flux_mst.data(),
             sed.data(), statev.data(), &k_step, &k_inc, &n_fac, &n_nodes, &n_mst, &n_surf_dir, &n_dir,
             &n_state_var, &n_props, &n_temp, &n_pred, &n_def, slave_nodes.data(), master_nodes.data(),
             connectivity.data(), &t, &t, &dt, name.text, blank.text, blank.text, rdisp.data(), drdisp.data(),
             d_rot.data(), per_node.data(), per_node.data(), shape.data(), coord_slv.data(), coord_mst.data(),
             local_dir.data(), props.data(), per_node.data(), per_node.data(), per_node.data(), per_node.data(),
             per_node.data(), one.data(), one.data(), one.data(), one.data(), 80, 80, 80);
  }
};

}  // namespace mj_abi_test
