// One contact point through uinter_ behind the Caller interface
// (abi/caller.hpp): its arguments (abi/uinter_call.hpp) and its committed
// STRESS, state, SED and RDISP. The law's variables convert exactly to
// Abaqus's (uinter_signs: factors of +-1 and a zero reference position).
#pragma once

#include <vector>

#include "abi/caller.hpp"
#include "abi/uinter_call.hpp"

namespace mortar::harness {

class UinterCaller : public Caller {
 public:
  explicit UinterCaller(const UinterSetup& setup);

  int size() const override { return 1; }
  int n_dir() const override { return uinter_.n_dir(); }
  // RDISP from the end; DRDISP = RDISP - the committed RDISP, as Abaqus passes it.
  void set_trial(int k, const Eigen::Vector3d& end, const Eigen::Vector3d& increment) override;
  void call(const CallTime& time) override;
  Eigen::Vector3d traction(int k) const override;
  double status(int k) const override;
  bool tangent(int k, Eigen::Matrix3d& d_traction_d_separation) const override;
  double size_request(int) const override { return uinter_.pnewdt(); }
  void accept(int k) override;
  void commit() override;
  const double* state(int) const override { return committed_.state.data(); }
  double elastic_energy(int) const override { return committed_.sed; }
  double dissipation_increment(int) const override { return accepted_.spd; }

 private:
  // What UINTER returns that the next increment starts from.
  struct Start {
    std::vector<double> state;
    Eigen::Vector3d stress = Eigen::Vector3d::Zero(), rdisp = Eigen::Vector3d::Zero();
    double sed = 0, spd = 0;
  };
  UinterPoint uinter_;
  Eigen::Vector3d trial_rdisp_ = Eigen::Vector3d::Zero();
  Start committed_, accepted_;
};

}  // namespace mortar::harness
