// A material-point driver with mixed control (as MFront's MTest): each
// component of the separation is either imposed, or free with its traction
// imposed. A traction-controlled increment is solved the way a solver would:
// Newton iterations on the free separation increments from a copy of the
// state at the start of the increment, then commit.
#pragma once

#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>

#include <Eigen/Dense>

#include "mortar/integrator.hpp"

namespace mortar::harness {

// One increment of one point: (state at start, separation increment) -> end
// state and result. The law itself, or a stepper through an ABI entry point.
using PointStepper = std::function<IncrementResult(State&, const Vec3&)>;

inline PointStepper law_stepper(const Model& model) {
  return [&model](State& s, const Vec3& d) { return integrate_increment(model, s, d); };
}

struct ComponentControl {
  bool traction_controlled = false;
  double target = 0;  // separation increment [mm], or traction at the end of the increment [MPa]
};

struct MixedIncrement {
  ComponentControl c[3];
};

struct MixedSolveOptions {
  double traction_tol = 1e-10;  // |sigma_j - target_j| [MPa] accepted
  int max_iterations = 50;
  double stiffness_guess = 0;   // initial Jacobian diagonal; 0 = finite differences
};

struct MixedResult {
  IncrementResult result;
  Vec3 d_separation = Vec3::Zero();  // the increment that was committed
  int iterations = 0;
  double residual = 0;  // max |sigma_j - target_j| after the last iteration
};

// Solves one mixed-control increment and commits it to `state`. Throws
// std::runtime_error when the traction cannot be reached within the options.
inline MixedResult solve_mixed(const PointStepper& step, State& state, const MixedIncrement& inc,
                               const MixedSolveOptions& opt = {}) {
  int free_idx[3], nf = 0;
  Vec3 d = Vec3::Zero();
  for (int i = 0; i < 3; ++i) {
    if (inc.c[i].traction_controlled) free_idx[nf++] = i;
    else d[i] = inc.c[i].target;
  }
  MixedResult out;
  auto trial = [&](const Vec3& dd, State& s) {
    s = state;
    return step(s, dd);
  };
  State s;
  if (nf == 0) {
    out.result = trial(d, s);
    out.d_separation = d;
    state = s;
    return out;
  }
  auto residual = [&](const IncrementResult& r) {
    Eigen::VectorXd res(nf);
    for (int j = 0; j < nf; ++j) res[j] = r.traction[free_idx[j]] - inc.c[free_idx[j]].target;
    return res;
  };
  IncrementResult r = trial(d, s);
  Eigen::VectorXd res = residual(r);
  for (int it = 0; it < opt.max_iterations; ++it) {
    out.iterations = it;
    if (res.cwiseAbs().maxCoeff() <= opt.traction_tol) break;
    // Jacobian of the free tractions by forward differences of the increment.
    Eigen::MatrixXd J(nf, nf);
    for (int j = 0; j < nf; ++j) {
      const double h = 1e-7 * (std::abs(d[free_idx[j]]) + 1e-4);
      Vec3 dh = d;
      dh[free_idx[j]] += h;
      State sh;
      const Eigen::VectorXd rh = residual(trial(dh, sh));
      J.col(j) = (rh - res) / h;
    }
    Eigen::VectorXd dx = -J.fullPivLu().solve(res);
    if (!dx.allFinite()) throw std::runtime_error("mixed control: singular traction Jacobian");
    // Backtracking: halve the correction until the residual decreases.
    double lambda = 1;
    for (int ls = 0; ls < 30; ++ls) {
      Vec3 dn = d;
      for (int j = 0; j < nf; ++j) dn[free_idx[j]] += lambda * dx[j];
      State sn;
      IncrementResult rn = trial(dn, sn);
      Eigen::VectorXd resn = residual(rn);
      if (resn.norm() < res.norm() || ls == 29) {
        d = dn;
        r = rn;
        s = sn;
        res = resn;
        break;
      }
      lambda *= 0.5;
    }
  }
  out.residual = res.cwiseAbs().maxCoeff();
  if (!(out.residual <= opt.traction_tol))
    throw std::runtime_error("mixed control: traction not reached, residual " + std::to_string(out.residual) +
                             " MPa");
  out.result = r;
  out.d_separation = d;
  state = s;
  return out;
}

}  // namespace mortar::harness
