// The fuzz target's independent oracles: what docs/model.md section 2, 7.4
// and docs/abaqus.md say of props and states (the compression cap's
// props(21..24) and SDV 36-37 included), read here without the law's own
// checks.
#include <algorithm>
#include <cmath>

#include "fuzz_target.hpp"
#include "mortar/integrator.hpp"
#include "mortar/parameters.hpp"

namespace mj_fuzz {
namespace {

mortar::Controls controls_with_scheme(int scheme) {
  mortar::Controls c;
  c.scheme = static_cast<mortar::Scheme>(scheme);
  return c;
}

// A low part belongs to its high part: both finite, and the low part at most
// the float spacing above the high part's magnitude.
bool pair_belongs(Real high, Real low) {
  const float h = std::fabs(float(high));
  return finite(double(high)) && finite(double(low)) && std::fabs(float(low)) <= std::nextafter(h, INFINITY) - h;
}

}  // namespace

// props(21..24), the compression cap (docs/abaqus.md): finite; fc = 0 is no
// cap; else each in its range, and the two rules against the joint's set.
bool cap_valid(const std::vector<double>& p) {
  const double ft0 = p[2], c0 = p[3], kn = p[0], ks = p[1];
  const double fc = p[20], Cs = p[21], Gfc = p[22], kappa_p = p[23];
  if (!(finite(fc) && finite(Cs) && finite(Gfc) && finite(kappa_p))) return false;
  if (fc == 0) return true;
  if (!(fc >= 1e-3 && fc <= 1000 && Cs >= 0 && Cs <= 1000 && Gfc >= 1e-6 && Gfc <= 1e4 && kappa_p >= 0 &&
        kappa_p <= 100))
    return false;
  if (!(fc / 3 > std::sqrt(ft0 * ft0 + Cs * c0 * c0))) return false;
  const double stiff = Cs > 0 ? std::min(kn, Cs * ks) : kn;
  return 481 * fc * fc / (588 * Gfc) < stiff;
}

bool props_valid(const std::vector<Real>& props, int n_props) {
  if (n_props < 14) return false;
  const int n = std::min(n_props, 24);
  std::vector<double> p(24, 0.0);
  for (int i = 0; i < n; ++i) {
    p[i] = double(props[i]);
    if (!finite(p[i])) return false;
  }
  const double ft0 = p[2], c0 = p[3], phi0 = p[6], phir = p[7], psi0 = p[9], psir = p[10];
  // Each parameter's own range is data of the law (kParameterRange); the
  // rules between parameters are restated here.
  for (int i = 0; i < mortar::kParameterCount; ++i)
    if (!mortar::kParameterRange[size_t(i)].holds(p[i])) return false;
  if (!(phir <= phi0 && psir <= psi0)) return false;
  if (!(c0 > ft0 * std::tan(phi0 * (3.14159265358979323846 / 180.0)))) return false;
  const double scheme = p[14], stol = p[15], ftol = p[16], max_sub = p[17], min_sub = p[18], sign = p[19];
  // Which schemes exist is the law's business (it grows): ask it, for whole
  // numbers only.
  if (!(scheme == 0 || (scheme == std::floor(scheme) && scheme >= 1 && scheme <= 9 &&
                        mortar::validate(controls_with_scheme(int(scheme))).ok())))
    return false;
  if (!(stol == 0 || (stol > 0 && stol < 1))) return false;
  if (!(ftol == 0 || (ftol > 0 && ftol < 1))) return false;
  if (!(max_sub == 0 || (max_sub == std::floor(max_sub) && max_sub >= 1 && max_sub <= 1e9))) return false;
  if (!(min_sub == 0 || (min_sub > 0 && min_sub <= 1))) return false;
  if (!(sign == 0 || sign == 1 || sign == -1)) return false;
  return cap_valid(p);
}

bool props_capped(const std::vector<Real>& props, int n_props) {
  return n_props > mortar::kCapFirstProp && double(props[mortar::kCapFirstProp]) > 0;
}

double kappa_c_value(const Real* s, bool paired) {
  const double high = double(s[mortar::cap_slot::kappa_c]);
  return paired ? high + double(s[mortar::cap_slot::kappa_c_low]) : high;
}

// The slots the routine owns per point: SDV 1-23, and SDV 24-34 for single
// precision's float pairs when nStates >= 34.
int owned_slots(int n_states) {
  return sizeof(Real) == 4 && n_states >= mortar::kPairedStateCount ? mortar::kPairedStateCount : kSlots;
}

// State variable i as the routine reads it: a paired variable's value is its
// high part plus its low part, summed in double.
double value(const Real* s, int i, bool paired) {
  if (paired)
    for (const mortar::SlotPair& p : mortar::kPairedSlots)
      if (p.high == i) return double(s[p.high]) + double(s[p.low]);
  return double(s[i]);
}


// The documented rules of an incoming state (docs/model.md section 3, the
// law's check_state, and the adapter's flags; SDV 35 where `flagged`).
const char* state_violation(const Real* s, bool paired, bool flagged, bool capped) {
  if (paired)
    for (const mortar::SlotPair& p : mortar::kPairedSlots)
      if (!pair_belongs(s[p.high], s[p.low])) return "a low part (SDV 24-34) beyond its high part's float spacing";
  auto v = [&](int i) { return value(s, i, paired); };
  for (int i = 0; i <= slot::energy_unilateral; ++i)
    if (!finite(v(i))) return "non-finite SDV 1-18";
  if (!(v(slot::damage_n) >= 0 && v(slot::damage_n) <= 1)) return "d_n outside [0, 1]";
  if (!(v(slot::damage_s) >= 0 && v(slot::damage_s) <= 1)) return "d_s outside [0, 1]";
  if (!(v(slot::work_I) >= 0)) return "w_I < 0";
  if (!(v(slot::work_II) >= 0)) return "w_II < 0";
  if (!(v(slot::work_III) >= 0)) return "w_III < 0";
  if (!(v(slot::dissipation_damage) >= 0)) return "D_damage < 0";
  if (!(s[slot::open] == 0 || s[slot::open] == 1)) return "open flag not 0 or 1";
  if (!(s[slot::initialised] == 0 || s[slot::initialised] == 1)) return "initialised flag not 0 or 1";
  if (flagged) {
    const double f = double(s[mortar::flag_slot::integration_flags]);
    if (!(f >= 0 && f <= 15 && f == std::floor(f))) return "SDV 35 not a whole number from 0 to 15";
  }
  if (capped) {
    if (paired && !pair_belongs(s[mortar::cap_slot::kappa_c], s[mortar::cap_slot::kappa_c_low]))
      return "SDV 37 beyond SDV 36's float spacing";
    const double kappa = kappa_c_value(s, paired);
    if (!(finite(kappa) && kappa >= 0)) return "kappa_c (SDV 36) not finite or negative";
  }
  if (s[slot::initialised] == 1 && !finite(double(s[slot::reference_penetration]))) return "non-finite reference";
  return nullptr;
}

}  // namespace mj_fuzz
