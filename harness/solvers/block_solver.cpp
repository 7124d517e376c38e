#include "solvers/block_solver.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "abi/props.hpp"
#include "input/input_error.hpp"
#include "mortar/state_layout.hpp"
#include "output/flag_tally.hpp"
#include "solvers/joint_calls.hpp"

namespace mortar::harness {

namespace {

constexpr double kPi = 3.14159265358979323846;

// A half-cosine step from 0 to 1 over [0, 1]: zero velocity at both ends.
double smooth_step(double x) { return x <= 0 ? 0 : x >= 1 ? 1 : 0.5 * (1 - std::cos(kPi * x)); }

enum Dof { kFixed = 0, kFree = 1, kPrescribed = 2 };

}  // namespace

double gravity_factor_at(const SceneSpec& s, double t) { return smooth_step(t / s.loading.self_weight_time); }

double precompression_factor_at(const SceneSpec& s, double t) {
  return smooth_step((t - s.loading.self_weight_time) / s.loading.precompression_time);
}

std::vector<AbiSetup> interface_setups(const SceneSpec& scene) {
  std::vector<AbiSetup> setups(kInterfaceRoles);
  for (int r = 0; r < kInterfaceRoles; ++r) {
    const CompressionCap& cap = scene.interface[r].cap;
    setups[r].n_dir = 2;
    setups[r].n_states = state_count_for(cap);  // SDV 1-23, the flags (35), with a cap kappa_c (36)
    setups[r].props = props_for(scene.interface_law[r], scene.scheme, scene.stol, 0, cap);
    setups[r].stiffness_default = scene.interface_law[r].kn;
  }
  return setups;
}

double horizontal_action_at(const SceneSpec& s, const std::vector<double>& ends, double t) {
  double start = ends[2], prev = 0;
  const std::vector<double>& corners = s.loading.corners();
  for (size_t k = 0; k < corners.size(); ++k) {
    const double d = corners[k], end = ends[3 + k];
    if (t < end) return prev + (d - prev) * smooth_step((t - start) / (end - start));
    start = end, prev = d;
  }
  return prev;
}

BlockSolver::BlockSolver(const SceneSpec& scene, const WallModel& model, const BlockSolverOptions& options)
    : scene_(scene), model_(model), options_(options) {
  const int nb = static_cast<int>(model.bodies.size());
  mass_.assign(3 * nb, 0.0);
  free_.assign(3 * nb, kFree);
  const double f = scene.solver.mass_scaling;
  for (int b = 0; b < nb; ++b) {
    const Body& body = model.bodies[b];
    mass_[3 * b] = mass_[3 * b + 1] = f * body.mass;
    mass_[3 * b + 2] = f * body.inertia;
  }
  for (int i = 0; i < 3; ++i) free_[3 * model.base() + i] = kFixed;
  const bool rotation_free = scene.wall.beam_rotation == BeamRotation::free;
  if (!scene.loading.force_control) free_[3 * model.beam()] = kPrescribed;
  if (!rotation_free) free_[3 * model.beam() + 2] = kFixed;
  action_arm_ = action_arm(scene, model);
  for (size_t i = 0; i < mass_.size(); ++i)
    if (free_[i] == kFree && !(mass_[i] > 0))
      throw std::invalid_argument("BlockSolver: a free degree of freedom without mass (body " +
                                  std::to_string(i / 3) + ")");
  stable_dt_ = stable_increment_bound();
  dt_ = scene.solver.safety_factor * stable_dt_;
}

// 2/ω_max with ω_max² ≤ max_i Σ_j |K_ij|/sqrt(m_i m_j) over the free
// degrees of freedom (Gershgorin), K summed point by point in absolute
// values (an upper bound again).
double BlockSolver::stable_increment_bound() const {
  std::vector<double> row(mass_.size(), 0.0);
  for (const ContactPoint& c : model_.points) {
    const Parameters& p = scene_.interface_law[static_cast<int>(c.role)];
    int dof[6];
    double bn[6], bt[6];
    const int bodies[2] = {c.a, c.b};
    for (int side = 0; side < 2; ++side) {
      const Body& body = model_.bodies[bodies[side]];
      const double sign = side == 0 ? -1.0 : 1.0, rx = c.x - body.cx, ry = c.y - body.cy;
      for (int i = 0; i < 3; ++i) dof[3 * side + i] = 3 * bodies[side] + i;
      bn[3 * side] = sign * c.nx, bn[3 * side + 1] = sign * c.ny, bn[3 * side + 2] = sign * (rx * c.ny - ry * c.nx);
      bt[3 * side] = sign * c.tx(), bt[3 * side + 1] = sign * c.ty();
      bt[3 * side + 2] = sign * (rx * c.ty() - ry * c.tx());
    }
    for (int i = 0; i < 6; ++i) {
      if (free_[dof[i]] != kFree) continue;
      for (int j = 0; j < 6; ++j) {
        if (free_[dof[j]] != kFree) continue;
        const double k = c.area * (p.kn * std::fabs(bn[i] * bn[j]) + p.ks * std::fabs(bt[i] * bt[j]));
        row[dof[i]] += k / std::sqrt(mass_[dof[i]] * mass_[dof[j]]);
      }
    }
  }
  const double omega2 = *std::max_element(row.begin(), row.end());
  if (!(omega2 > 0)) throw std::invalid_argument("BlockSolver: no joint stiffness on any free degree of freedom");
  return 2.0 / std::sqrt(omega2);
}

long BlockSolver::total_increments() const {
  const long n = static_cast<long>(std::ceil(scene_.end_time() / dt_ - 1e-9));
  return options_.max_increments > 0 ? std::min(n, options_.max_increments) : n;
}

namespace {

// External forces at time t: the weights (real masses: mass scaling changes
// inertia only) and the precompression on the beam.
void external_forces(const SceneSpec& s, const std::vector<double>& ends, const WallModel& m, double arm, double t,
                     std::vector<double>& f) {
  std::fill(f.begin(), f.end(), 0.0);
  const double g = s.loading.gravity * gravity_factor_at(s, t);
  for (size_t b = 1; b < m.bodies.size(); ++b) f[3 * b + 1] = -m.bodies[b].mass * g;
  const double p = s.loading.precompression * m.length * s.wall.unit_depth;
  f[3 * m.beam() + 1] -= p * precompression_factor_at(s, t);
  if (s.loading.force_control) {  // at the action's height: a moment about the centroid
    const double h = horizontal_action_at(s, ends, t);
    f[3 * m.beam()] += h;
    f[3 * m.beam() + 2] -= arm * h;
  }
}

int stage_at(const std::vector<double>& ends, double t) {
  for (size_t k = 0; k < ends.size(); ++k)
    if (t < ends[k]) return static_cast<int>(k);
  return static_cast<int>(ends.size()) - 1;
}

}  // namespace

WallSnapshot wall_snapshot(const JointCalls& joints, const std::vector<double>& q, double t, const std::string& label) {
  WallSnapshot s;
  s.time = t, s.label = label, s.q = q;
  for (int i = 0; i < joints.points(); ++i) {
    s.opening.push_back(joints.opening(i));
    s.slip.push_back(joints.slip(i));
    s.damage_n.push_back(joints.state(i, slot::damage_n));
    s.damage_s.push_back(joints.state(i, slot::damage_s));
    s.dissipation.push_back(joints.state(i, slot::dissipation_plastic) + joints.state(i, slot::dissipation_damage) +
                            joints.state(i, slot::energy_unilateral));
    s.kappa_c.push_back(joints.kappa_c(i));
  }
  return s;
}

WallRunSummary BlockSolver::run(int every, const std::function<void(const WallSample&)>& sample,
                                const std::function<void(long, long)>& progress,
                                std::vector<WallSnapshot>* snapshots) {
  const auto clock_start = std::chrono::steady_clock::now();
  JointCalls joints(model_, interface_setups(scene_), options_.block, options_.threads);

  const std::vector<double> ends = scene_.stage_ends();
  const std::vector<int> base = model_.base_points();
  std::vector<int> top;  // the points of the joint under the beam
  for (size_t i = 0; i < model_.points.size(); ++i)
    if (model_.points[i].b == model_.beam()) top.push_back(static_cast<int>(i));
  const long n_end = total_increments();
  const int nd = static_cast<int>(mass_.size()), ux_beam = 3 * model_.beam(), uy_beam = ux_beam + 1,
            rz_beam = ux_beam + 2;
  const bool force_control = scene_.loading.force_control;
  // A displacement pushing a beam free to turn, at `arm` above its centroid.
  const double arm = action_arm_;
  const bool push_turns = !force_control && free_[rz_beam] == kFree;
  const double inertia_push = mass_[rz_beam] + mass_[ux_beam] * arm * arm;
  std::vector<char> dofs = free_;  // the beam's uy is held during the run
  const double dt = dt_, c = 0.5 * scene_.solver.mass_damping * dt;
  std::vector<double> q(nd, 0.0), v(nd, 0.0), v_prev(nd, 0.0), f_int(nd, 0.0), f_ext(nd, 0.0), f_next(nd, 0.0);
  std::vector<double> snapshot_times = scene_.output.snapshot_times;
  std::sort(snapshot_times.begin(), snapshot_times.end());
  size_t next_snapshot = 0;
  WallSnapshot peak_snapshot;

  CallTime time;
  joints.reference(time);
  WallRunSummary sum;
  sum.stable_increment = stable_dt_, sum.time_increment = dt_, sum.points = joints.points();
  sum.blocks = sum.calls_per_increment = joints.blocks();
  double work_loads = 0, work_actuator = 0, damping = 0, reaction_prev = 0, u_prev = 0, external_max = 0;
  external_forces(scene_, ends, model_, action_arm_, 0.0, f_ext);

  for (long n = 0;; ++n) {
    const double t = n * dt;
    const bool last = n == n_end;
    // The beam held at its height from the end of the hold on: the
    // support takes the beam's vertical momentum (booked as its work).
    if (scene_.wall.beam_held && dofs[uy_beam] == kFree && t >= ends[2]) {
      work_loads -= 0.125 * mass_[uy_beam] * (v[uy_beam] + v_prev[uy_beam]) * (v[uy_beam] + v_prev[uy_beam]);
      dofs[uy_beam] = kFixed, v[uy_beam] = v_prev[uy_beam] = 0;
    }
    // Velocities to n+1/2 (not past the end: the last sample uses v(n-1/2)).
    v_prev = v;
    if (!last) {
      for (int i = 0; i < nd; ++i)
        if (dofs[i] == kFree && !(push_turns && i == rz_beam))
          v[i] = ((1 - c) * v[i] + dt * (f_ext[i] + f_int[i]) / mass_[i]) / (1 + c);
      if (!force_control) {
        // The point at the action's height follows U: ux = U + arm·θ, and θ
        // moves under (I + m·arm²)·θ'' = Mθ + arm·Fx − m·arm·U''.
        const double u0 = horizontal_action_at(scene_, ends, t - dt), u1 = horizontal_action_at(scene_, ends, t),
                     u2 = horizontal_action_at(scene_, ends, t + dt);
        if (push_turns) {
          const double turn = f_ext[rz_beam] + f_int[rz_beam] + arm * (f_ext[ux_beam] + f_int[ux_beam]) -
                              mass_[ux_beam] * arm * (u2 - 2 * u1 + u0) / (dt * dt);
          v[rz_beam] = ((1 - c) * v[rz_beam] + dt * turn / inertia_push) / (1 + c);
        }
        v[ux_beam] = (u2 - u1) / dt + (push_turns ? arm * v[rz_beam] : 0.0);
      }
    }
    // The actuator's force at n: what the beam's prescribed motion needs
    // (its work over the action point's displacement is booked here), or
    // the force it applies (in f_ext).
    const double u_action = q[ux_beam] - arm * q[rz_beam];
    double reaction = f_ext[ux_beam];
    if (!force_control) {
      reaction = last ? -f_int[ux_beam] : mass_[ux_beam] * (v[ux_beam] - v_prev[ux_beam]) / dt - f_int[ux_beam];
      if (n > 0) work_actuator += 0.5 * (reaction_prev + reaction) * (u_action - u_prev);
      reaction_prev = reaction, u_prev = u_action;
    }

    WallSample s;
    s.increment = n, s.time = t, s.stage = stage_at(ends, t);
    s.top_ux = u_action, s.top_uy = q[uy_beam], s.top_rotation = q[rz_beam];
    s.actuator = reaction;
    for (int i : base) {
      s.base_shear += joints.tau(i) * model_.points[i].area;
      s.base_normal += joints.sigma(i) * model_.points[i].area;
    }
    for (int i : top) s.top_normal += joints.sigma(i) * model_.points[i].area;
    WallEnergies& e = s.energy;
    e.external = work_loads + work_actuator;
    e.elastic = joints.elastic_energy();
    e.dissipated = joints.dissipated();
    e.plastic = joints.state_sum(slot::dissipation_plastic);
    e.damage = joints.state_sum(slot::dissipation_damage);
    e.unilateral = joints.state_sum(slot::energy_unilateral);
    for (int i = 0; i < nd; ++i)
      if (dofs[i] != kFixed) e.kinetic += 0.125 * mass_[i] * (v[i] + v_prev[i]) * (v[i] + v_prev[i]);
    e.damping = damping;
    external_max = std::max(external_max, std::fabs(e.external));
    // Measured from the displacement stage on: before it the energies are
    // tiny and their ratio is noise.
    if (s.stage >= 3 && external_max > 0) sum.max_balance_error = std::max(sum.max_balance_error, std::fabs(e.balance()) / external_max);
    if (s.stage >= 3) {
      if (std::fabs(s.base_shear) > std::fabs(sum.peak_shear)) {
        sum.peak_shear = s.base_shear, sum.peak_displacement = s.top_ux, sum.peak_time = t;
        if (snapshots) peak_snapshot = wall_snapshot(joints, q, t, "peak");
      }
      if (e.internal() > 0) sum.max_kinetic_ratio = std::max(sum.max_kinetic_ratio, e.kinetic / e.internal());
    }
    if (snapshots)
      while (next_snapshot < snapshot_times.size() && snapshot_times[next_snapshot] <= t + 0.5 * dt)
        snapshots->push_back(wall_snapshot(joints, q, t, "t = " + std::to_string(snapshot_times[next_snapshot++]) + " s"));
    if (sample && (last || (every > 0 && n % every == 0))) sample(s);
    if (progress && n % 256 == 0) progress(n, n_end);
    if (last) break;

    // Positions to n+1, the work of the loads and of the damping over the step.
    external_forces(scene_, ends, model_, action_arm_, t + dt, f_next);
    for (int i = 0; i < nd; ++i) {
      if (dofs[i] != kFree) continue;
      const double dq = dt * v[i];
      work_loads += 0.5 * (f_ext[i] + f_next[i]) * dq;
      damping += 2 * c / dt * (push_turns && i == rz_beam ? inertia_push : mass_[i]) * v[i] * dq;
      q[i] += dq;
    }
    if (!force_control) q[ux_beam] = horizontal_action_at(scene_, ends, t + dt) + arm * q[rz_beam];
    f_ext.swap(f_next);
    time.increment = static_cast<int>(n + 1);
    time.step_time = time.total_time = t + dt;
    time.time_increment = dt;
    joints.update(q, time);
    std::fill(f_int.begin(), f_int.end(), 0.0);
    joints.add_forces(f_int);
  }
  if (snapshots) {
    if (!peak_snapshot.q.empty()) snapshots->push_back(peak_snapshot);
    snapshots->push_back(wall_snapshot(joints, q, n_end * dt, "end"));
  }
  sum.increments = n_end;
  FlagTally flags;
  for (int i = 0; i < static_cast<int>(model_.points.size()); ++i) {
    flags.add(i, static_cast<int>(joints.state(i, flag_slot::integration_flags)));
    flags.add_unpaired(i, joints.unpaired(i));
  }
  sum.integration_flags = flags.summary(false);
  sum.unpaired_warning = flags.unpaired_warning();
  sum.seconds_in_routine = joints.seconds_in_routine();
  sum.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - clock_start).count();
  return sum;
}

}  // namespace mortar::harness
