// Abaqus/Explicit adapters of the mortar-joint law: VUINTERACTION (general
// contact) and VUINTER (contact pairs). One source, compiled once per
// precision (mj_real = float, or double with MJ_DOUBLE_PRECISION); the law
// itself always runs in double precision.
//
// This file is the only place where Abaqus's conventions meet the law's:
//
//   normal   delta_n = (reference penetration) - penetration, the reference
//            being the penetration at the point's first call (stored in SDV 22,
//            SDV 23 = 1 once set). drDisp(1) is not used: its sign relative to
//            the penetration is not pinned down by the manual.
//   shear    the slips are the running sum of drDisp(2..nDir) (VUINTER:
//            drdisp(2..nDir)); the first call contributes nothing, because the
//            first call defines the zero (docs/model.md, section 1).
//   stress   stress(1) = -sigma_n (Abaqus: pressure positive; law: tension
//            positive); stress(2..nDir) = shear_sign * tau, shear_sign = -1
//            unless props(20) = +1 (see docs/abaqus.md for why, and how to
//            check it against a release).
//   energies sed = elastic energy per unit area at the end of the increment;
//            spd = increment of all inelastic energy of the law (plastic +
//            damage + unilateral, so that the balance closes); sfd = scd =
//            svd = 0; fluxes 0.
//   state    state(:,1,k) (VUINTERACTION) or statev(:,k) (VUINTER) in the
//            layout of mortar::slot (23 values; positions 1-14 as MODEL.md 3).
//
// Errors never cross the boundary as exceptions or silent exits. A bad
// argument or property: a message on stderr naming the interaction, the
// argument or property, its value and the rule, then Abaqus's exit utility
// XPLB_EXIT. That is the default, so that the source behaves right wherever
// Abaqus links it. In the standalone build (MJ_STANDALONE, used by the harness
// and the tests) there is no exit utility: the outputs are left finite (stress and
// sed as they came in), and every point of the block gets a negative code in
// SDV 21 (status); a point whose increment the law rejects keeps its start
// state with the law's positive Failure code there.
#include "vuinteraction.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "adapter_common.hpp"
#include "mortar/integrator.hpp"

#ifndef MJ_STANDALONE
// Abaqus/Explicit's exit utility (Fortran: CALL XPLB_EXIT, no arguments),
// resolved when Abaqus loads the library.
extern "C" void xplb_exit_();
#endif

namespace {

using Real = mj_real;
using mortar::Vec3;
namespace slot = mortar::slot;
// Shared with the Abaqus/Standard adapter (uinter.cpp): adapter_common.hpp.
using namespace mj_adapter;

// Point-failure messages printed per call before a summary line.
constexpr int kMaxPointMessages = 5;

// One call in the adapter's own terms: points k = 0 .. n_points-1.
struct Block {
  int n_points = 0, n_dir = 0, n_states = 0, n_props = 0;
  int n_node_states = 1;           // VUINTERACTION's nNodState; 1 for VUINTER
  long state_stride = 0;           // distance between the states of points k and k+1
  const Real* penetration = nullptr;
  long penetration_stride = 1;     // 1 (VUINTERACTION) or nDir (VUINTER: rdisp(1,k))
  const Real* d_rel_disp = nullptr;  // (nDir, n_points)
  const int* node = nullptr;       // user node number of point k, for messages
  long node_stride = 1;
  const Real* props = nullptr;
  Real *stress = nullptr, *state = nullptr, *sed = nullptr;
  Real *spd = nullptr, *sfd = nullptr, *scd = nullptr, *svd = nullptr;
  Real *flux_slv = nullptr, *flux_mst = nullptr;

