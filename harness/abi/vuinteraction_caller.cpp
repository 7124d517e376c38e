#include "abi/vuinteraction_caller.hpp"

#include <algorithm>

#include "mortar/state_layout.hpp"

namespace mortar::harness {

VuinteractionCaller::VuinteractionCaller(const AbiSetup& setup, int n_points, int first_point)
    : abi_(setup, n_points, first_point) {
  committed_stress_.assign(abi_.stress_array().size(), 0.0);
  committed_state_.assign(abi_.state_array().size(), 0.0);
  committed_sed_.assign(static_cast<size_t>(n_points), 0.0);
  accepted_stress_ = committed_stress_;
  accepted_state_ = committed_state_;
  accepted_sed_ = committed_sed_;
  accepted_spd_.assign(static_cast<size_t>(n_points), 0.0);
}

void VuinteractionCaller::set_trial(int k, const Eigen::Vector3d& end, const Eigen::Vector3d& increment) {
  abi_.set_separation_increment(k, end[0], increment);
}

void VuinteractionCaller::call(const CallTime& time) {
  // Every call starts from the committed arrays: the routine overwrites
  // stress, state and sed in place.
  std::copy(committed_stress_.begin(), committed_stress_.end(), abi_.stress_array().begin());
  std::copy(committed_state_.begin(), committed_state_.end(), abi_.state_array().begin());
  std::copy(committed_sed_.begin(), committed_sed_.end(), abi_.sed_array().begin());
  abi_.invoke(time);
}

double VuinteractionCaller::status(int k) const { return abi_.state(k)[slot::status]; }

void VuinteractionCaller::accept(int k) {
  const int nd = abi_.n_dir(), ns = abi_.n_states();
  std::copy_n(abi_.stress(k), nd, &accepted_stress_[static_cast<size_t>(k) * nd]);
  std::copy_n(abi_.state(k), ns, &accepted_state_[static_cast<size_t>(k) * ns]);
  accepted_sed_[static_cast<size_t>(k)] = abi_.sed(k);
  accepted_spd_[static_cast<size_t>(k)] = abi_.spd(k);
}

void VuinteractionCaller::commit() {
  committed_stress_ = accepted_stress_;
  committed_state_ = accepted_state_;
  committed_sed_ = accepted_sed_;
}

const double* VuinteractionCaller::state(int k) const {
  return &committed_state_[static_cast<size_t>(k) * abi_.n_states()];
}

}  // namespace mortar::harness
