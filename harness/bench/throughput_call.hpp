// The argument arrays of many interface points as Abaqus/Explicit hands them
// to VUINTERACTION (Fortran layout, the point index last), in either
// precision, and one call of a routine over a block of them. The throughput
// bench (bench/throughput.hpp) keeps all its points in one set of arrays so
// that a block is a window into them, as in a solver whose contact data are
// larger than the cache.
#pragma once

#include <vector>

namespace mortar::harness {

// VUINTERACTION's argument list (vuinteraction/vuinteraction.h) with REAL =
// Real: one type for both precisions' entry points.
template <class Real>
using VuinteractionRoutine = void (*)(
    Real* stress, Real* fluxSlv, Real* fluxMst, Real* state, Real* sed, Real* sfd, Real* scd, Real* spd, Real* svd,
    const int* nBlock, const int* nBlockAnal, const int* nBlockEdge, const int* nNodState, const int* nNodSlv,
    const int* nNodMst, const int* nDir, const int* nStates, const int* nProps, const int* nTemp,
    const int* nFields, const int* jFlags, const Real* rData, const char* surfInt, const char* surfSlv,
    const char* surfMst, const int* jConSlvUid, const int* jConMstUid, const Real* props, const Real* penetration,
    const Real* drDisp, const Real* dRot, const Real* dircos, const Real* stiffDflt, const Real* condDflt,
    const Real* areaSlv, const Real* dircosSl, const Real* shapeSlv, const Real* shapeMst, const Real* coordSlv,
    const Real* coordMst, const Real* velSlv, const Real* velMst, const Real* tempSlv, const Real* tempMst,
    const Real* fieldSlv, const Real* fieldMst, int lenSurfInt, int lenSurfSlv, int lenSurfMst);

// The single-precision routine (float pairs with DEPVAR 34), built for the
// harness under another symbol name (bench/throughput_single.cpp), and the
// double-precision one the harness links as vuinteraction_.
VuinteractionRoutine<float> single_precision_routine();
VuinteractionRoutine<double> double_precision_routine();

// Node-to-face contact of one slave node on a four-node master face, nDir = 3,
// identity local directions and rotation increments, unit area (the mock
// scene of harness/README.md). Inputs that change from increment to increment
// (penetration, drDisp) are held in `variants` alternatives, chosen per call.
template <class Real>
struct PointArrays {
  static constexpr int kDir = 3, kMasterNodes = 4;
  int points = 0, n_states = 0;
  std::vector<Real> props;
  std::vector<Real> stress, flux_slv, flux_mst, state, sed, sfd, scd, spd, svd;
  std::vector<int> j_con_slv, j_con_mst;
  std::vector<std::vector<Real>> penetration, dr_disp;  // [variant][point (x nDir)]
  std::vector<Real> d_rot, dircos, stiff_dflt, cond_dflt, area_slv, dircos_sl, shape_slv, shape_mst, coord_slv,
      coord_mst, vel_slv, vel_mst;
  Real none[1] = {Real(0)};  // temperatures and fields: nTemp = nFields = 0

  PointArrays(int points_, int n_states_, const std::vector<double>& props_, int variants)
      : points(points_), n_states(n_states_) {
    const long n = points;
    for (double p : props_) props.push_back(Real(p));
    stress.assign(n * kDir, Real(0));
    for (auto* v : {&flux_slv, &flux_mst, &sed, &sfd, &scd, &spd, &svd, &cond_dflt}) v->assign(n, Real(0));
    state.assign(n * n_states, Real(0));
    j_con_slv.resize(n);
    j_con_mst.resize(n * kMasterNodes);
    for (long k = 0; k < n; ++k) {
      j_con_slv[k] = int(k + 1);
      for (int m = 0; m < kMasterNodes; ++m) j_con_mst[k * kMasterNodes + m] = int(1000000 + k * kMasterNodes + m);
    }
    penetration.assign(variants, std::vector<Real>(n, Real(0)));
    dr_disp.assign(variants, std::vector<Real>(n * kDir, Real(0)));
    d_rot.assign(n * 4, Real(0));
    dircos.assign(n * kDir * kDir, Real(0));
    for (long k = 0; k < n; ++k) {
      d_rot[k * 4] = d_rot[k * 4 + 3] = Real(1);
      for (int i = 0; i < kDir; ++i) dircos[k * kDir * kDir + i * (kDir + 1)] = Real(1);
    }
    stiff_dflt.assign(n, Real(props_.at(0)));
    area_slv.assign(n, Real(1));
    dircos_sl.assign(n * kDir, Real(0));
    shape_slv.assign(1, Real(1));
    shape_mst.assign(n * kMasterNodes, Real(0.25));
    coord_slv.assign(n * kDir, Real(0));
    coord_mst.assign(n * kDir * kMasterNodes, Real(0));
    vel_slv.assign(n * kDir, Real(0));
    vel_mst.assign(n * kDir * kMasterNodes, Real(0));
  }

  // One call of `routine` over points first .. first + count - 1 with the
  // inputs of `variant`.
  void call(VuinteractionRoutine<Real> routine, long first, int count, int variant) {
    static const char surf_int[80] = "MORTAR", surf_slv[80] = "SLAVE", surf_mst[80] = "MASTER";
    const int n_block = count, n_block_edge = 1, n_nod_state = 1, n_nod_slv = 1, n_nod_mst = kMasterNodes;
    const int n_dir = kDir, n_props = int(props.size()), zero = 0;
    const int j_flags[3] = {1, 1, 0};
    const Real r_data[4] = {Real(1), Real(1), Real(1e-6), Real(0)};
    const long d = first * kDir;
    routine(&stress[d], &flux_slv[first], &flux_mst[first], &state[first * n_states], &sed[first], &sfd[first],
            &scd[first], &spd[first], &svd[first], &n_block, &n_block, &n_block_edge, &n_nod_state, &n_nod_slv,
            &n_nod_mst, &n_dir, &n_states, &n_props, &zero, &zero, j_flags, r_data, surf_int, surf_slv, surf_mst,
            &j_con_slv[first], &j_con_mst[first * kMasterNodes], props.data(), &penetration[variant][first],
            &dr_disp[variant][d], &d_rot[first * 4], &dircos[d * kDir], &stiff_dflt[first], &cond_dflt[first],
            &area_slv[first], &dircos_sl[d], shape_slv.data(), &shape_mst[first * kMasterNodes], &coord_slv[d],
            &coord_mst[d * kMasterNodes], &vel_slv[d], &vel_mst[d * kMasterNodes], none, none, none, none, 80, 80,
            80);
  }
};

}  // namespace mortar::harness