  Real* state_of(int k) const { return state + k * state_stride; }
  Real* stress_of(int k) const { return stress + static_cast<long>(k) * n_dir; }
  const Real* d_rel_disp_of(int k) const { return d_rel_disp + static_cast<long>(k) * n_dir; }
  double penetration_of(int k) const { return double(penetration[k * penetration_stride]); }
  int node_of(int k) const { return node ? node[k * node_stride] : 0; }
};

// The first argument that breaks a rule.
struct ArgumentError {
  int code = 0;  // 0: none
  const char* argument = "";
  long value = 0;
  const char* rule = "";
};

ArgumentError check_arguments(const Block& b, const char* states_name) {
  if (b.n_dir != 2 && b.n_dir != 3)
    return {kBadDirections, "nDir", b.n_dir, "nDir is 2 (2D) or 3 (3D)"};
  if (b.n_node_states < 1) return {kBadNodeStates, "nNodState", b.n_node_states, "nNodState >= 1"};
  if (b.n_states < mortar::kStateCount)
    return {kBadStateCount, states_name, b.n_states,
            "at least 23 state variables (DEPVAR=23 on *SURFACE INTERACTION)"};
  if (b.n_props < mortar::kParameterCount)
    return {kBadPropCount, "nProps", b.n_props,
            "at least the 14 parameters of Table 1 (PROPERTIES=14 or more)"};
  return {};
}

// Abaqus/Explicit: props(15) = 0 is modified Euler, props(20) = 0 is -1.
constexpr Defaults kExplicitDefaults = {mortar::Scheme::modified_euler, -1.0,
                                        "props(20) is 0 (default, = -1), -1 or +1"};

mortar::ValidationError read_setup(const Block& b, Setup& setup) {
  double p[kReadPropCount] = {};
  const int n = std::min(b.n_props, kReadPropCount);
  for (int i = 0; i < n; ++i) p[i] = double(b.props[i]);
  return mj_adapter::read_setup(p, n, kExplicitDefaults, setup);
}

double finite_or_zero(Real x) { return std::isfinite(double(x)) ? double(x) : 0.0; }

void write_energies(const Block& b, int k, double sed, double spd) {
  b.sed[k] = Real(sed);
  b.spd[k] = Real(spd);
  b.sfd[k] = b.scd[k] = b.svd[k] = Real(0);
  b.flux_slv[k] = b.flux_mst[k] = Real(0);
}

// Outputs of a point that is not integrated: stress and sed as they came in
// (made finite), no dissipation.
void keep_start_outputs(const Block& b, int k) {
  Real* s = b.stress_of(k);
  for (int i = 0; i < b.n_dir; ++i) s[i] = Real(finite_or_zero(s[i]));
  write_energies(b, k, finite_or_zero(b.sed[k]), 0.0);
}

// A rejected block: finite outputs and the code in SDV 21 of every point, as
// far as the arrays the caller declared reach (n_dir and n_states may be the
// bad arguments themselves).
void reject_block(const Block& b, int code) {
  for (int k = 0; k < b.n_points; ++k) {
    if (b.n_dir > 0) {
      keep_start_outputs(b, k);
    } else {
      write_energies(b, k, finite_or_zero(b.sed[k]), 0.0);
    }
    if (b.n_states > slot::status && b.n_node_states >= 1) b.state_of(k)[slot::status] = Real(code);
  }
}

// Stops the analysis after an error has been reported.
void stop_analysis() {
#ifndef MJ_STANDALONE
  std::fflush(stderr);
  xplb_exit_();
#endif
  // Standalone: nothing to stop; the caller reads SDV 21.
}

void report_argument(const Caller& c, const ArgumentError& e) {
  char what[400];
  std::snprintf(what, sizeof what, "argument %s = %ld violates the rule: %s", e.argument, e.value, e.rule);
  report(c, what);
}

void report_point(const Caller& c, const Block& b, int k, int failure) {
  char what[400];
  std::snprintf(what, sizeof what,
                "point %d of %d (slave node %d): the law rejected the increment: %s (SDV 21 = %d); "
                "the point keeps its start state",
                k + 1, b.n_points, b.node_of(k), mortar::failure_name(static_cast<mortar::Failure>(failure)),
                failure);
  report(c, what);
}

// The separation increment of point k (law signs), from its state and inputs.
// The first call defines the zero, so it contributes no increment; a
// non-finite penetration yields a non-finite increment, which the law rejects.
Vec3 separation_increment(const Block& b, int k, const Real* st, const mortar::State& s) {
  const double penetration = b.penetration_of(k);
  const bool first = st[slot::initialised] == Real(0);
  if (first) return std::isfinite(penetration) ? Vec3::Zero() : Vec3::Constant(NAN);
  const double reference = double(st[slot::reference_penetration]);
  const Real* dd = b.d_rel_disp_of(k);
  return Vec3((reference - penetration) - s.separation[0], double(dd[1]), b.n_dir > 2 ? double(dd[2]) : 0.0);
}

// The adapter's own slots obey their rules: the open flag (SDV 15) and the
// initialised flag (SDV 23) are 0 or 1. The law reads the open flag as a
// bool, so a corrupted 0.5 or NaN would silently become "open".
bool flags_valid(const Real* st) {
  auto flag = [](Real x) { return x == Real(0) || x == Real(1); };
  return flag(st[slot::open]) && flag(st[slot::initialised]);
}

// A point that is not integrated: its start state (the caller's array,
// untouched but for the status), its stress and sed as they came in.
int reject_point(const Block& b, int k, mortar::Failure failure) {
  b.state_of(k)[slot::status] = Real(static_cast<int>(failure));
  keep_start_outputs(b, k);
  return static_cast<int>(failure);
}

bool all_finite(const Real* a, int n) {
  for (int i = 0; i < n; ++i)
    if (!std::isfinite(double(a[i]))) return false;
  return true;
}

// Integrates point k and writes its outputs. Returns the law's Failure code.
int integrate_point(const Setup& setup, const Block& b, int k) {
  if (b.penetration_of(k) <= kUnpairedPenetration) {  // no opposite surface: no interaction
    std::fill(b.stress_of(k), b.stress_of(k) + b.n_dir, Real(0));
    write_energies(b, k, 0.0, 0.0);
    return 0;
  }
  Real* st = b.state_of(k);
  if (!flags_valid(st)) return reject_point(b, k, mortar::Failure::invalid_state);
  mortar::State s;
  mortar::load_state(st, s);
  const bool first = st[slot::initialised] == Real(0);
  const mortar::IncrementResult r = mortar::integrate_increment(setup.model, s, separation_increment(b, k, st, s));
  if (!r.status.ok()) {  // the law kept the start state; only the counts and status change
    st[slot::substeps_accepted] = Real(s.substeps_accepted);
    st[slot::substeps_rejected] = Real(s.substeps_rejected);
    st[slot::status] = Real(s.status);
    Real* stress = b.stress_of(k);
    stress[0] = Real(-r.traction[0]);
    for (int i = 1; i < b.n_dir; ++i) stress[i] = Real(setup.shear_sign * r.traction[i]);
    write_energies(b, k, r.elastic_energy, 0.0);
    if (!all_finite(stress, b.n_dir) || !std::isfinite(double(b.sed[k]))) keep_start_outputs(b, k);
    return static_cast<int>(r.status.failure);
  }
  // The law's result in this routine's precision: a double beyond a float's
  // range would come back as infinity. Checked before anything is stored.
  Real end[mortar::kStateCount];
  std::copy(st, st + mortar::kStateCount, end);
  mortar::store_state(s, end);
  if (first) {
    end[slot::reference_penetration] = Real(b.penetration_of(k));
    end[slot::initialised] = Real(1);
  }
  Real stress_end[3] = {Real(-r.traction[0]), Real(setup.shear_sign * r.traction[1]),
                        Real(setup.shear_sign * r.traction[2])};
  const Real sed = Real(r.elastic_energy);
  const Real spd = Real(r.d_dissipation_plastic + r.d_dissipation_damage + r.d_energy_unilateral);
  if (!all_finite(end, mortar::kStateCount) || !all_finite(stress_end, b.n_dir) || !std::isfinite(double(sed)) ||
      !std::isfinite(double(spd)))
    return reject_point(b, k, mortar::Failure::non_finite_result);
  std::copy(end, end + mortar::kStateCount, st);
  std::copy(stress_end, stress_end + b.n_dir, b.stress_of(k));
  write_energies(b, k, double(sed), double(spd));
  return 0;
}

// Integrates every point; reports the failed ones. Returns how many failed.
int integrate_block(const Caller& c, const Setup& setup, const Block& b) {
  int failures = 0;
  for (int k = 0; k < b.n_points; ++k) {
    const int failure = integrate_point(setup, b, k);
    if (failure == 0) continue;
    if (++failures <= kMaxPointMessages) report_point(c, b, k, failure);
  }
  if (failures > kMaxPointMessages) {
    char what[160];
    std::snprintf(what, sizeof what, "%d points of %d failed in this call (first %d shown)", failures, b.n_points,
                  kMaxPointMessages);
    report(c, what);
  }
  return failures;
}

// The whole call: checks, then the law, point by point.
void run(const Caller& c, const Block& b, const char* states_name) noexcept {
  try {
    const ArgumentError a = check_arguments(b, states_name);
    if (a.code != 0) {
      report_argument(c, a);
      reject_block(b, a.code);
      stop_analysis();
      return;
    }
    Setup setup;
    const mortar::ValidationError e = read_setup(b, setup);
    if (!e.ok()) {
      report_property(c, e);
      reject_block(b, kBadProperty);
      stop_analysis();
      return;
    }
    if (integrate_block(c, setup, b) > 0) stop_analysis();
  } catch (...) {
    report(c, "internal error: an exception escaped the law; the block keeps its start values");
    reject_block(b, kInternalError);
    stop_analysis();
  }
}

}  // namespace

