// One UINTER contact point as the Catch2 tests call it (uinter_tests.cpp):
// every argument of the call, always double precision, and a driver along a
// straight path of RDISP in converged increments.
#pragma once

#include <algorithm>
#include <utility>
#include <vector>

#include <catch2/catch.hpp>

#include "abi_support.hpp"
#include "mortar/state_layout.hpp"
#include "vuinteraction.h"

namespace mj_abi_test {

// One contact point as Abaqus/Standard passes it. `statev` is the state at
// the start of the increment (the caller's copy); call() works on a copy of
// it, as Abaqus does, and leaves the end state in `out_statev`.
struct Point {
  int n_dir, n_states = mortar::kStateCount, linper = 0, node = 4711;
  std::vector<double> props;
  std::vector<double> statev, out_statev;
  double stress[3] = {}, ddsddr[9] = {}, rdisp[3] = {}, drdisp[3] = {};
  double drot[4] = {1, 0, 0, 1};  // DROT(2,2): the tangent directions do not turn unless a test says so
  double sed = 0, sfd = 0, spd = 0, svd = 0, scd = 0, pnewdt = 0;
  double flux[2] = {7, 7}, ddfddt[4] = {7, 7, 7, 7}, ddsddt[6] = {7, 7, 7, 7, 7, 7}, ddfddr[6] = {7, 7, 7, 7, 7, 7};
  Name80 name{"MORTAR-STD"};

  Point(int dir, std::vector<double> p) : n_dir(dir), props(std::move(p)), statev(mortar::kStateCount, 0.0) {}

  void call() {
    out_statev = statev;
    double amki[9] = {}, amski[9] = {}, temp[2] = {}, dtemp[2] = {}, predef[2] = {}, dpred[2] = {}, time[2] = {};
    double coords[3] = {}, alocal[9] = {};
    const double dtime = 0.01, freqr = 0, area = 1, chrlngth = 10;
    const int npred = 1, nprops = int(props.size()), mcrd = 3, kstep = 1, kinc = 1, kit = 0, lprint = 0;
    int lopenclose = -1, lstate = -1, lsdi = 0;
    const Name80 blank("");
    pnewdt = 1e36;
    uinter_(stress, ddsddr, amki, amski, flux, ddfddt, ddsddt, ddfddr, out_statev.data(), &sed, &sfd, &spd, &svd,
            &scd, &pnewdt, rdisp, drdisp, temp, dtemp, predef, dpred, time, &dtime, &freqr, name.text, blank.text,
            blank.text, props.data(), coords, alocal, drot, &area, &chrlngth, &node, &n_dir, &n_states, &npred,
            &nprops, &mcrd, &kstep, &kinc, &kit, &linper, &lopenclose, &lstate, &lsdi, &lprint, 80, 80, 80);
    CHECK(lopenclose == -1);  // not used: left as it came
    CHECK(lsdi == 0);
  }
  // Moves to the relative position `r` (RDISP at the end of the increment)
  // from `r0` (the start), as one increment.
  void to(const double* r0, const double* r) {
    for (int i = 0; i < n_dir; ++i) {
      rdisp[i] = r[i];
      drdisp[i] = r[i] - r0[i];
    }
    call();
  }
  // Commits the increment (Abaqus: converged).
  void commit() { statev = out_statev; }
  double D(int i, int j) const { return ddsddr[i + j * n_dir]; }
};

// Drives a point along a straight path of RDISP in n converged increments.
inline void drive(Point& pt, double* r, const double* target, int n) {
  double start[3];
  for (int k = 0; k < n; ++k) {
    std::copy(r, r + 3, start);
    for (int i = 0; i < 3; ++i) r[i] = start[i] + (target[i] - start[i]) / (n - k);
    pt.to(start, r);
    REQUIRE(pt.pnewdt >= 1);
    pt.commit();
  }
}

}  // namespace mj_abi_test
