#include "solvers/joint_calls.hpp"

#include <algorithm>
#include <chrono>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "abi/status.hpp"
#include "abi/vuinteraction_signs.hpp"
#include "mortar/state_layout.hpp"

namespace mortar::harness {

namespace {

// Displacement of the material point (x, y) of body b under q (small rotation).
void point_displacement(const Body& b, const double* q, double x, double y, double& ux, double& uy) {
  ux = q[0] - q[2] * (y - b.cy);
  uy = q[1] + q[2] * (x - b.cx);
}

}  // namespace

JointCalls::JointCalls(const WallModel& model, const std::vector<AbiSetup>& setups, int block, int threads)
    : model_(model), threads_(std::max(1, threads)) {
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
}

double JointCalls::state(int i, int slot) const {
  return block_of(i).state(slot_of_[i])[slot];
}

double JointCalls::kappa_c(int i) const {
  const AbiBlock& b = block_of(i);
  return b.n_states() > cap_slot::kappa_c ? b.state(slot_of_[i])[cap_slot::kappa_c] : 0.0;
}

void JointCalls::reference(const CallTime& time) {
  for (AbiBlock& b : blocks_)
    for (int k = 0; k < b.size(); ++k) b.set_separation_increment(k, 0.0, Eigen::Vector3d::Zero());
  call_all(time);
}

void JointCalls::update(const std::vector<double>& q, const CallTime& time) {
  for (size_t i = 0; i < model_.points.size(); ++i) {
    const ContactPoint& p = model_.points[i];
    double ax, ay, bx, by;
    point_displacement(model_.bodies[p.a], &q[3 * p.a], p.x, p.y, ax, ay);
    point_displacement(model_.bodies[p.b], &q[3 * p.b], p.x, p.y, bx, by);
    const double dx = bx - ax, dy = by - ay;
    const double opening = dx * p.nx + dy * p.ny, slip = dx * p.tx() + dy * p.ty();
    const Eigen::Vector3d d(opening - opening_[i], slip - slip_[i], 0.0);
    blocks_[block_of_[i]].set_separation_increment(slot_of_[i], opening, d);
    if (abi_signs::unpaired(opening)) ++unpaired_[i];
    opening_[i] = opening;
    slip_[i] = slip;
  }
  call_all(time);
}

void JointCalls::call_all(const CallTime& time) {
  const auto start = std::chrono::steady_clock::now();
  const int nb = blocks(), nt = std::min(threads_, nb);
  // Thread t calls blocks t, t + nt, ...: each block is touched by one thread.
  auto work = [&](int t) {
    for (int j = t; j < nb; j += nt) blocks_[j].invoke(time);
  };
  if (nt <= 1) {
    work(0);
  } else {
    std::vector<std::thread> pool;
    for (int t = 1; t < nt; ++t) pool.emplace_back(work, t);
    work(0);
    for (auto& th : pool) th.join();
  }
  seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  check_status(time);
  // Tractions and energies in point order: the sums do not depend on blocks.
  for (size_t i = 0; i < model_.points.size(); ++i) {
    const AbiBlock& b = block_of(static_cast<int>(i));
    const int k = slot_of_[i];
    const Eigen::Vector3d t = b.traction(k);
    sigma_[i] = t[0];
    tau_[i] = t[1];
    dissipated_ += (b.spd(k) + b.sfd(k)) * model_.points[i].area;
  }
}

void JointCalls::check_status(const CallTime& time) const {
  for (size_t i = 0; i < model_.points.size(); ++i) {
    const double status = state(static_cast<int>(i), slot::status);
    if (status == 0) continue;
    const ContactPoint& p = model_.points[i];
    std::ostringstream m;
    m << "contact point " << i + 1 << " (" << role_name(p.role) << " at x = " << p.x << ", y = " << p.y
      << " mm), increment " << time.increment << ": vuinteraction_ returned status " << status << " ("
      << status_meaning(status) << ")";
    throw std::runtime_error(m.str());
  }
}

void JointCalls::add_forces(std::vector<double>& f) const {
  for (size_t i = 0; i < model_.points.size(); ++i) {
    const ContactPoint& p = model_.points[i];
    // Traction on body b (law signs: tension pulls b back towards a).
    const double fx = -(sigma_[i] * p.nx + tau_[i] * p.tx()) * p.area;
    const double fy = -(sigma_[i] * p.ny + tau_[i] * p.ty()) * p.area;
    const Body& a = model_.bodies[p.a];
    const Body& b = model_.bodies[p.b];
    f[3 * p.b] += fx, f[3 * p.b + 1] += fy;
    f[3 * p.b + 2] += (p.x - b.cx) * fy - (p.y - b.cy) * fx;
    f[3 * p.a] -= fx, f[3 * p.a + 1] -= fy;
    f[3 * p.a + 2] -= (p.x - a.cx) * fy - (p.y - a.cy) * fx;
  }
}

double JointCalls::elastic_energy() const {
  double e = 0;
  for (size_t i = 0; i < model_.points.size(); ++i) {
    e += block_of(static_cast<int>(i)).sed(slot_of_[i]) * model_.points[i].area;
  }
  return e;
}

double JointCalls::state_sum(int slot) const {
  double e = 0;
  for (size_t i = 0; i < model_.points.size(); ++i) e += state(static_cast<int>(i), slot) * model_.points[i].area;
  return e;
}

}  // namespace mortar::harness
