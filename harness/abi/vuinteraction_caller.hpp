// A block of points through vuinteraction_ behind the Caller interface
// (abi/caller.hpp): the block's argument arrays (abi/vuinteraction_call.hpp),
// and the committed and accepted stress, state and sed of every point
// (Abaqus layout and signs).
#pragma once

#include <vector>

#include "abi/caller.hpp"
#include "abi/vuinteraction_call.hpp"

namespace mortar::harness {

class VuinteractionCaller : public Caller {
 public:
  VuinteractionCaller(const AbiSetup& setup, int n_points, int first_point);

  int size() const override { return abi_.size(); }
  int n_dir() const override { return abi_.n_dir(); }
  void set_trial(int k, const Eigen::Vector3d& end, const Eigen::Vector3d& increment) override;
  void call(const CallTime& time) override;
  Eigen::Vector3d traction(int k) const override { return abi_.traction(k); }
  double status(int k) const override;
  void accept(int k) override;
  void commit() override;
  const double* state(int k) const override;
  double elastic_energy(int k) const override { return committed_sed_[static_cast<size_t>(k)]; }
  double dissipation_increment(int k) const override { return accepted_spd_[static_cast<size_t>(k)]; }

 private:
  AbiBlock abi_;  // the arrays of every call
  std::vector<double> committed_stress_, committed_state_, committed_sed_;
  std::vector<double> accepted_stress_, accepted_state_, accepted_sed_, accepted_spd_;
};

}  // namespace mortar::harness