extern "C" void vuinteraction_(
    mj_real* stress, mj_real* fluxSlv, mj_real* fluxMst, mj_real* state, mj_real* sed,
    mj_real* sfd, mj_real* scd, mj_real* spd, mj_real* svd,
    const int* nBlock, const int* /*nBlockAnal*/, const int* /*nBlockEdge*/,
    const int* nNodState, const int* nNodSlv, const int* /*nNodMst*/,
    const int* nDir, const int* nStates, const int* nProps,
    const int* /*nTemp*/, const int* /*nFields*/,
    const int* /*jFlags*/, const mj_real* /*rData*/,
    const char* surfInt, const char* /*surfSlv*/, const char* /*surfMst*/,
    const int* jConSlvUid, const int* /*jConMstUid*/,
    const mj_real* props, const mj_real* penetration, const mj_real* drDisp,
    const mj_real* /*dRot*/, const mj_real* /*dircos*/, const mj_real* /*stiffDflt*/,
    const mj_real* /*condDflt*/, const mj_real* /*areaSlv*/, const mj_real* /*dircosSl*/,
    const mj_real* /*shapeSlv*/, const mj_real* /*shapeMst*/,
    const mj_real* /*coordSlv*/, const mj_real* /*coordMst*/,
    const mj_real* /*velSlv*/, const mj_real* /*velMst*/,
    const mj_real* /*tempSlv*/, const mj_real* /*tempMst*/,
    const mj_real* /*fieldSlv*/, const mj_real* /*fieldMst*/,
    int lenSurfInt, int /*lenSurfSlv*/, int /*lenSurfMst*/) {
  Block b;
  b.n_points = *nBlock;
  b.n_dir = *nDir;
  b.n_states = *nStates;
  b.n_props = *nProps;
  b.n_node_states = *nNodState;
  b.state_stride = static_cast<long>(*nStates) * *nNodState;  // state(:,1,k): first node state of point k
  b.penetration = penetration;
  b.d_rel_disp = drDisp;
  b.node = *nNodSlv >= 1 ? jConSlvUid : nullptr;
  b.node_stride = *nNodSlv;
  b.props = props;
  b.stress = stress;
  b.state = state;
  b.sed = sed;
  b.spd = spd;
  b.sfd = sfd;
  b.scd = scd;
  b.svd = svd;
  b.flux_slv = fluxSlv;
  b.flux_mst = fluxMst;
  run(make_caller("VUINTERACTION", surfInt, lenSurfInt), b, "nStates");
}

