// Abaqus/Standard adapter of the mortar-joint law: UINTER (contact pairs,
// *SURFACE INTERACTION, USER). Always double precision. One call per contact
// point and per equilibrium iteration; Abaqus passes the state at the start
// of the increment every time, and keeps what the call returns only when the
// increment converges.
//
// This file is where Abaqus/Standard's conventions meet the law's
// (docs/abaqus.md, "Using it in Abaqus/Standard"):
//
//   normal   RDISP(1) > 0 is a penetration, < 0 a gap, at the END of the
//            increment (current iteration); DRDISP its increment. The zero of
//            the law's separation is the position at the start of the first
//            increment in which the point is seen (SDV 22 = RDISP(1) -
//            DRDISP(1) then, SDV 23 = 1): the same in every iteration of that
//            increment, so repeating the call cannot move it. delta_n =
//            SDV 22 - RDISP(1), opening positive.
//   shear    RDISP(2..NDIR) are the accumulated slips from the beginning of
//            the analysis; the law's slips are these totals, so the increment
//            is RDISP(2..) - SDV 13..14 (a joint is bonded from the start of
//            the analysis in shear).
//   stress   STRESS(1) = -sigma_n (pressure positive); STRESS(2..NDIR) =
//            shear_sign * tau with shear_sign = +1 unless props(20) = -1 (the
//            convention of public working UINTER code, STRESS(2) = +K
//            RDISP(2)).
//   tangent  DDSDDR = d STRESS / d RDISP = C T D with T = d sigma / d delta
//            the law's tangent (the consistent tangent of the implicit
//            scheme, 7.5), C = diag(-1, s, s) and D = d delta / d RDISP =
//            diag(-1, 1, 1). It is not symmetric (non-associated flow,
//            softening): use UNSYMM=YES on *SURFACE INTERACTION.
//   scheme   props(15) = 0 (or absent) selects the implicit scheme here (the
//            only one with a consistent tangent); 1 or 2 run an explicit
//            scheme with its continuum tangent.
//   energies SED elastic energy at the end; SPD increment of plastic + damage
//            + unilateral energy; SFD = SVD = SCD = 0; FLUX, DDFDDT, DDSDDT,
//            DDFDDR = 0 (no heat, no temperature dependence).
//   failure  the law rejects the increment (e.g. the local Newton fails at
//            its smallest substep): PNEWDT = 0.5 (Abaqus retries with half
//            the time increment), outputs finite (start traction, start
//            secant stiffness, start state with the code in SDV 21), one line
//            on stderr naming the interaction and node.
//   errors   a bad argument or property: a line on stderr naming the
//            interaction, then Abaqus/Standard's XIT. Standalone build
//            (MJ_STANDALONE): no exit utility; the code in SDV 21, outputs
//            finite.
//   LINPER   in a linear perturbation step the inputs are perturbations:
//            DDSDDR is the tangent of the base state for a zero increment
//            (its secant stiffness), STRESS = DDSDDR DRDISP, the state is not
//            changed.
//
// Nothing here keeps mutable global or static state: every output is a
// function of the arguments of this call alone.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "adapter_common.hpp"
#include "mortar/integrator.hpp"
#include "vuinteraction.h"

#ifndef MJ_STANDALONE
// Abaqus/Standard's exit utility (Fortran: CALL XIT, no arguments).
extern "C" void xit_();
#endif

