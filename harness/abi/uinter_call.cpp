#include "abi/uinter_call.hpp"

#include "abi/caller.hpp"
#include "abi/fortran_string.hpp"
#include "vuinteraction.h"

namespace mortar::harness {

UinterPoint::UinterPoint(const UinterSetup& setup, int node)
    : setup_(setup), node_(node), state_(static_cast<size_t>(setup.n_states), 0.0) {
  // Local directions = global axes.
  for (int i = 0; i < 3; ++i) alocaldir_[static_cast<size_t>(4 * i)] = 1.0;
  drot_ = {1.0, 0.0, 0.0, 1.0};
  coords_ = {0.0, static_cast<double>(node), 0.0};  // plausible, not used by the law
  fortran_string(ciname_, "MORTAR");
  fortran_string(slname_, "SLAVE");
  fortran_string(msname_, "MASTER");
}

void UinterPoint::invoke(const CallTime& t) {
  const double time[2] = {t.step_time, t.total_time};
  const double dtime = t.time_increment, freqr = 0, area = 1.0, chrlngth = 1.0;
  const int npred = 0, nprops = static_cast<int>(setup_.props.size()), mcrd = 3, linper = 0, lprint = 0;
  int lopenclose = -1, lstate = -1, lsdi = 0;
  pnewdt_ = Caller::kNoSizeRequest;  // as Abaqus sets it before every call
  uinter_(stress_.data(), ddsddr_.data(), amki_.data(), amski_.data(), flux_.data(), ddfddt_.data(),
          ddsddt_.data(), ddfddr_.data(), state_.data(), &sed_, &sfd_, &spd_, &svd_, &scd_, &pnewdt_,
          rdisp_.data(), drdisp_.data(), temp_.data(), dtemp_.data(), predef_.data(), dpred_.data(), time, &dtime,
          &freqr, ciname_.data(), slname_.data(), msname_.data(), setup_.props.data(), coords_.data(),
          alocaldir_.data(), drot_.data(), &area, &chrlngth, &node_, &setup_.n_dir, &setup_.n_states, &npred,
          &nprops, &mcrd, &t.step, &t.increment, &t.iteration, &linper, &lopenclose, &lstate, &lsdi, &lprint, 80,
          80, 80);
}

}  // namespace mortar::harness
