// The fuzz target's checks after one call (the pass condition of
// fuzz_vuinteraction.cpp): finite outputs, invalid calls reported and
// harmless, each point's state accepted by the rules or rejected and kept.
#include <cmath>
#include <cstring>

#include "fuzz_target.hpp"
#include "mortar/integrator.hpp"

namespace mj_fuzz {
namespace {

void check_outputs_finite(const Block& b, const std::string& when) {
  for (size_t i = 0; i < b.stress.size(); ++i)
    if (!finite(double(b.stress[i]))) fail("%s: stress[%zu] = %g is not finite", when.c_str(), i, double(b.stress[i]));
  const std::vector<Real>* outs[] = {&b.sed, &b.spd, &b.sfd, &b.scd, &b.svd, &b.flux_slv, &b.flux_mst};
  const char* names[] = {"sed", "spd", "sfd", "scd", "svd", "fluxSlv", "fluxMst"};
  for (int o = 0; o < 7; ++o)
    for (size_t k = 0; k < outs[o]->size(); ++k)
      if (!finite(double((*outs[o])[k])))
        fail("%s: %s[%zu] = %g is not finite", when.c_str(), names[o], k, double((*outs[o])[k]));
}

bool reported(const std::string& text) {
  return text.find(std::string("VUINTERACTION, interaction '") + kName + "'") != std::string::npos;
}

// `text` without the single-precision routine's one warning per process that
// DEPVAR < 34 falls back to plain floats (docs/model.md 3): not a report of
// a point or an argument.
std::string without_fallback_warning(const std::string& text) {
  const size_t at = text.find("warning: DEPVAR = ");
  if (at == std::string::npos) return text;
  const size_t begin = text.rfind('\n', at), end = text.find('\n', at);
  const size_t from = begin == std::string::npos ? 0 : begin + 1;
  return text.substr(0, from) + (end == std::string::npos ? "" : text.substr(end + 1));
}

}  // namespace

void check_call(const Block& b, const Block& before, const std::string& text, int call) {
  char when_buf[64];
  std::snprintf(when_buf, sizeof when_buf, "call %d", call + 1);
  const std::string when = when_buf;
  check_outputs_finite(b, when);
  const bool args_ok = (b.n_dir == 2 || b.n_dir == 3) && b.n_node_states >= 1 && b.n_states >= kSlots &&
                       b.n_props >= 14;
  // A deck with a cap needs DEPVAR 36 (double) or 37 (single).
  const bool capped = args_ok && props_valid(b.props, b.n_props) && props_capped(b.props, b.n_props);
  const bool valid = args_ok && props_valid(b.props, b.n_props) && (!capped || b.n_states >= kCappedSlots);
  const long per_point = long(count(b.n_states)) * long(count(b.n_node_states));

  if (!valid) {
    ++stats.invalid_calls;
    if (!reported(text)) fail("%s: invalid arguments or props but no report on stderr: '%s'", when.c_str(), text.c_str());
    const bool holds_status = b.n_states > slot::status && b.n_node_states >= 1;
    for (int k = 0; k < b.n_block; ++k) {
      for (long i = 0; i < per_point; ++i) {
        const Real now = b.state[k * per_point + i], was = before.state[k * per_point + i];
        if (holds_status && i == slot::status) {
          if (!(now < 0)) fail("%s: invalid call, point %d: SDV 21 = %g, expected a negative code", when.c_str(), k + 1, double(now));
        } else if (!same_bits(now, was)) {
          fail("%s: invalid call changed state slot %ld of point %d", when.c_str(), i + 1, k + 1);
        }
      }
      if (b.n_dir > 0)
        for (int i = 0; i < b.n_dir; ++i) {
          const double in = double(before.stress[k * b.n_dir + i]);
          if (double(b.stress[k * b.n_dir + i]) != (finite(in) ? in : 0.0))
            fail("%s: invalid call changed stress(%d,%d)", when.c_str(), i + 1, k + 1);
        }
      if (b.spd[k] != Real(0)) fail("%s: invalid call, spd(%d) != 0", when.c_str(), k + 1);
      const double sed_in = double(before.sed[k]);
      if (double(b.sed[k]) != (finite(sed_in) ? sed_in : 0.0)) fail("%s: invalid call changed sed(%d)", when.c_str(), k + 1);
    }
    return;
  }

  const int slots = owned_slots(b.n_states);
  const bool paired = slots != kSlots;
  bool any_failure = false;
  for (int k = 0; k < b.n_block; ++k) {
    const Real* s0 = before.state.data() + k * per_point;
    const Real* s1 = b.state.data() + k * per_point;
    // Nothing beyond the routine's slots of state(:, 1, k) is touched, but
    // for the integration flags (SDV 35, with nStates >= 35, either
    // precision): a whole number of the four bits (docs/model.md 9); and
    // with a cap kappa_c (SDV 36, 37), checked with the state below.
    const bool flagged = b.n_states >= mortar::kFlaggedStateCount;
    for (long i = slots; i < per_point; ++i) {
      if (flagged && i == mortar::flag_slot::integration_flags) continue;
      if (capped && i >= mortar::cap_slot::kappa_c && i < kCappedSlots) continue;
      if (!same_bits(s0[i], s1[i])) fail("%s: point %d: state slot %ld (beyond SDV %d or node state 2) written", when.c_str(), k + 1, i + 1, slots);
    }
    if (flagged && !same_bits(s0[mortar::flag_slot::integration_flags], s1[mortar::flag_slot::integration_flags])) {
      const double f = double(s1[mortar::flag_slot::integration_flags]);
      if (!(f >= 0 && f <= 15 && f == std::floor(f))) fail("%s: point %d: SDV 35 = %g is not a set of flags", when.c_str(), k + 1, f);
    }
    const double pen = double(b.penetration[k]);
    if (pen <= -1e30) {  // no opposite surface: nothing happens, nothing carried
      ++stats.unpaired;
      for (int i = 0; i < (capped ? kCappedSlots : slots); ++i)
        if ((i < slots || i >= mortar::cap_slot::kappa_c) && !same_bits(s0[i], s1[i]))
          fail("%s: unpaired point %d: state slot %d changed", when.c_str(), k + 1, i + 1);
      for (int i = 0; i < b.n_dir; ++i)
        if (b.stress[k * b.n_dir + i] != Real(0)) fail("%s: unpaired point %d carries stress", when.c_str(), k + 1);
      continue;
    }
    ++stats.points;
    const Real status = s1[slot::status];
    if (!(status >= 0 && status < 16 && status == std::floor(status) &&
          std::strcmp(mortar::failure_name(static_cast<mortar::Failure>(int(status))), "unknown") != 0))
      fail("%s: point %d: SDV 21 = %g is not one of the law's failure codes", when.c_str(), k + 1, double(status));
    ++stats.status[int(status)];
    const char* corrupt = state_violation(s0, paired, flagged, capped);
    if (corrupt) {
      ++stats.corrupt_reported;
      if (status == 0)
        fail("%s: point %d: incoming state breaks a rule (%s) but the increment was accepted", when.c_str(), k + 1, corrupt);
    }
    if (status != 0) {
      any_failure = true;
      for (int i = 0; i < slots; ++i) {
        if (i == slot::substeps_accepted || i == slot::substeps_rejected || i == slot::status) continue;
        if (!same_bits(s0[i], s1[i]))
          fail("%s: point %d rejected (SDV 21 = %g) but state slot %d changed", when.c_str(), k + 1, double(status), i + 1);
      }
      if (capped)
        for (int i = mortar::cap_slot::kappa_c; i < kCappedSlots; ++i)
          if (!same_bits(s0[i], s1[i]))
            fail("%s: point %d rejected (SDV 21 = %g) but state slot %d changed", when.c_str(), k + 1, double(status), i + 1);
      if (b.spd[k] != Real(0)) fail("%s: rejected point %d has spd != 0", when.c_str(), k + 1);
      if (!corrupt) {
        // A plausible state: the only admissible reasons are a non-finite
        // increment (4) or a failure of the integration itself (1-3, 6).
        const bool first = s0[slot::initialised] == Real(0);
        double dn = 0;
        if (first) {
          dn = finite(pen) ? 0.0 : NAN;
        } else {
          dn = (double(s0[slot::reference_penetration]) - pen) - value(s0, slot::separation_n, paired);
        }
        bool inc_finite = finite(dn);
        if (!first)
          for (int i = 1; i < b.n_dir; ++i) inc_finite = inc_finite && finite(double(b.dr_disp[k * b.n_dir + i]));
        if (inc_finite && (status == 4 || status == 5))
          fail("%s: point %d: plausible state and finite increment rejected with SDV 21 = %g", when.c_str(), k + 1, double(status));
        if (!inc_finite && status != 4)
          fail("%s: point %d: non-finite increment gave SDV 21 = %g, expected 4", when.c_str(), k + 1, double(status));
      }
      continue;
    }
    // Accepted: a state that obeys every rule, grown from the incoming one.
    for (int i = 0; i < slots; ++i)
      if (!finite(double(s1[i]))) fail("%s: point %d accepted but SDV %d = %g is not finite", when.c_str(), k + 1, i + 1, double(s1[i]));
    if (const char* v = state_violation(s1, paired, flagged, capped)) fail("%s: point %d accepted but its new state breaks a rule: %s", when.c_str(), k + 1, v);
    if (s1[slot::initialised] != Real(1)) fail("%s: point %d accepted but not initialised", when.c_str(), k + 1);
    const Real ref = s0[slot::initialised] == Real(1) ? s0[slot::reference_penetration] : b.penetration[k];
    if (!same_bits(s1[slot::reference_penetration], ref)) fail("%s: point %d: reference penetration changed", when.c_str(), k + 1);
    auto grew = [&](int i) { return value(s1, i, paired) >= value(s0, i, paired); };
    if (!grew(slot::damage_n) || !grew(slot::damage_s)) fail("%s: point %d: damage decreased", when.c_str(), k + 1);
    if (!grew(slot::work_I) || !grew(slot::work_III))
      fail("%s: point %d: w_I or w_III decreased", when.c_str(), k + 1);
    if (b.sed[k] < Real(0)) fail("%s: point %d: sed < 0", when.c_str(), k + 1);
  }
  if (any_failure && !reported(text)) fail("%s: a point was rejected but nothing was reported", when.c_str());
  if (!any_failure && !without_fallback_warning(text).empty())
    fail("%s: every point accepted, yet stderr got: '%s'", when.c_str(), text.c_str());
}

}  // namespace mj_fuzz
