// Abaqus/Standard's contact point (UINTER) over the law, always in double
// precision. One call per contact point and per equilibrium iteration;
// Abaqus passes the state at the start of the increment every time, and
// keeps what the call returns only when the increment converges. This is
// where Abaqus/Standard's conventions meet the law's (docs/abaqus.md, "Using
// it in Abaqus/Standard"; law signs: docs/model.md 1):
// The rest: docs/adapters.md, section 6.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "adapter/arguments.hpp"
#include "adapter/report.hpp"
#include "adapter/rotation.hpp"
#include "mortar/integrator.hpp"
#include "mortar/state_layout.hpp"

namespace mj_adapter {

constexpr double kCutBack = 0.5;  // PNEWDT asked for when the law fails

// Abaqus/Standard: props(15) = 0 is the implicit scheme, props(20) = 0 is +1.
constexpr Defaults kStandardDefaults = {mortar::Scheme::implicit, 1.0, "props(20) is 0 (default, = +1), -1 or +1"};

// The arguments UINTER reads or writes, in the adapter's own terms.
struct StandardPoint {
  Counts counts;
  int node = 0;
  bool perturbation = false;  // LINPER = 1
  const double* rdisp = nullptr;
  const double* drdisp = nullptr;
  const double* drot = nullptr;  // DROT(2,2)
  const double* props = nullptr;
  double *stress = nullptr, *ddsddr = nullptr, *statev = nullptr;
  double *flux = nullptr, *ddfddt = nullptr, *ddsddt = nullptr, *ddfddr = nullptr;
  double *sed = nullptr, *sfd = nullptr, *spd = nullptr, *svd = nullptr, *scd = nullptr, *pnewdt = nullptr;

  // A rejected call (bad argument or property): finite outputs as far as
  // the declared arrays reach, and the code in SDV 21.
  void reject(int code) const {
    const int n_dir = counts.n_dir;
    if (n_dir >= 1 && n_dir <= 3) {
      for (int i = 0; i < n_dir; ++i) stress[i] = std::isfinite(stress[i]) ? stress[i] : 0.0;
      std::fill(ddsddr, ddsddr + n_dir * n_dir, 0.0);
      write_unused();
    } else {
      *sfd = *svd = *scd = 0;
    }
    *sed = std::isfinite(*sed) ? *sed : 0.0;
    *spd = 0;
    if (counts.n_states > mortar::slot::status) statev[mortar::slot::status] = code;
  }

  // DROT's rule where it is used (3D, a paired point, not a perturbation):
  // a rotation. Reports a break and returns its adapter code, or 0.
  int check_points(const Caller& who, const ArgumentNames& names) const {
    if (counts.n_dir != 3 || perturbation || rdisp[0] <= kUnpairedPenetration) return 0;
    const RotationCheck c = check_rotation(drot);
    if (c.ok()) return 0;
    char where[48];
    std::snprintf(where, sizeof where, "node %d", node);
    report_rotation(who, names.rotation, "", where, drot, c);
    return kBadRotation;
  }

  // The law over this point. A rejected increment asks Abaqus for a smaller
  // one (PNEWDT) rather than stopping: always true.
  bool integrate(const Caller& who, const Setup& setup) const {
    write_unused();
    if (rdisp[0] <= kUnpairedPenetration) {  // no opposite surface: no interaction
      std::fill(stress, stress + counts.n_dir, 0.0);
      std::fill(ddsddr, ddsddr + counts.n_dir * counts.n_dir, 0.0);
      *sed = *spd = 0;
      return true;
    }
    if (perturbation) {
      integrate_perturbation(setup);
    } else {
      integrate_step(who, setup);
    }
    return true;
  }

 private:
  // No heat and no temperature dependence; no friction, viscous or creep
  // dissipation booked apart from the law's plasticity.
  void write_unused() const {
    flux[0] = flux[1] = 0;
    std::fill(ddfddt, ddfddt + 4, 0.0);
    std::fill(ddsddt, ddsddt + 2 * counts.n_dir, 0.0);
    std::fill(ddfddr, ddfddr + 2 * counts.n_dir, 0.0);
    *sfd = *svd = *scd = 0;
  }

