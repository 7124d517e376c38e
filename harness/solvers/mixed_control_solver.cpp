#include "solvers/mixed_control_solver.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "abi/status.hpp"
#include "abi/vuinteraction_caller.hpp"
#include "mortar/state_layout.hpp"

namespace mortar::harness {

namespace {
// Forward-difference step for a separation increment x [mm]: relative to the
// increment, floored at 1e-10 mm (far above round-off of separations near
// 1e-3 mm, far below any increment a solver takes).
double difference_step(double x) { return 1e-7 * (std::abs(x) + 1e-3); }
}  // namespace

MixedControlSolver::MixedControlSolver(const AbiSetup& setup, int first_point, int n_points, const MixedControlOptions& options)
    : MixedControlSolver(std::make_unique<VuinteractionCaller>(setup, n_points, first_point), first_point,
                  Eigen::Vector3d(setup.props.at(0), setup.props.at(1), setup.props.at(1)), options) {}

MixedControlSolver::MixedControlSolver(std::unique_ptr<Caller> caller, int first_point, const Eigen::Vector3d& elastic_stiffness,
                         const MixedControlOptions& options)
    : caller_(std::move(caller)), first_point_(first_point), elastic_stiffness_(elastic_stiffness),
      options_(options) {
  const size_t n = static_cast<size_t>(caller_->size());
  accepted_traction_.assign(n, Vec3::Zero());
  results_.assign(n, PointResult{});
  d_.assign(n, Vec3::Zero());
  dx_ = trial_ = trial_traction_ = residual_ = d_;
  jacobian_.assign(n, Mat3::Identity());
  lambda_.assign(n, 1.0);
  ok_.assign(n, 0);
  converged_ = pending_ = use_elastic_ = stalled_ = ok_;
  iterations_.assign(n, 0);
  sweeps_.assign(n, 0);
  brackets_.assign(n, Bracket{});
}

void MixedControlSolver::evaluate(const std::vector<Vec3>& candidate, const CallTime& info) {
  for (int k = 0; k < size(); ++k) caller_->set_trial(k, results_[k].separation + candidate[k], candidate[k]);
  caller_->call(info);
  ++calls_;
  for (int k = 0; k < size(); ++k) {
    trial_traction_[k] = caller_->traction(k);
    ok_[k] = caller_->status(k) == 0.0 && trial_traction_[k].allFinite();
  }
}

void MixedControlSolver::keep(int k) {
  caller_->accept(k);
  accepted_traction_[k] = trial_traction_[k];
}

void MixedControlSolver::commit() {
  caller_->commit();
  for (int k = 0; k < size(); ++k) {
    PointResult& r = results_[k];
    r.separation += d_[k];
    r.increment = d_[k];
    r.start_traction = r.traction;
    r.traction = accepted_traction_[k];
    r.elastic_energy = caller_->elastic_energy(k);
    r.dissipation_increment = caller_->dissipation_increment(k);
    r.iterations = iterations_[k];
  }
}

MixedControlSolver::Vec3 MixedControlSolver::residual_of(int k, const PointTargets& t) const {
  Vec3 r = Vec3::Zero();
  for (int j = 0; j < 3; ++j)
    if (free_component(t, j)) r[j] = trial_traction_[k][j] - t.value[j];
  return r;
}

void MixedControlSolver::fail(int k, const CallTime& info, const std::string& why) const {
  std::ostringstream msg;
  msg << failure_location(first_point_ + k, info.step, info.increment) << why;
  const double status = caller_->status(k);
  if (status != 0.0) {
    msg << " (the routine reported status " << status << " in SDV" << slot::status + 1 << ": "
        << status_meaning(status) << ")";
  }
  throw RunFailure(msg.str());
}

void MixedControlSolver::reference_call(const CallTime& info) {
  for (int k = 0; k < size(); ++k) d_[k].setZero();
  evaluate(d_, info);
  for (int k = 0; k < size(); ++k) {
    if (!ok_[k]) fail(k, info, "the first (reference) call failed");
    keep(k);
    iterations_[k] = 0;
    results_[k].traction_residual = 0;
  }
  commit();
}

void MixedControlSolver::advance(const PointTargets* targets, const CallTime& info) {
  start(targets, info);
  const double tol = options_.traction_tolerance;
  for (int iteration = 1; iteration <= options_.max_iterations; ++iteration) {
    if (std::all_of(converged_.begin(), converged_.end(), [](char c) { return c != 0; })) break;
    newton_step(targets, info);
    if (std::any_of(stalled_.begin(), stalled_.end(), [](char c) { return c != 0; })) bracket_sweep(targets, info);
  }
  for (int k = 0; k < size(); ++k) {
    if (converged_[k]) continue;
    std::ostringstream why;
    why << "the traction target was not reached within " << options_.max_iterations
        << " iterations: residual " << max_abs(residual_[k]) << " MPa, tolerance " << tol << " MPa";
    fail(k, info, why.str());
  }
  commit();
  for (int k = 0; k < size(); ++k) results_[k].traction_residual = max_abs(residual_[k]);
}

// Predictor and first evaluation. Displacement-controlled components are
// known; free ones start from the previous increment of the same point (a
// secant predictor), or from rest when that call fails.
void MixedControlSolver::start(const PointTargets* targets, const CallTime& info) {
  const int n = size();
  bool any_free = false;
  for (int k = 0; k < n; ++k) {
    const PointTargets& t = targets[k];
    for (int j = 0; j < 3; ++j) {
      if (free_component(t, j)) {
        d_[k][j] = results_[k].increment[j];
        any_free = true;
      } else {
        d_[k][j] = t.value[j] - results_[k].separation[j];
      }
    }
    iterations_[k] = sweeps_[k] = 0;
    use_elastic_[k] = stalled_[k] = 0;
  }
  evaluate(d_, info);
  bool retry = false;
  for (int k = 0; k < n; ++k) {
    if (ok_[k]) continue;
    if (!any_free) fail(k, info, "the call failed");
    for (int j = 0; j < 3; ++j)
      if (free_component(targets[k], j)) d_[k][j] = 0;
    retry = true;
  }
  if (retry) evaluate(d_, info);
  for (int k = 0; k < n; ++k) {
    if (!ok_[k]) fail(k, info, "the call failed");
    keep(k);
    residual_[k] = residual_of(k, targets[k]);
    converged_[k] = max_abs(residual_[k]) <= options_.traction_tolerance;
  }
}

// One Newton update of every unconverged point: forward-difference Jacobian
// (one call per free component, all points perturbed at once), then
// backtracking. A point whose step reduces nothing even with the elastic
// Jacobian is marked stalled.
void MixedControlSolver::newton_step(const PointTargets* targets, const CallTime& info) {
  const int n = size();
  const double tol = options_.traction_tolerance;
  for (int k = 0; k < n; ++k) jacobian_[k].setIdentity();
  for (int j = 0; j < 3; ++j) {
    bool needed = false;
    for (int k = 0; k < n; ++k) {
      trial_[k] = d_[k];
      if (!converged_[k] && !use_elastic_[k] && free_component(targets[k], j)) {
        trial_[k][j] += difference_step(d_[k][j]);
        needed = true;
      }
    }
    if (!needed) continue;
    evaluate(trial_, info);
    for (int k = 0; k < n; ++k) {
      if (converged_[k] || use_elastic_[k] || !free_component(targets[k], j)) continue;
      if (!ok_[k]) {
        use_elastic_[k] = 1;
        continue;
      }
      const double h = trial_[k][j] - d_[k][j];
      for (int i = 0; i < 3; ++i)
        if (free_component(targets[k], i))
          jacobian_[k](i, j) = (trial_traction_[k][i] - accepted_traction_[k][i]) / h;
    }
  }
  for (int k = 0; k < n; ++k) {
    pending_[k] = 0;
    if (converged_[k]) continue;
    ++iterations_[k];
    // The undamaged elastic stiffness: the Jacobian of a closed elastic
    // joint, used when the finite differences are unusable.
    const Mat3 elastic = elastic_stiffness_.asDiagonal();
    Vec3 step = -solve_on_free(targets[k], use_elastic_[k] ? elastic : jacobian_[k], residual_[k]);
    if (!step.allFinite() || step.isZero(0.0)) step = -solve_on_free(targets[k], elastic, residual_[k]);
    dx_[k] = step;
    lambda_[k] = 1.0;
    pending_[k] = 1;
  }
  for (int halving = 0; halving <= options_.max_halvings; ++halving) {
    bool any = false;
    for (int k = 0; k < n; ++k) {
      trial_[k] = pending_[k] ? Vec3(d_[k] + lambda_[k] * dx_[k]) : d_[k];
      any = any || pending_[k];
    }
    if (!any) break;
    evaluate(trial_, info);
    for (int k = 0; k < n; ++k) {
      if (!pending_[k]) continue;
      const Vec3 r = residual_of(k, targets[k]);
      if (ok_[k] && max_abs(r) < max_abs(residual_[k])) {
        d_[k] = trial_[k];
        keep(k);
        residual_[k] = r;
        converged_[k] = max_abs(r) <= tol;
        pending_[k] = 0;
      } else {
        lambda_[k] *= 0.5;
      }
    }
  }
  for (int k = 0; k < n; ++k) {
    if (!pending_[k]) continue;
    // No decrease along this direction: the finite-difference Jacobian
    // straddled a kink, or the residual has a local minimum here. Try the
    // elastic Jacobian once, then bracket.
    if (use_elastic_[k]) stalled_[k] = 1;
    use_elastic_[k] = 1;
  }
}

}  // namespace mortar::harness
