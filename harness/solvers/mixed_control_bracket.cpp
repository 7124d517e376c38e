// The mixed-control solver's rescue of a stalled Newton iteration: each free
// component of each stalled point solved alone by bracketing (expansion from
// the point's elastic stiffness, then Illinois), Gauss-Seidel over the
// components. Every trial is a call of the whole group, as in
// mixed_control_solver.cpp.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "solvers/mixed_control_solver.hpp"

namespace mortar::harness {

// Solves the free components of the stalled points one after the other
// (Gauss-Seidel), each by bracketing; Newton resumes afterwards.
void MixedControlSolver::bracket_sweep(const PointTargets* targets, const CallTime& info) {
  for (int j = 0; j < 3; ++j) bracket_component(j, targets, info);
  for (int k = 0; k < size(); ++k) {
    if (!stalled_[k]) continue;
    stalled_[k] = 0;
    use_elastic_[k] = 0;
    if (++sweeps_[k] > options_.max_sweeps && !converged_[k]) {
      std::ostringstream why;
      why << "the traction target was not reached after " << options_.max_sweeps
          << " bracketing sweeps: residual " << max_abs(residual_[k]) << " MPa";
      fail(k, info, why.str());
    }
  }
}

void MixedControlSolver::bracket_component(int j, const PointTargets* targets, const CallTime& info) {
  const int n = size();
  const double tol = options_.traction_tolerance;
  bool any = false;
  for (int k = 0; k < n; ++k) {
    Bracket& b = brackets_[k];
    b.phase = Bracket::idle;
    if (!stalled_[k] || !free_component(targets[k], j) || std::abs(residual_[k][j]) <= tol) continue;
    b = Bracket{};
    b.phase = Bracket::expanding;
    b.x0 = d_[k][j];
    b.f0 = residual_[k][j];
    // First step: what the undamaged elastic stiffness says would close the gap.
    b.step = -b.f0 / elastic_stiffness_[j];
    b.direction = 1;
    b.a = b.x0;
    b.fa = b.f0;
    any = true;
  }
  while (any) {
    any = false;
    for (int k = 0; k < n; ++k) {
      trial_[k] = d_[k];
      Bracket& b = brackets_[k];
      if (b.phase == Bracket::expanding) {
        b.x = b.x0 + b.direction * b.step;
      } else if (b.phase == Bracket::refining) {
        // Illinois: the secant through the bracket, ends weighted so that
        // the same end is not kept forever.
        b.x = b.fb != b.fa ? b.b - b.fb * (b.b - b.a) / (b.fb - b.fa) : 0.5 * (b.a + b.b);
        if (!(b.x > std::min(b.a, b.b) && b.x < std::max(b.a, b.b))) b.x = 0.5 * (b.a + b.b);
      } else {
        continue;
      }
      trial_[k][j] = b.x;
      any = true;
    }
    if (!any) break;
    evaluate(trial_, info);
    for (int k = 0; k < n; ++k) {
      Bracket& b = brackets_[k];
      if (b.phase != Bracket::expanding && b.phase != Bracket::refining) continue;
      const Vec3 r = residual_of(k, targets[k]);
      const double f = r[j];
      if (ok_[k] && std::abs(f) <= tol) {  // this component is solved: take it
        d_[k] = trial_[k];
        keep(k);
        residual_[k] = r;
        converged_[k] = max_abs(r) <= tol;
        b.phase = Bracket::done;
        continue;
      }
      if (b.phase == Bracket::expanding) {
        if (ok_[k] && (f > 0) != (b.f0 > 0)) {  // sign change: bracketed
          b.b = b.x;
          b.fb = f;
          b.phase = Bracket::refining;
          continue;
        }
        if (ok_[k]) {  // same sign: move the near end along and grow the step
          b.a = b.x;
          b.fa = f;
        }
        b.step *= 2;
        if (!ok_[k] || ++b.doublings > options_.max_doublings) {
          // Nothing this way (or the routine refused the trial): search the
          // other way from the start, once.
          if (++b.turns > 1) {
            b.phase = Bracket::failed;
            continue;
          }
          b.direction = -b.direction;
          b.step = std::abs(b.f0 / elastic_stiffness_[j]);
          b.doublings = 0;
          b.a = b.x0;
          b.fa = b.f0;
        }
        continue;
      }
      // Refining.
      if (!ok_[k] || ++b.refinements > options_.max_refinements) {
        b.phase = Bracket::failed;
        continue;
      }
      // Illinois (Dowell and Jarratt): the root stays between a and b; when
      // the new point does not change sign, the kept end's value is halved
      // so that the secant does not stall on one side.
      if ((f > 0) != (b.fb > 0)) {
        b.a = b.b;
        b.fa = b.fb;
      } else {
        b.fa *= 0.5;
      }
      b.b = b.x;
      b.fb = f;
      if (std::abs(b.b - b.a) <= 1e-15 * std::max(std::abs(b.a), std::abs(b.b))) b.phase = Bracket::failed;
    }
  }
  for (int k = 0; k < n; ++k) {
    const Bracket& b = brackets_[k];
    if (b.phase != Bracket::failed) continue;
    std::ostringstream why;
    why << "the traction target of component " << kComponentNames[j] << " cannot be reached: ";
    if (b.refinements > 0) {
      // A sign change that does not close: the traction jumps across the
      // target (the routine's response is only piecewise continuous, e.g.
      // where its number of substeps changes).
      why << "the traction jumps across the target between increments " << b.a << " and " << b.b
          << " mm; loosen --traction-tol or tighten --stol";
    } else {
      why << "no separation increment brings the residual " << std::abs(residual_[k][j])
          << " MPa to zero (beyond a peak under traction control?)";
    }
    fail(k, info, why.str());
  }
}

}  // namespace mortar::harness