namespace {

using mortar::Mat3;
using mortar::Vec3;
namespace slot = mortar::slot;
using namespace mj_adapter;

constexpr double kCutBack = 0.5;  // PNEWDT asked for when the law fails

// Abaqus/Standard: props(15) = 0 is the implicit scheme, props(20) = 0 is +1.
constexpr Defaults kStandardDefaults = {mortar::Scheme::implicit, 1.0, "props(20) is 0 (default, = +1), -1 or +1"};

// The arguments this adapter reads or writes, in its own terms.
struct Call {
  int n_dir = 0, n_states = 0, n_props = 0, node = 0;
  bool perturbation = false;  // LINPER = 1
  const double* rdisp = nullptr;
  const double* drdisp = nullptr;
  const double* props = nullptr;
  double *stress = nullptr, *ddsddr = nullptr, *statev = nullptr;
  double *flux = nullptr, *ddfddt = nullptr, *ddsddt = nullptr, *ddfddr = nullptr;
  double *sed = nullptr, *sfd = nullptr, *spd = nullptr, *svd = nullptr, *scd = nullptr, *pnewdt = nullptr;
};

double finite_or_zero(double x) { return std::isfinite(x) ? x : 0.0; }

void stop_analysis() {
#ifndef MJ_STANDALONE
  std::fflush(stderr);
  xit_();
#endif
}

// No heat and no temperature dependence; no friction, viscous or creep
// dissipation booked apart from the law's plasticity.
void write_unused(const Call& c) {
  c.flux[0] = c.flux[1] = 0;
  std::fill(c.ddfddt, c.ddfddt + 4, 0.0);
  std::fill(c.ddsddt, c.ddsddt + 2 * c.n_dir, 0.0);
  std::fill(c.ddfddr, c.ddfddr + 2 * c.n_dir, 0.0);
  *c.sfd = *c.svd = *c.scd = 0;
}

// A rejected call (bad argument or property): finite outputs as far as the
// declared arrays reach, and the code in SDV 21.
void reject(const Call& c, int code) {
  if (c.n_dir >= 1 && c.n_dir <= 3) {
    for (int i = 0; i < c.n_dir; ++i) c.stress[i] = finite_or_zero(c.stress[i]);
    std::fill(c.ddsddr, c.ddsddr + c.n_dir * c.n_dir, 0.0);
    write_unused(c);
  } else {
    *c.sfd = *c.svd = *c.scd = 0;
  }
  *c.sed = finite_or_zero(*c.sed);
  *c.spd = 0;
  if (c.n_states > slot::status) c.statev[slot::status] = code;
}

void report_argument(const Caller& who, const char* argument, long value, const char* rule) {
  char what[400];
  std::snprintf(what, sizeof what, "argument %s = %ld violates the rule: %s", argument, value, rule);
  report(who, what);
}

// Abaqus's STRESS and DDSDDR from the law's traction and tangent (docs at the
// top): STRESS = C sigma, DDSDDR = C T D.
void write_stress(const Call& c, const Setup& setup, const Vec3& traction, const Mat3& tangent) {
  const Vec3 C(-1.0, setup.shear_sign, setup.shear_sign);
  const Vec3 D(-1.0, 1.0, 1.0);
  for (int i = 0; i < c.n_dir; ++i) {
    c.stress[i] = C[i] * traction[i];
    for (int j = 0; j < c.n_dir; ++j) c.ddsddr[i + j * c.n_dir] = C[i] * tangent(i, j) * D[j];
  }
}

void integrate(const Caller& who, const Call& c, const Setup& setup) {
  double* st = c.statev;
  write_unused(c);
  if (c.rdisp[0] <= kUnpairedPenetration) {  // no opposite surface: no interaction
    std::fill(c.stress, c.stress + c.n_dir, 0.0);
    std::fill(c.ddsddr, c.ddsddr + c.n_dir * c.n_dir, 0.0);
    *c.sed = *c.spd = 0;
    return;
  }
  mortar::State s;
  mortar::load_state(st, s);
  const bool first = st[slot::initialised] == 0.0;
  Mat3 T;
  if (c.perturbation) {
    // Linear perturbation: the tangent of the base state (a zero increment
    // from it, i.e. its secant stiffness), applied to the perturbation; the
    // base state is not changed.
    mortar::State base = s;
    const mortar::IncrementResult r = mortar::integrate_increment(setup.model, base, Vec3::Zero(), &T);
    Vec3 d_rdisp = Vec3::Zero();
    for (int i = 0; i < c.n_dir; ++i) d_rdisp[i] = c.drdisp[i];
    const Vec3 D(-1.0, 1.0, 1.0);
    write_stress(c, setup, T * D.cwiseProduct(d_rdisp), T);
    *c.sed = *c.spd = 0;
    if (!r.status.ok()) *c.pnewdt = std::min(*c.pnewdt, kCutBack);
    return;
  }
  // The reference is the start-of-increment position, the same in every
  // iteration of the first increment (RDISP - DRDISP).
  const double reference = first ? c.rdisp[0] - c.drdisp[0] : st[slot::reference_penetration];
  Vec3 d((reference - c.rdisp[0]) - s.separation[0], c.rdisp[1] - s.separation[1],
         c.n_dir > 2 ? c.rdisp[2] - s.separation[2] : 0.0);
  if (!std::isfinite(reference)) d[0] = NAN;  // rejected by the law below
  const mortar::IncrementResult r = mortar::integrate_increment(setup.model, s, d, &T);
  mortar::store_state(s, st);
  write_stress(c, setup, r.traction, T);
  *c.sed = r.elastic_energy;
  *c.spd = r.d_dissipation_plastic + r.d_dissipation_damage + r.d_energy_unilateral;
  if (!r.status.ok()) {
    // The start state is kept (with the code in SDV 21); Abaqus abandons the
    // increment and retries with PNEWDT times the time increment.
    *c.pnewdt = std::min(*c.pnewdt, kCutBack);
    char what[400];
    std::snprintf(what, sizeof what,
                  "node %d: the law rejected the increment: %s (SDV 21 = %d); asking for a smaller increment "
                  "(PNEWDT = %g)",
                  c.node, mortar::failure_name(r.status.failure), int(r.status.failure), kCutBack);
    report(who, what);
    return;
  }
  if (first) {
    st[slot::reference_penetration] = reference;
    st[slot::initialised] = 1;
  }
}

void run(const Caller& who, const Call& c) noexcept {
  try {
    if (c.n_dir != 2 && c.n_dir != 3) {
      report_argument(who, "NDIR", c.n_dir, "NDIR is 2 (2D) or 3 (3D)");
      reject(c, kBadDirections);
      stop_analysis();
      return;
    }
    if (c.n_states < mortar::kStateCount) {
      report_argument(who, "NSTATV", c.n_states, "at least 23 state variables (DEPVAR=23 on *SURFACE INTERACTION)");
      reject(c, kBadStateCount);
      stop_analysis();
      return;
    }
    if (c.n_props < mortar::kParameterCount) {
      report_argument(who, "NPROPS", c.n_props, "at least the 14 parameters of Table 1 (PROPERTIES=14 or more)");
      reject(c, kBadPropCount);
      stop_analysis();
      return;
    }
    double p[kReadPropCount] = {};
    const int n = std::min(c.n_props, kReadPropCount);
    std::copy(c.props, c.props + n, p);
    Setup setup;
    const mortar::ValidationError e = read_setup(p, n, kStandardDefaults, setup);
    if (!e.ok()) {
      report_property(who, e);
      reject(c, kBadProperty);
      stop_analysis();
      return;
    }
    integrate(who, c, setup);
  } catch (...) {
    report(who, "internal error: an exception escaped the law; the point keeps its start values");
    reject(c, kInternalError);
    stop_analysis();
  }
}

}  // namespace

