#include "solvers/joint_calls.hpp"

#include <algorithm>
#include <chrono>
#include <sstream>
#include <stdexcept>

#include "abi/status.hpp"
#include "abi/vuinteraction_signs.hpp"
#include "mortar/state_layout.hpp"
#include "solvers/thread_pool.hpp"

namespace mortar::harness {

namespace {

// Displacement of the material point (x, y) of body b under q (small rotation).
void point_displacement(const Body& b, const double* q, double x, double y, double& ux, double& uy) {
  ux = q[0] - q[2] * (y - b.cy);
  uy = q[1] + q[2] * (x - b.cx);
}

constexpr int kPush = 4;    // push_ per point: fx, fy, moment on b, moment on a
constexpr int kEnergy = 5;  // energy_ per point: sed, spd + sfd, SDV 16, 17, 18 (times area)
constexpr int kSummedSlots[3] = {slot::dissipation_plastic, slot::dissipation_damage, slot::energy_unilateral};

}  // namespace

JointCalls::JointCalls(const WallModel& model, const std::vector<AbiSetup>& setups, int block, int threads)
    : model_(model) {
  const int n = static_cast<int>(model.points.size());
  block_of_.assign(n, 0);
  slot_of_.assign(n, 0);
  // The points of one role lie together (build_wall); each run of one role
  // is cut into near-equal blocks, so that the node labels stay the points'
  // numbers and threads get even shares.
  for (int first = 0; first < n;) {
    const InterfaceRole role = model.points[first].role;
    int end = first;
    while (end < n && model.points[end].role == role) ++end;
    const auto r = static_cast<size_t>(role);
    if (r >= setups.size() || setups[r].n_dir != 2)
      throw std::invalid_argument(std::string("JointCalls: no in-plane (nDir = 2) setup for the ") + role_name(role) +
                                  "s");
    const int count = end - first, pieces = (count + block - 1) / block;
    for (int j = 0; j < pieces; ++j) {
      const int b0 = first + static_cast<int>(static_cast<long>(count) * j / pieces);
      const int b1 = first + static_cast<int>(static_cast<long>(count) * (j + 1) / pieces);
      blocks_.emplace_back(setups[r], b1 - b0, b0);
      block_first_.push_back(b0);
      AbiBlock& b = blocks_.back();
      for (int i = b0; i < b1; ++i) {
        block_of_[i] = static_cast<int>(blocks_.size()) - 1, slot_of_[i] = i - b0;
        const ContactPoint& p = model.points[i];
        const double normal[2] = {p.nx, p.ny}, tangent[2] = {p.tx(), p.ty()}, x[2] = {p.x, p.y};
        b.set_joint_point(i - b0, p.area, normal, tangent, x);
      }
    }
    first = end;
  }
  opening_.assign(n, 0.0);
  slip_.assign(n, 0.0);
  sigma_.assign(n, 0.0);
  tau_.assign(n, 0.0);
  unpaired_.assign(n, 0);
  push_.assign(static_cast<size_t>(kPush) * n, 0.0);
  energy_.assign(static_cast<size_t>(kEnergy) * n, 0.0);
  result_.assign(blocks_.size(), BlockResult());

  // Each body's points in point order: the order in which its forces are summed.
  const int nb = static_cast<int>(model.bodies.size());
  body_first_.assign(nb + 1, 0);
  for (const ContactPoint& p : model.points) ++body_first_[p.a + 1], ++body_first_[p.b + 1];
  for (int b = 0; b < nb; ++b) body_first_[b + 1] += body_first_[b];
  body_points_.assign(2 * static_cast<size_t>(n), 0);
  std::vector<int> fill(body_first_.begin(), body_first_.end() - 1);
  for (int i = 0; i < n; ++i) {
    body_points_[fill[model.points[i].a]++] = ~i;
    body_points_[fill[model.points[i].b]++] = i;
  }
  force_.assign(3 * static_cast<size_t>(nb), 0.0);

  const int nt = std::max(1, std::min(threads, blocks()));
  // Phase 0: the blocks, largest first to the thread with the fewest points
  // so far; phase 1: the energies (item 0) and chunks of bodies (a chunk of
  // about the work of one block's kinematics, at least four per thread).
  job_.assign(2, std::vector<std::vector<int>>(nt));
  std::vector<int> order(blocks_.size());
  for (size_t j = 0; j < order.size(); ++j) order[j] = static_cast<int>(j);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return blocks_[a].size() > blocks_[b].size(); });
  std::vector<long> load(nt, 0);
  for (int j : order) {
    const int t = static_cast<int>(std::min_element(load.begin(), load.end()) - load.begin());
    job_[0][t].push_back(j), load[t] += blocks_[j].size();
  }
  const int per_chunk = std::max(32, 2 * n / (4 * nt));
  body_chunks_.push_back(0);
  for (int b = 0; b < nb; ++b)
    if (body_first_[b + 1] - body_first_[body_chunks_.back()] >= per_chunk || b + 1 == nb) body_chunks_.push_back(b + 1);
  const int items = static_cast<int>(body_chunks_.size());  // the energies and the chunks
  job_[1][nt - 1].push_back(0);
  for (int c = 1; c < items; ++c) job_[1][static_cast<long>(c - 1) * nt / (items - 1)].push_back(c);
  pool_ = std::make_unique<ThreadPool>(nt);
}