extern "C" void vuinter_(
    mj_real* sfd, mj_real* scd, mj_real* spd, mj_real* svd,
    mj_real* stress, mj_real* fluxSlv, mj_real* fluxMst, mj_real* sed, mj_real* statev,
    const int* /*kStep*/, const int* /*kInc*/,
    const int* /*nFacNod*/, const int* nSlvNod, const int* /*nMstNod*/,
    const int* /*nSurfDir*/, const int* nDir, const int* nStateVar,
    const int* nProps, const int* /*nTemp*/, const int* /*nPred*/,
    const int* /*numDefTfv*/,
    const int* jSlvUid, const int* /*jMstUid*/, const int* /*jConMstid*/,
    const mj_real* /*timStep*/, const mj_real* /*timGlb*/, const mj_real* /*dTimCur*/,
    const char* surfInt, const char* /*surfSlv*/, const char* /*surfMst*/,
    const mj_real* rdisp, const mj_real* drdisp, const mj_real* /*drot*/,
    const mj_real* /*stiffDflt*/, const mj_real* /*condDflt*/, const mj_real* /*shape*/,
    const mj_real* /*coordSlv*/, const mj_real* /*coordMst*/, const mj_real* /*alocaldir*/,
    const mj_real* props, const mj_real* /*areaSlv*/,
    const mj_real* /*tempSlv*/, const mj_real* /*dtempSlv*/,
    const mj_real* /*preDefSlv*/, const mj_real* /*dpreDefSlv*/,
    const mj_real* /*tempMst*/, const mj_real* /*dtempMst*/,
    const mj_real* /*preDefMst*/, const mj_real* /*dpreDefMst*/,
    int lenSurfInt, int /*lenSurfSlv*/, int /*lenSurfMst*/) {
  Block b;
  b.n_points = *nSlvNod;
  b.n_dir = *nDir;
  b.n_states = *nStateVar;
  b.n_props = *nProps;
  b.state_stride = *nStateVar;
  b.penetration = rdisp;  // rdisp(1,k): > 0 penetration, < 0 gap
  b.penetration_stride = *nDir;
  b.d_rel_disp = drdisp;
  b.node = jSlvUid;
  b.props = props;
  b.stress = stress;
  b.state = statev;
  b.sed = sed;
  b.spd = spd;
  b.sfd = sfd;
  b.scd = scd;
  b.svd = svd;
  b.flux_slv = fluxSlv;
  b.flux_mst = fluxMst;
  run(make_caller("VUINTER", surfInt, lenSurfInt), b, "nStateVar");
}