extern "C" void uinter_(
    double* stress, double* ddsddr, double* /*amki*/, double* /*amski*/, double* flux, double* ddfddt,
    double* ddsddt, double* ddfddr, double* statev, double* sed, double* sfd, double* spd, double* svd,
    double* scd, double* pnewdt, const double* rdisp, const double* drdisp, const double* /*temp*/,
    const double* /*dtemp*/, const double* /*predef*/, const double* /*dpred*/, const double* /*time*/,
    const double* /*dtime*/, const double* /*freqr*/, const char* ciname, const char* /*slname*/,
    const char* /*msname*/, const double* props, const double* /*coords*/, const double* /*alocaldir*/,
    const double* /*drot*/, const double* /*area*/, const double* /*chrlngth*/, const int* node, const int* ndir,
    const int* nstatv, const int* /*npred*/, const int* nprops, const int* /*mcrd*/, const int* /*kstep*/,
    const int* /*kinc*/, const int* /*kit*/, const int* linper, int* /*lopenclose*/, int* /*lstate*/,
    int* /*lsdi*/, const int* /*lprint*/, int lenCiname, int /*lenSlname*/, int /*lenMsname*/) {
  Call c;
  c.n_dir = *ndir;
  c.n_states = *nstatv;
  c.n_props = *nprops;
  c.node = *node;
  c.perturbation = *linper == 1;
  c.rdisp = rdisp;
  c.drdisp = drdisp;
  c.props = props;
  c.stress = stress;
  c.ddsddr = ddsddr;
  c.statev = statev;
  c.flux = flux;
  c.ddfddt = ddfddt;
  c.ddsddt = ddsddt;
  c.ddfddr = ddfddr;
  c.sed = sed;
  c.sfd = sfd;
  c.spd = spd;
  c.svd = svd;
  c.scd = scd;
  c.pnewdt = pnewdt;
  run(make_caller("UINTER", ciname, lenCiname), c);
}