JointCalls::~JointCalls() = default;

int JointCalls::threads() const { return pool_->size(); }

double JointCalls::state(int i, int slot) const {
  return block_of(i).state(slot_of_[i])[slot];
}

double JointCalls::state_sum(int slot) const {
  if (slot == kSummedSlots[0]) return sums_.plastic;
  if (slot == kSummedSlots[1]) return sums_.damage;
  if (slot == kSummedSlots[2]) return sums_.unilateral;
  double e = 0;
  for (size_t i = 0; i < model_.points.size(); ++i) e += state(static_cast<int>(i), slot) * model_.points[i].area;
  return e;
}

double JointCalls::kappa_c(int i) const {
  const AbiBlock& b = block_of(i);
  return b.n_states() > cap_slot::kappa_c ? b.state(slot_of_[i])[cap_slot::kappa_c] : 0.0;
}

void JointCalls::reference(const CallTime& time) { call_all(time, nullptr); }

void JointCalls::update(const std::vector<double>& q, const CallTime& time) { call_all(time, q.data()); }

// Phase 0: the blocks (kinematics, the call, tractions); phase 1: the
// energies (item 0) and the bodies' forces (a chunk of bodies an item).
void JointCalls::call_all(const CallTime& time, const double* q) {
  const std::function<void(int, int)> work = [&](int phase, int item) {
    if (phase == 0) return block_part(item, time, q);
    for (const BlockResult& r : result_)
      if (r.failed >= 0) return;
    if (item == 0) return sum_part();
    body_part(body_chunks_[item - 1], body_chunks_[item]);
  };
  pool_->run(job_, work);
  double seconds = 0;
  for (const BlockResult& r : result_) seconds += r.seconds;
  seconds_ += seconds / std::max(1, pool_->participants());
  for (const BlockResult& r : result_) {
    const int i = r.failed;
    if (i < 0) continue;
    const ContactPoint& p = model_.points[i];
    const double status = state(i, slot::status);
    std::ostringstream m;
    m << "contact point " << i + 1 << " (" << role_name(p.role) << " at x = " << p.x << ", y = " << p.y
      << " mm), increment " << time.increment << ": vuinteraction_ returned status " << status << " ("
      << status_meaning(status) << ")";
    throw std::runtime_error(m.str());
  }
}

