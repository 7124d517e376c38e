#include "block_solver.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <Eigen/LU>

#include "abi_signs.hpp"
#include "mortar/integrator.hpp"
#include "mortar/state.hpp"

namespace mortar::harness {

namespace {
bool free_component(const PointTargets& t, int j) { return t.kind[j] == Control::traction; }

double max_abs(const Eigen::Vector3d& v) { return v.cwiseAbs().maxCoeff(); }

// Forward-difference step for a separation increment x [mm]: relative to the
// increment, floored at 1e-10 mm (far above round-off of separations near
// 1e-3 mm, far below any increment a solver takes).
double difference_step(double x) { return 1e-7 * (std::abs(x) + 1e-3); }

// What a status in SDV21 means (docs/abaqus.md): the law's failure codes are
// positive, the adapter's argument and property codes negative.
std::string status_meaning(double status) {
  if (status > 0) return failure_name(static_cast<Failure>(static_cast<int>(status)));
  switch (static_cast<int>(status)) {
    case -1: return "nDir is not 2 or 3";
    case -2: return "fewer than 23 state variables";
    case -3: return "fewer than 14 properties";
    case -4: return "a property breaks its rule (the routine's message on stderr names it)";
    case -5: return "nNodState < 1";
    default: return "the routine's internal error";
  }
}
}  // namespace

BlockSolver::BlockSolver(const AbiSetup& setup, int first_point, int n_points, const MixedControlOptions& options)
    : setup_(setup), first_point_(first_point), options_(options), abi_(setup, n_points, first_point) {
  const size_t n = static_cast<size_t>(n_points);
  elastic_stiffness_ = Eigen::Vector3d(setup.props.at(0), setup.props.at(1), setup.props.at(1));
  committed_stress_.assign(abi_.stress_array().size(), 0.0);
  committed_state_.assign(abi_.state_array().size(), 0.0);
  committed_sed_.assign(n, 0.0);
  accepted_stress_ = committed_stress_;
  accepted_state_ = committed_state_;
  accepted_sed_ = committed_sed_;
  accepted_spd_.assign(n, 0.0);
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

void BlockSolver::evaluate(const std::vector<Vec3>& candidate, const CallInfo& info) {
  // Every trial starts from the committed arrays: the routine may overwrite
  // stress, state and sed in place.
  std::copy(committed_stress_.begin(), committed_stress_.end(), abi_.stress_array().begin());
  std::copy(committed_state_.begin(), committed_state_.end(), abi_.state_array().begin());
  std::copy(committed_sed_.begin(), committed_sed_.end(), abi_.sed_array().begin());
  const int nd = abi_.n_dir();
  for (int k = 0; k < size(); ++k) {
    const Vec3& d = candidate[k];
    abi_.penetration(k) = abi_signs::penetration_for_opening(results_[k].separation[0] + d[0]);
    double* dr = abi_.dr_disp(k);
    dr[0] = abi_signs::normal_dr_disp(d[0]);
    for (int i = 1; i < nd; ++i) dr[i] = abi_signs::kSlipSign * d[i];
  }
  abi_.invoke(info);
  ++calls_;
  for (int k = 0; k < size(); ++k) {
    const double* s = abi_.stress(k);
    Vec3 t(abi_signs::normal_traction_from_stress(s[0]), 0.0, 0.0);
    for (int i = 1; i < nd; ++i) t[i] = abi_signs::kShearSign * s[i];
    trial_traction_[k] = t;
    ok_[k] = abi_.state(k)[slot::status] == 0.0 && t.allFinite();
  }
}

void BlockSolver::keep(int k) {
  const int nd = abi_.n_dir(), ns = abi_.n_states();
  std::copy_n(abi_.stress(k), nd, &accepted_stress_[static_cast<size_t>(k) * nd]);
  std::copy_n(abi_.state(k), ns, &accepted_state_[static_cast<size_t>(k) * ns]);
  accepted_sed_[k] = abi_.sed(k);
  accepted_spd_[k] = abi_.spd(k);
  accepted_traction_[k] = trial_traction_[k];
}

void BlockSolver::commit() {
  committed_stress_ = accepted_stress_;
  committed_state_ = accepted_state_;
  committed_sed_ = accepted_sed_;
  for (int k = 0; k < size(); ++k) {
    PointResult& r = results_[k];
    r.separation += d_[k];
    r.increment = d_[k];
    r.start_traction = r.traction;
    r.traction = accepted_traction_[k];
    r.elastic_energy = accepted_sed_[k];
    r.dissipation_increment = accepted_spd_[k];
    r.iterations = iterations_[k];
  }
}

BlockSolver::Vec3 BlockSolver::residual_of(int k, const PointTargets& t) const {
  Vec3 r = Vec3::Zero();
  for (int j = 0; j < 3; ++j)
    if (free_component(t, j)) r[j] = trial_traction_[k][j] - t.value[j];
  return r;
}

// The undamaged elastic stiffness on the free components: the Jacobian of a
// closed elastic joint, used when the finite differences are unusable.
BlockSolver::Mat3 BlockSolver::elastic_jacobian(const PointTargets& t) const {
  Mat3 J = Mat3::Identity();
  for (int j = 0; j < 3; ++j)
    if (free_component(t, j)) J(j, j) = elastic_stiffness_[j];
  return J;
}

void BlockSolver::fail(int k, const CallInfo& info, const std::string& why) const {
  std::ostringstream msg;
  msg << "point " << first_point_ + k + 1 << ", step " << info.step << ", increment " << info.increment << ": "
      << why;
  const double status = abi_.state(k)[slot::status];
  if (status != 0.0) {
    msg << " (the routine reported status " << status << " in SDV" << slot::status + 1 << ": "
        << status_meaning(status) << ")";
  }
  throw RunFailure(msg.str());
}

void BlockSolver::reference_call(const CallInfo& info) {
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

void BlockSolver::advance(const PointTargets* targets, const CallInfo& info) {
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
void BlockSolver::start(const PointTargets* targets, const CallInfo& info) {
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
void BlockSolver::newton_step(const PointTargets* targets, const CallInfo& info) {
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
    const Mat3 J = use_elastic_[k] ? elastic_jacobian(targets[k]) : jacobian_[k];
    Vec3 step = -J.fullPivLu().solve(residual_[k]);
    if (!step.allFinite() || step.isZero(0.0)) step = -elastic_jacobian(targets[k]).fullPivLu().solve(residual_[k]);
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

// Solves the free components of the stalled points one after the other
// (Gauss-Seidel), each by bracketing; Newton resumes afterwards.
void BlockSolver::bracket_sweep(const PointTargets* targets, const CallInfo& info) {
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

void BlockSolver::bracket_component(int j, const PointTargets* targets, const CallInfo& info) {
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
