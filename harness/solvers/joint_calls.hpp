// The wall's contact points through vuinteraction_, as Abaqus/Explicit hands
// them over: in blocks of at most `block` points (Abaqus's nBlock is at most
// 136), every block its own argument arrays that persist from increment to
// increment (stress, state and sed are owned by the caller and handed back),
// one interaction property per block (the points of one interface role,
// scenes/wall.hpp, each role its own props, as Abaqus calls the routine once
// per property), the first call at zero penetration taken by the routine as the bonded
// reference, then each point's penetration (minus its opening) and its slip
// increment in the joint's local frame, its tributary area, its dircos and
// stiffDflt = kn.
//
// Blocks are independent: a pool of threads (solvers/thread_pool.hpp) calls
// them, each block with its points' kinematics and tractions; then the
// bodies' forces are summed, each body's over its points in point order, and
// the energies in point order. So no result depends on the block size or the
// number of threads.
#pragma once

#include <memory>
#include <vector>

#include "abi/vuinteraction_call.hpp"
#include "scenes/wall.hpp"

namespace mortar::harness {

class ThreadPool;

class JointCalls {
 public:
  // setups[r]: the arguments of role r's interaction (InterfaceRole r);
  // blocks of one role hold near-equal numbers of points, at most `block`.
  JointCalls(const WallModel& model, const std::vector<AbiSetup>& setups, int block, int threads);
  ~JointCalls();

  int points() const { return static_cast<int>(opening_.size()); }
  int blocks() const { return static_cast<int>(blocks_.size()); }
  int threads() const;

  // The reference call (increment 0, zero penetration and slip).
  void reference(const CallTime& time);
  // One increment to the body displacements q (3 per body: ux, uy, rotation).
  // std::runtime_error naming the point when the routine reports a failure.
  void update(const std::vector<double>& q, const CallTime& time);

  // Adds the joints' forces and moments on the bodies after the last call to
  // f (3 per body).
  void add_forces(std::vector<double>& f) const;

  // Point i after the last call (law signs: opening and tension positive).
  double opening(int i) const { return opening_[i]; }
  double slip(int i) const { return slip_[i]; }
  double sigma(int i) const { return sigma_[i]; }
  double tau(int i) const { return tau_[i]; }
  // Increments in which point i was opened so far that the routine took it
  // as unpaired (abi_signs::unpaired): not integrated.
  long unpaired(int i) const { return unpaired_[i]; }
  double state(int i, int slot) const;  // SDV slot+1
  // The compression cap's plastic closure kappa_c of point i [mm] (SDV 36;
  // 0 for a role without a cap).
  double kappa_c(int i) const;
  // Sums over the points, times the tributary areas [N·mm]: sed, and the
  // accumulated spd + sfd of every call so far.
  double elastic_energy() const { return sums_.sed; }
  double dissipated() const { return sums_.dissipated; }
  // Σ SDV(slot+1)·area: the law's split of the dissipation (SDV 16, 17, 18)
  // is summed with each call; any other slot on request.
  double state_sum(int slot) const;
  // Wall-clock seconds spent in the calls of vuinteraction_: per increment,
  // the time of all blocks' calls over the threads that took part.
  double seconds_in_routine() const { return seconds_; }

 private:
  void call_all(const CallTime& time, const double* q);
  void block_part(int j, const CallTime& time, const double* q);
  void body_part(int first, int end);
  void sum_part();

  const AbiBlock& block_of(int i) const { return blocks_[block_of_[i]]; }

  const WallModel& model_;
  std::vector<AbiBlock> blocks_;
  std::vector<int> block_first_;         // block j holds points block_first_[j] ..
  std::vector<int> block_of_, slot_of_;  // point i is slot slot_of_[i] of block block_of_[i]
  std::vector<std::vector<std::vector<int>>> job_;  // items[phase][thread] (ThreadPool::run)
  std::vector<int> body_chunks_;         // chunk c: the forces of bodies [c[c], c[c+1])
  // Per body, its points in point order: i (body b of the point) or ~i (body a).
  std::vector<int> body_points_, body_first_;
  std::vector<double> opening_, slip_, sigma_, tau_;
  std::vector<long> unpaired_;
  std::vector<double> push_;    // per point: fx, fy on body b, moments on b and on a
  std::vector<double> energy_;  // per point, times area: sed, spd + sfd, SDV 16, 17, 18
  std::vector<double> force_;   // 3 per body
  // What each thread writes in a call, each on cache lines of its own.
  struct alignas(64) BlockResult {
    int failed = -1;       // the block's first point with a nonzero status, or -1
    double seconds = 0;    // in the routine in the last call
  };
  std::vector<BlockResult> result_;  // per block
  struct alignas(64) Sums {
    double sed = 0, plastic = 0, damage = 0, unilateral = 0, dissipated = 0;  // times area
  } sums_;
  double seconds_ = 0;
  std::unique_ptr<ThreadPool> pool_;
};

}  // namespace mortar::harness