void JointCalls::block_part(int j, const CallTime& time, const double* q) {
  AbiBlock& b = blocks_[j];
  const int first = block_first_[j], size = b.size();
  for (int k = 0; k < size; ++k) {
    if (!q) {
      b.set_separation_increment(k, 0.0, Eigen::Vector3d::Zero());
      continue;
    }
    const int i = first + k;
    const ContactPoint& p = model_.points[i];
    double ax, ay, bx, by;
    point_displacement(model_.bodies[p.a], &q[3 * p.a], p.x, p.y, ax, ay);
    point_displacement(model_.bodies[p.b], &q[3 * p.b], p.x, p.y, bx, by);
    const double dx = bx - ax, dy = by - ay;
    const double opening = dx * p.nx + dy * p.ny, slip = dx * p.tx() + dy * p.ty();
    b.set_separation_increment(k, opening, Eigen::Vector3d(opening - opening_[i], slip - slip_[i], 0.0));
    if (abi_signs::unpaired(opening)) ++unpaired_[i];
    opening_[i] = opening;
    slip_[i] = slip;
  }
  const auto start = std::chrono::steady_clock::now();
  b.invoke(time);
  result_[j].seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result_[j].failed = -1;
  for (int k = 0; k < size; ++k) {
    const int i = first + k;
    const ContactPoint& p = model_.points[i];
    const double* state = b.state(k);
    if (state[slot::status] != 0) {
      result_[j].failed = i;
      return;
    }
    // AbiBlock::traction, inline.
    const double* stress = b.stress(k);
    const double sigma = abi_signs::normal_traction_from_stress(stress[0]), tau = abi_signs::kShearSign * stress[1];
    sigma_[i] = sigma;
    tau_[i] = tau;
    // The traction on body b (law signs: tension pulls b back towards a).
    const double fx = -(sigma * p.nx + tau * p.tx()) * p.area;
    const double fy = -(sigma * p.ny + tau * p.ty()) * p.area;
    const Body& ba = model_.bodies[p.a];
    const Body& bb = model_.bodies[p.b];
    double* push = &push_[static_cast<size_t>(kPush) * i];
    push[0] = fx, push[1] = fy;
    push[2] = (p.x - bb.cx) * fy - (p.y - bb.cy) * fx;
    push[3] = (p.x - ba.cx) * fy - (p.y - ba.cy) * fx;
    double* e = &energy_[static_cast<size_t>(kEnergy) * i];
    e[0] = b.sed(k) * p.area;
    e[1] = (b.spd(k) + b.sfd(k)) * p.area;
    for (int s = 0; s < 3; ++s) e[2 + s] = state[kSummedSlots[s]] * p.area;
  }
}

// Each body's forces summed over its points in point order, from zero.
void JointCalls::body_part(int first, int end) {
  for (int b = first; b < end; ++b) {
    double fx = 0, fy = 0, m = 0;
    for (int k = body_first_[b]; k < body_first_[b + 1]; ++k) {
      const int c = body_points_[k];
      if (c >= 0) {
        const double* push = &push_[static_cast<size_t>(kPush) * c];
        fx += push[0], fy += push[1], m += push[2];
      } else {
        const double* push = &push_[static_cast<size_t>(kPush) * ~c];
        fx -= push[0], fy -= push[1], m -= push[3];
      }
    }
    force_[3 * b] = fx, force_[3 * b + 1] = fy, force_[3 * b + 2] = m;
  }
}

// The energies summed in point order.
void JointCalls::sum_part() {
  double sed = 0, plastic = 0, damage = 0, unilateral = 0, dissipated = sums_.dissipated;
  const double* e = energy_.data();
  for (int i = 0; i < points(); ++i, e += kEnergy) {
    sed += e[0];
    dissipated += e[1];
    plastic += e[2];
    damage += e[3];
    unilateral += e[4];
  }
  sums_.sed = sed, sums_.plastic = plastic, sums_.damage = damage, sums_.unilateral = unilateral;
  sums_.dissipated = dissipated;
}

void JointCalls::add_forces(std::vector<double>& f) const {
  for (size_t i = 0; i < force_.size(); ++i) f[i] += force_[i];
}

}  // namespace mortar::harness