  // Abaqus's STRESS and DDSDDR from the law's traction and tangent:
  // STRESS = C sigma, DDSDDR = C T D (see the top of this file).
  void write_stress(const Setup& setup, const mortar::Vec3& traction, const mortar::Mat3& tangent) const {
    const mortar::Vec3 C(-1.0, setup.shear_sign, setup.shear_sign);
    const mortar::Vec3 D(-1.0, 1.0, 1.0);
    const int n_dir = counts.n_dir;
    for (int i = 0; i < n_dir; ++i) {
      stress[i] = C[i] * traction[i];
      for (int j = 0; j < n_dir; ++j) ddsddr[i + j * n_dir] = C[i] * tangent(i, j) * D[j];
    }
  }

  // Linear perturbation: the tangent of the base state (a zero increment
  // from it, i.e. its secant stiffness), applied to the perturbation; the
  // base state is not changed.
  void integrate_perturbation(const Setup& setup) const {
    mortar::State base;
    mortar::load_state(statev, base);
    if (setup.model.cap.on()) base.kappa_c = mortar::load_kappa_c(statev);
    mortar::Mat3 T;
    const mortar::IncrementResult r = mortar::integrate_increment(setup.model, base, mortar::Vec3::Zero(), &T);
    mortar::Vec3 d_rdisp = mortar::Vec3::Zero();
    for (int i = 0; i < counts.n_dir; ++i) d_rdisp[i] = drdisp[i];
    const mortar::Vec3 D(-1.0, 1.0, 1.0);
    write_stress(setup, T * D.cwiseProduct(d_rdisp), T);
    *sed = *spd = 0;
    if (!r.status.ok()) *pnewdt = std::min(*pnewdt, kCutBack);
  }

  void integrate_step(const Caller& who, const Setup& setup) const {
    namespace slot = mortar::slot;
    double* st = statev;
    // SDV 35, the integration flags, with NSTATV >= 35 (docs/abaqus.md).
    const bool flags = counts.n_states >= mortar::kFlaggedStateCount;
    // SDV 36, kappa_c, with a cap (run_call checked NSTATV >= 36).
    const bool cap = setup.model.cap.on();
    if (!mortar::adapter_slots_valid(st, flags) ||
        (cap && !mortar::kappa_c_valid(mortar::load_kappa_c(st)))) {  // as the law's own rejections
      reject(static_cast<int>(mortar::Failure::invalid_state));
      *pnewdt = std::min(*pnewdt, kCutBack);
      report_rejected(who, mortar::Failure::invalid_state);
      return;
    }
    mortar::State s;
    mortar::load_state(st, s);
    if (flags) s.integration_flags = mortar::load_integration_flags(st);
    if (cap) s.kappa_c = mortar::load_kappa_c(st);
    if (counts.n_dir == 3) rotate_tangential_state(drot, s);
    const bool first = st[slot::initialised] == 0.0;
    // The reference is the start-of-increment position, the same in every
    // iteration of the first increment (RDISP - DRDISP).
    const double reference = first ? rdisp[0] - drdisp[0] : st[slot::reference_penetration];
    mortar::Vec3 d((reference - rdisp[0]) - s.separation[0], rdisp[1] - s.separation[1],
                   counts.n_dir > 2 ? rdisp[2] - s.separation[2] : 0.0);
    if (!std::isfinite(reference)) d[0] = NAN;  // rejected by the law below
    mortar::Mat3 T;
    const mortar::IncrementResult r = mortar::integrate_increment(setup.model, s, d, &T);
    mortar::store_state(s, st);
    if (flags) mortar::store_integration_flags(s.integration_flags, st);
    if (cap) mortar::store_kappa_c(s.kappa_c, st);
    write_stress(setup, r.traction, T);
    *sed = r.elastic_energy;
    *spd = r.d_inelastic();
    if (!r.status.ok()) {
      // The start state is kept (with the code in SDV 21); Abaqus abandons
      // the increment and retries with PNEWDT times the time increment.
      *pnewdt = std::min(*pnewdt, kCutBack);
      report_rejected(who, r.status.failure);
      return;
    }
    if (first) {
      st[slot::reference_penetration] = reference;
      st[slot::initialised] = 1;
    }
  }

  void report_rejected(const Caller& who, mortar::Failure failure) const {
    char what[400];
    std::snprintf(what, sizeof what,
                  "node %d: the law rejected the increment: %s (SDV 21 = %d); asking for a smaller increment "
                  "(PNEWDT = %g)",
                  node, mortar::failure_name(failure), int(failure), kCutBack);
    report(who, what);
  }
};

}  // namespace mj_adapter
