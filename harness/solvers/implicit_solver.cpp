#include "solvers/implicit_solver.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "abi/status.hpp"
#include "mortar/state_layout.hpp"

namespace mortar::harness {

namespace {
using uinter_signs::kRdispFactor;
using uinter_signs::kStressFactor;
using uinter_signs::rdisp_of;
using uinter_signs::separation_of;

// Two residuals equal to round-off: Newton has entered a cycle (it bounces
// across a kink of the response, e.g. between the elastic and the plastic
// branch) and will repeat it for ever.
bool same(double a, double b) { return std::abs(a - b) <= 1e-9 * std::max(std::abs(a), std::abs(b)); }
}  // namespace

const char* outcome_name(AttemptOutcome o) {
  switch (o) {
    case AttemptOutcome::converged: return "converged";
    case AttemptOutcome::cut_by_routine: return "a request for a smaller increment (PNEWDT < 1)";
    case AttemptOutcome::diverged: return "divergence";
    case AttemptOutcome::not_converged: return "no convergence within the iteration limit";
    case AttemptOutcome::cycling: return "Newton cycling between two iterates";
  }
  return "?";
}

ImplicitPointSolver::ImplicitPointSolver(const UinterSetup& setup, const ImplicitOptions& options)
    : options_(options), caller_(setup), n_dir_(setup.n_dir) {
  options_.max_iterations = std::clamp(options_.max_iterations, 1, kMaxRecordedIterations);
  committed_rdisp_[0] = uinter_signs::kReferencePosition;
}

void ImplicitPointSolver::fail(const std::string& why) const {
  throw RunFailure(failure_location(0, step_, increment_) + why);
}

// The targets at fraction `end` of the program increment: linear between its
// start and end values, the end itself exactly.
PointTargets ImplicitPointSolver::targets_at(const PointTargets& from, const PointTargets& to, double end) const {
  if (end >= 1.0) return to;
  PointTargets t = to;
  for (int j = 0; j < 3; ++j) t.value[j] = from.value[j] + (to.value[j] - from.value[j]) * end;
  return t;
}

void ImplicitPointSolver::advance(const PointTargets& from, const PointTargets& to, const CallTime& time, int step,
                                  long increment, const std::function<void(const ResidualSequence&)>& on_attempt) {
  if (step != step_) solved_in_step_ = 0;
  step_ = step;
  increment_ = increment;
  result_.start_traction = result_.traction;
  result_.increment = result_.separation;  // the start, until the end is known
  result_.dissipation_increment = 0;
  result_.iterations = 0;
  work_increment_ = 0;
  sub_increments_ = 0;
  double start = 0, size = 1;
  int cuts = 0;
  while (start < 1.0) {
    const double end = size >= 1.0 - start ? 1.0 : start + size;
    ResidualSequence record;
    record.step = step;
    record.increment = increment;
    record.sub_increment = ++sub_increments_;
    record.start = start;
    record.size = end - start;
    CallTime t = time;
    t.time_increment = record.size * time.time_increment;
    t.step_time = time.step_time - (1.0 - end) * time.time_increment;
    t.total_time = time.total_time - (1.0 - end) * time.time_increment;
    const AttemptOutcome outcome = attempt(targets_at(from, to, end), t, record);
    ++outcomes_[static_cast<size_t>(outcome)];
    if (on_attempt) on_attempt(record);
    if (outcome == AttemptOutcome::converged) {
      ++solved_in_step_;
      start = end;
      continue;
    }
    // Abandoned: retry a smaller piece from the same start.
    const double factor = outcome == AttemptOutcome::cut_by_routine ? record.pnewdt : options_.divergence_cut;
    size = record.size * factor;
    if (++cuts > options_.max_cuts || size < options_.min_fraction) give_up(record, cuts - 1);
  }
  result_.increment = result_.separation - result_.increment;
}

void ImplicitPointSolver::give_up(const ResidualSequence& last, int cuts) const {
  std::ostringstream why;
  why << "the increment could not be solved: after " << cuts << " cut-back(s) (at most " << options_.max_cuts
      << ", --max-cuts; sub-increments of at least " << options_.min_fraction << " of the increment) the attempt on "
      << last.size << " of the increment ended with " << outcome_name(last.outcome);
  if (last.outcome == AttemptOutcome::cut_by_routine) why << " (PNEWDT = " << last.pnewdt << ")";
  if (last.count > 0) why << ", last residual " << last.residual[static_cast<size_t>(last.count - 1)] << " MPa";
  if (last.outcome == AttemptOutcome::cycling)
    why << "; DDSDDR sends Newton back and forth across a kink of the response (the traction-controlled "
           "response is not monotone there, e.g. at a brittle peak with dilatancy); --solver explicit "
           "brackets such roots";
  fail(why.str());
}

// Calls the routine from the start of the increment at the relative
// position `rdisp` (the caller passes DRDISP = rdisp - start).
void ImplicitPointSolver::call(const Vec3& rdisp, CallTime& time) {
  Vec3 end = Vec3::Zero();
  for (int j = 0; j < n_dir_; ++j) end[j] = separation_of(j, rdisp[j]);
  caller_.set_trial(0, end, end - result_.separation);
  caller_.call(time);
  ++time.iteration;
  ++calls_;
  read_call();
}

// STRESS = C sigma and DDSDDR = C T D from the caller's traction and tangent.
void ImplicitPointSolver::read_call() {
  const Vec3 traction = caller_.traction(0);
  Mat3 T;
  caller_.tangent(0, T);
  for (int i = 0; i < n_dir_; ++i) {
    stress_[i] = kStressFactor[i] * traction[i];
    for (int j = 0; j < n_dir_; ++j) ddsddr_(i, j) = kStressFactor[i] * T(i, j) * kRdispFactor[j];
  }
  // Without UNSYMM Abaqus/Standard keeps only the symmetric part (docs/abaqus.md).
  if (options_.symmetric_tangent) ddsddr_ = (0.5 * (ddsddr_ + ddsddr_.transpose())).eval();
}

// True when the routine abandons the attempt (PNEWDT < 1). Anything else the
// routine reports is a failure of the run: a status without a cut-back
// request, a PNEWDT that is no factor, a non-finite STRESS or DDSDDR.
bool ImplicitPointSolver::cut_requested() const {
  const double pnewdt = caller_.size_request(0), status = caller_.status(0);
  std::ostringstream why;
  if (pnewdt < 1.0) {
    if (pnewdt > 0.0) return true;
    why << "the routine returned PNEWDT = " << pnewdt << ", which is no size factor (0 < PNEWDT < 1)";
    fail(why.str());
  }
  if (status != 0.0) {
    why << "the routine reported status " << status << " in SDV" << slot::status + 1 << " ("
        << status_meaning(status) << ") without asking for a smaller increment (PNEWDT = " << pnewdt << ")";
    fail(why.str());
  }
  for (int i = 0; i < n_dir_; ++i) {
    bool finite = std::isfinite(stress_[i]);
    for (int j = 0; j < n_dir_; ++j) finite = finite && std::isfinite(ddsddr_(i, j));
    if (!finite) fail("the routine returned a non-finite STRESS or DDSDDR without asking for a smaller increment");
  }
  return false;
}

// STRESS_j - P_j on the free components (zero elsewhere); P_j = C_j target_j
// is the applied traction in Abaqus's signs, so this is sigma_j - target_j
// up to the sign C_j = +-1.
ImplicitPointSolver::Vec3 ImplicitPointSolver::residual(const PointTargets& t) const {
  Vec3 r = Vec3::Zero();
  for (int j = 0; j < n_dir_; ++j)
    if (free_component(t, j)) r[j] = stress_[j] - kStressFactor[j] * t.value[j];
  return r;
}

// Solves K_FF x_F = rhs_F with K = DDSDDR of the last call; zero on the
// displacement-controlled components.
ImplicitPointSolver::Vec3 ImplicitPointSolver::newton_step(const PointTargets& t, const Vec3& rhs) const {
  return solve_on_free(t, ddsddr_, rhs, n_dir_);
}

// The iterate at the start of an attempt, as Abaqus's absolute RDISP: the
// displacement-controlled components at their targets exactly, the free ones
// where the increment started.
ImplicitPointSolver::Vec3 ImplicitPointSolver::prescribed(const PointTargets& t) const {
  Vec3 x = committed_rdisp_;
  for (int j = 0; j < n_dir_; ++j)
    if (!free_component(t, j)) x[j] = rdisp_of(j, t.value[j]);
  return x;
}

// After a call: true when the routine abandons the attempt (recorded).
bool ImplicitPointSolver::abandoned(ResidualSequence& record) const {
  if (!cut_requested()) return false;
  record.outcome = AttemptOutcome::cut_by_routine;
  record.pnewdt = caller_.size_request(0);
  return true;
}

// The stiffness call at the start (DRDISP = 0) and the predictor from its
// DDSDDR: K_FF dx_F = -(STRESS_F - P_F) - K_FD dx_D. False when abandoned.
bool ImplicitPointSolver::predict(const PointTargets& t, CallTime& time, Vec3& x, ResidualSequence& record) {
  const Vec3 d_prescribed = x - committed_rdisp_;
  call(committed_rdisp_, time);
  if (abandoned(record)) return false;
  Vec3 rhs = -residual(t);
  for (int i = 0; i < n_dir_; ++i)
    for (int j = 0; j < n_dir_; ++j) rhs[i] -= ddsddr_(i, j) * d_prescribed[j];
  const Vec3 dx = newton_step(t, rhs);
  if (!dx.allFinite()) {
    record.outcome = AttemptOutcome::diverged;
    return false;
  }
  x += dx;
  return true;
}

// Iterations that cannot converge: a non-finite residual or one growing in
// two consecutive iterations (divergence), or a repeated two-iterate cycle.
bool ImplicitPointSolver::hopeless(ResidualSequence& r) const {
  const int k = r.count;
  const double* q = r.residual.data();
  if (!std::isfinite(q[k - 1]) || (k >= 3 && q[k - 1] > q[k - 2] && q[k - 2] > q[k - 3])) {
    r.outcome = AttemptOutcome::diverged;
    return true;
  }
  if (k >= 4 && same(q[k - 1], q[k - 3]) && same(q[k - 2], q[k - 4])) {
    r.outcome = AttemptOutcome::cycling;
    return true;
  }
  return false;
}

// Newton on DDSDDR until the residual rises: the step crossed a kink of the
// response (the elastic-plastic boundary at a brittle peak, where Newton on
// the one-sided tangents would cycle). From there on the Jacobian is that of
// the iterate before the rise, corrected by Broyden's rank-one update with
// every step taken (the secant across the kink).
AttemptOutcome ImplicitPointSolver::attempt(const PointTargets& t, CallTime time, ResidualSequence& record) {
  time.increment = static_cast<int>(solved_in_step_ + 1);
  time.iteration = 0;
  Vec3 x = prescribed(t);
  const bool any_free = std::any_of(t.kind.begin(), t.kind.begin() + n_dir_,
                                    [](Control c) { return c == Control::traction; });
  if (any_free && !predict(t, time, x, record)) return record.outcome;
  Vec3 x_last = x, R_last = Vec3::Zero();
  Mat3 J = Mat3::Zero(), tangent_last = ddsddr_;
  bool secant = false;
  for (int k = 1; k <= options_.max_iterations; ++k) {
    call(x, time);
    if (abandoned(record)) return record.outcome;
    const Vec3 R = residual(t);
    const size_t n = static_cast<size_t>(record.count++);
    record.residual[n] = R.cwiseAbs().maxCoeff();
    if (record.residual[n] <= options_.traction_tolerance) {
      commit(x, record);
      return record.outcome = AttemptOutcome::converged;
    }
    if (!secant && n >= 1 && record.residual[n] > record.residual[n - 1]) {
      secant = true;
      J = tangent_last;
    }
    if (!secant && hopeless(record)) return record.outcome;
    if (secant) {
      const Vec3 s = x - x_last;
      if (s.squaredNorm() > 0) J += ((R - R_last) - J * s) * s.transpose() / s.squaredNorm();
    }
    const Vec3 dx = secant ? Vec3(solve_on_free(t, J, -R, n_dir_)) : newton_step(t, -R);
    if (!dx.allFinite()) return record.outcome = AttemptOutcome::diverged;
    x_last = x;
    R_last = R;
    tangent_last = ddsddr_;
    x += dx;
  }
  return record.outcome = AttemptOutcome::not_converged;
}

// The converged call's outputs become the start of the next increment.
void ImplicitPointSolver::commit(const Vec3& rdisp, const ResidualSequence& record) {
  caller_.accept(0);
  caller_.commit();
  Vec3 separation = Vec3::Zero();
  for (int j = 0; j < n_dir_; ++j) {
    committed_rdisp_[j] = rdisp[j];
    separation[j] = separation_of(j, rdisp[j]);
  }
  const Vec3 traction = caller_.traction(0);
  work_increment_ += 0.5 * (result_.traction + traction).dot(separation - result_.separation);
  result_.separation = separation;
  result_.traction = traction;
  result_.elastic_energy = caller_.elastic_energy(0);
  result_.dissipation_increment += caller_.dissipation_increment(0);
  result_.iterations += record.count;
  result_.traction_residual = record.residual[static_cast<size_t>(record.count - 1)];
}

}  // namespace mortar::harness
