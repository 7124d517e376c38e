#include "abi/uinter_caller.hpp"

#include <algorithm>

#include "mortar/state_layout.hpp"

namespace mortar::harness {

using uinter_signs::kRdispFactor;
using uinter_signs::kStressFactor;

UinterCaller::UinterCaller(const UinterSetup& setup) : uinter_(setup, 1) {
  committed_.state.assign(static_cast<size_t>(setup.n_states), 0.0);
  committed_.rdisp[0] = uinter_signs::kReferencePosition;
  accepted_ = committed_;
}

void UinterCaller::set_trial(int, const Eigen::Vector3d& end, const Eigen::Vector3d&) {
  for (int j = 0; j < uinter_.n_dir(); ++j) trial_rdisp_[j] = uinter_signs::rdisp_of(j, end[j]);
}

void UinterCaller::call(const CallTime& time) {
  // Every call starts from the committed arguments: the routine overwrites
  // STRESS, STATEV and SED in place.
  std::copy(committed_.state.begin(), committed_.state.end(), uinter_.state());
  for (int i = 0; i < uinter_.n_dir(); ++i) {
    uinter_.stress()[i] = committed_.stress[i];
    uinter_.rdisp()[i] = trial_rdisp_[i];
    uinter_.drdisp()[i] = trial_rdisp_[i] - committed_.rdisp[i];
  }
  uinter_.sed() = committed_.sed;
  uinter_.invoke(time);
}

Eigen::Vector3d UinterCaller::traction(int) const {
  Eigen::Vector3d t = Eigen::Vector3d::Zero();
  for (int j = 0; j < uinter_.n_dir(); ++j) t[j] = uinter_.stress()[j] / kStressFactor[static_cast<size_t>(j)];
  return t;
}

double UinterCaller::status(int) const { return uinter_.state()[slot::status]; }

// DDSDDR = C T D (uinter_signs), so T = C DDSDDR D with C, D = +-1.
bool UinterCaller::tangent(int, Eigen::Matrix3d& T) const {
  T.setZero();
  for (int i = 0; i < uinter_.n_dir(); ++i)
    for (int j = 0; j < uinter_.n_dir(); ++j)
      T(i, j) = kStressFactor[static_cast<size_t>(i)] * uinter_.ddsddr(i, j) * kRdispFactor[static_cast<size_t>(j)];
  return true;
}

void UinterCaller::accept(int) {
  std::copy_n(uinter_.state(), accepted_.state.size(), accepted_.state.begin());
  for (int j = 0; j < uinter_.n_dir(); ++j) {
    accepted_.stress[j] = uinter_.stress()[j];
    accepted_.rdisp[j] = trial_rdisp_[j];
  }
  accepted_.sed = uinter_.sed();
  accepted_.spd = uinter_.spd();
}

void UinterCaller::commit() { committed_ = accepted_; }

}  // namespace mortar::harness
