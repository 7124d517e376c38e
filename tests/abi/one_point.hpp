// One contact point driven through vuinteraction_ (the routine's precision,
// mj_real) along a path of separation increments, and the same path through
// the law in double precision: what the precision tests compare. Arrays are
// allocated once, so that paths of 10^5..10^6 increments stay cheap.
#pragma once

#include <algorithm>
#include <vector>

#include "abi_support.hpp"
#include "mortar/integrator.hpp"
#include "mortar/state_layout.hpp"
#include "vuinteraction.h"

namespace mj_abi_test {

using Real = mj_real;

// VUINTERACTION with nBlock = 1, nDir = 3, `n_states` state variables.
struct OnePoint {
  int n_states, n_props;
  std::vector<Real> state, props;
  Real stress[3] = {}, sed = 0, spd = 0, sfd = 0, scd = 0, svd = 0, flux_slv = 0, flux_mst = 0;
  Real penetration = 0, dr_disp[3] = {};
  Real d_rot[4] = {1, 0, 0, 1}, dircos[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1}, one = 1, dircos_sl[3] = {1, 0, 0};
  Real shape_mst[4] = {}, coords[12] = {}, field[1] = {};
  int slave = 1001, masters[4] = {};
  Name80 name{"PRECISION"}, blank{""};

  OnePoint(std::vector<Real> p, int states) : n_states(states), n_props(int(p.size())), state(states, Real(0)),
                                              props(std::move(p)) {}

  void call() {
    const int n_block = 1, n_nod_state = 1, n_nod_slv = 1, n_nod_mst = 4, n_dir = 3, n_temp = 0, n_fields = 1;
    const int flags[3] = {1, 1, 0};
    const Real r_data[4] = {0, 0, Real(1e-7), 0};
    vuinteraction_(stress, &flux_slv, &flux_mst, state.data(), &sed, &sfd, &scd, &spd, &svd, &n_block, &n_block,
                   &n_block, &n_nod_state, &n_nod_slv, &n_nod_mst, &n_dir, &n_states, &n_props, &n_temp, &n_fields,
                   flags, r_data, name.text, blank.text, blank.text, &slave, masters, props.data(), &penetration,
                   dr_disp, d_rot, dircos, &one, &one, &one, dircos_sl, &one, shape_mst, coords, coords, coords, coords,
                   &one, &one, field, field, 80, 80, 80);
  }

  // The law's traction (law signs, default shear sign -1).
  mortar::Vec3 traction() const { return mortar::Vec3(-stress[0], -stress[1], -stress[2]); }
};

// A straight leg of a path: `count` increments of `d` (opening, slip 1).
struct Leg {
  double dn, ds;
  long count;
};

// The traction along a path, and the work done on it (trapezoidal rule).
struct Curve {
  std::vector<mortar::Vec3> traction;
  double work = 0;
  long failures = 0;  // increments rejected (SDV 21 != 0)
};

// The path through vuinteraction_: the first call (penetration 0) defines
// the zero; the opening goes in as -penetration, the slip as drDisp(2).
inline Curve run_routine(const std::vector<Real>& props, int n_states, const std::vector<Leg>& legs) {
  OnePoint pt(props, n_states);
  pt.call();
  Curve c;
  double opening = 0, slip = 0;
  mortar::Vec3 before = pt.traction(), at_before(0, 0, 0);
  for (const Leg& leg : legs) {
    const double start = opening;
    for (long i = 1; i <= leg.count; ++i) {
      opening = start + double(i) * leg.dn;
      pt.penetration = Real(-opening);
      pt.dr_disp[1] = Real(leg.ds);
      pt.call();
      slip += double(pt.dr_disp[1]);
      c.failures += pt.state[mortar::slot::status] != Real(0);
      const mortar::Vec3 at(-double(pt.penetration), slip, 0), now = pt.traction();
      c.work += 0.5 * (before + now).dot(at - at_before);
      c.traction.push_back(now);
      before = now;
      at_before = at;
    }
  }
  return c;
}

// The same path through the law in double precision (what the
// double-precision routine computes: it agrees with the law to 1e-9 ft0,
// abi_tests.cpp).
inline Curve run_law(const mortar::Model& M, const std::vector<Leg>& legs) {
  mortar::State s;
  Curve c;
  double opening = 0;
  mortar::Vec3 before(0, 0, 0);
  for (const Leg& leg : legs) {
    const double start = opening;
    for (long i = 1; i <= leg.count; ++i) {
      const double next = start + double(i) * leg.dn;
      const mortar::Vec3 d(next - opening, leg.ds, 0);
      const mortar::IncrementResult r = mortar::integrate_increment(M, s, d);
      c.failures += !r.status.ok();
      c.work += 0.5 * (before + r.traction).dot(d);
      c.traction.push_back(r.traction);
      before = r.traction;
      opening = next;
    }
  }
  return c;
}

}  // namespace mj_abi_test
