// Fuzz target of the VUINTERACTION entry point vuinteraction_ (docs/robustness.md).
//
// One input (format: fuzz_input.hpp) is a block of points with arbitrary
// dimensions (nDir, nStates, nNodState, nBlock, nProps, valid and not),
// arbitrary props (paper sets, random valid sets, scaled sets, raw doubles,
// controls), and a sequence of up to 8 calls with arbitrary penetrations and
// relative-displacement increments (tiny, huge, NaN, infinite, "unpaired")
// and state corruptions between calls (garbage a corrupted restart could
// hold). Arrays are sized as declared, as Abaqus sizes them.
//
// Pass condition, checked after every call (a violation prints what was
// wrong and aborts, so libFuzzer keeps the input as a crash):
//   - no crash and no sanitizer report (the build adds ASan + UBSan);
//   - every output (stress, sed, spd, sfd, scd, svd, fluxes) is finite,
//     whatever came in;
//   - invalid arguments or properties (judged here by an independent reading
//     of docs/model.md section 2 and docs/abaqus.md) are reported: a message
//     naming the routine and the interaction, the negative code in SDV 21 of
//     every point, no other state slot changed, stress and sed as they came
//     in (made finite), spd = 0;
//   - a point whose incoming state breaks the documented rules (non-finite
//     SDV 1-18, damage outside [0, 1], negative work w_I, w_II, w_III or
//     damage dissipation (which only grows from 0), open flag or
//     initialised flag not 0/1, non-finite reference) is reported and not
//     propagated: SDV 21 > 0, every other slot it holds unchanged, a message;
//   - a point the law rejects keeps its start state and is reported;
//   - a point that succeeds (SDV 21 = 0) has every state variable finite,
//     damage in [0, 1] and not decreased, w_I and w_III not decreased (w_II
//     may: docs/robustness.md), the flags 0/1,
//     the reference stored; no message at all when every point succeeds;
//   - nothing outside state(1:23, 1, k) is written (other node states,
//     slots beyond 23); state(1:34, 1, k) in single precision with
//     nStates >= 34, where SDV 24-34 hold the low parts of the float pairs
//     and each paired variable is the sum of its two parts (docs/model.md 3),
//     a low part larger than its high part's float spacing a broken rule.
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "fuzz_input.hpp"
#include "mortar/integrator.hpp"
#include "mortar/state_layout.hpp"
#include "paper_sets.hpp"
#include "vuinteraction.h"

namespace {

using Real = mj_real;
using mj_fuzz::Reader;
namespace slot = mortar::slot;
constexpr int kSlots = mortar::kStateCount;  // 23
constexpr const char* kName = "FUZZ-JOINT";
// Substeps (SDV 19 + 20) an input's points may spend before its remaining
// calls are skipped (fuzz_input.hpp, "calls").
constexpr double kInputSubstepBudget = 2e3;
// The largest substep budget per increment (props(18)) an input gets. The
// libFuzzer build's default budget, for nProps < 18, is the same
// (FUZZING_BUILD_MODE_UNSAFE_FOR_PRODUCTION, src/mortar/parameters.hpp); the
// plain build's replay of the seeds keeps the law's 10^5 there.
constexpr double kFuzzMaxSubsteps = 1e3;

size_t count(long n) { return n > 0 ? size_t(n) : 0; }
bool finite(double x) { return std::isfinite(x); }
bool same_bits(Real a, Real b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// Statistics, printed at exit.
struct Stats {
  long inputs = 0, calls = 0, invalid_calls = 0, unpaired = 0, points = 0, corrupt_reported = 0;
  long status[16] = {};  // by SDV 21 after the call
};
Stats stats;

FILE* real_stderr = nullptr;
// MJ_FUZZ_VERBOSE=1: print every call (arguments, props, per-point inputs and
// results), to turn a failing input into a reproducer.
bool verbose = false;

template <class Vec>
void print_values(const char* name, const Vec& v) {
  std::fprintf(real_stderr, "  %s =", name);
  for (const auto& x : v) std::fprintf(real_stderr, " %.17g", double(x));
  std::fputs("\n", real_stderr);
}

[[noreturn]] void fail(const char* format, ...) {
  std::va_list args;
  va_start(args, format);
  std::fputs("fuzz_vuinteraction: PROPERTY VIOLATED: ", real_stderr);
  std::vfprintf(real_stderr, format, args);
  std::fputs("\n", real_stderr);
  va_end(args);
  std::fflush(real_stderr);
  std::abort();
}

// ---------------------------------------------------------------------------
// Independent oracles (docs/model.md section 2, 7.4; docs/abaqus.md).

mortar::Controls controls_with_scheme(int scheme) {
  mortar::Controls c;
  c.scheme = static_cast<mortar::Scheme>(scheme);
  return c;
}

bool props_valid(const std::vector<Real>& props, int n_props) {
  if (n_props < 14) return false;
  const int n = std::min(n_props, 20);
  std::vector<double> p(20, 0.0);
  for (int i = 0; i < n; ++i) {
    p[i] = double(props[i]);
    if (!finite(p[i])) return false;
  }
  const double ft0 = p[2], c0 = p[3], phi0 = p[6], phir = p[7], psi0 = p[9], psir = p[10];
  // Each parameter's own range is data of the law (kParameterRange); the
  // rules between parameters are restated here.
  for (int i = 0; i < mortar::kParameterCount; ++i) {
    const mortar::ParameterRange& r = mortar::kParameterRange[size_t(i)];
    if (!((r.lo_open ? p[i] > r.lo : p[i] >= r.lo) && (r.hi_open ? p[i] < r.hi : p[i] <= r.hi))) return false;
  }
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
  return true;
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

// A low part belongs to its high part: both finite, and the low part at most
// the float spacing above the high part's magnitude.
bool pair_belongs(Real high, Real low) {
  const float h = std::fabs(float(high));
  return finite(double(high)) && finite(double(low)) && std::fabs(float(low)) <= std::nextafter(h, INFINITY) - h;
}

// The documented rules of an incoming state (docs/model.md section 3, the
// law's check_state, and the adapter's flags).
const char* state_violation(const Real* s, bool paired) {
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
  if (s[slot::initialised] == 1 && !finite(double(s[slot::reference_penetration]))) return "non-finite reference";
  return nullptr;
}

// ---------------------------------------------------------------------------
// The block and its arguments, sized as declared.

struct Block {
  int n_dir = 3, n_states = kSlots, n_node_states = 1, n_block = 1, n_props = 14, n_nod_slv = 1;
  std::vector<Real> stress, flux_slv, flux_mst, state, sed, sfd, scd, spd, svd, props, penetration, dr_disp;
  std::vector<int> slave_nodes, master_nodes;
  // The rotation increment (read in 3D: here the unit matrix) and the
  // arguments the adapter does not read, sized as declared all the same.
  std::vector<Real> d_rot, dircos, per_point, dircos_sl, shape_slv, shape_mst, coord_slv, coord_mst, field;

  void allocate() {
    const size_t nb = count(n_block), nd = count(n_dir);
    stress.assign(nd * nb, Real(0));
    for (auto* v : {&flux_slv, &flux_mst, &sed, &sfd, &scd, &spd, &svd, &penetration, &per_point, &field})
      v->assign(nb, Real(0));
    state.assign(count(n_states) * count(n_node_states) * nb, Real(0));
    props.assign(count(n_props), Real(0));
    dr_disp.assign(nd * nb, Real(0));
    slave_nodes.resize(count(n_nod_slv) * nb);
    for (size_t i = 0; i < slave_nodes.size(); ++i) slave_nodes[i] = int(1000 + i);
    master_nodes.assign(4 * nb, 0);
    d_rot.assign(4 * nb, Real(0));  // the unit matrix: the tangent directions do not turn
    for (size_t k = 0; k < nb; ++k) d_rot[4 * k] = d_rot[4 * k + 3] = Real(1);
    dircos.assign(nd * nd * nb, Real(0));
    dircos_sl.assign(nd * nb, Real(0));
    shape_slv.assign(count(n_nod_slv) * nb, Real(0));
    shape_mst.assign(4 * nb, Real(0));
    coord_slv.assign(nd * count(n_nod_slv) * nb, Real(0));
    coord_mst.assign(nd * 4 * nb, Real(0));
  }
  Real* state_of(int k) { return state.data() + long(k) * n_states * n_node_states; }

  // Calls vuinteraction_ with stderr redirected into `capture`; returns what
  // was written there.
  std::string call(FILE* capture) {
    const int n_nod_mst = 4, n_temp = 0, n_fields = 1;
    const int flags[3] = {1, 1, 0};
    const Real r_data[4] = {0, 0, Real(1e-6), 0};
    char name[80], blank[80];
    std::memset(name, ' ', sizeof name);
    std::memset(blank, ' ', sizeof blank);
    std::memcpy(name, kName, std::strlen(kName));
    std::rewind(capture);
    FILE* saved = stderr;
    stderr = capture;  // glibc: stderr is an assignable variable; sanitizers write to fd 2 directly
    vuinteraction_(stress.data(), flux_slv.data(), flux_mst.data(), state.data(), sed.data(), sfd.data(),
                   scd.data(), spd.data(), svd.data(), &n_block, &n_block, &n_block, &n_node_states, &n_nod_slv,
                   &n_nod_mst, &n_dir, &n_states, &n_props, &n_temp, &n_fields, flags, r_data, name, blank,
                   blank, slave_nodes.data(), master_nodes.data(), props.data(), penetration.data(),
                   dr_disp.data(), d_rot.data(), dircos.data(), per_point.data(), per_point.data(),
                   per_point.data(), dircos_sl.data(), shape_slv.data(), shape_mst.data(), coord_slv.data(),
                   coord_mst.data(), coord_slv.data(), coord_mst.data(), per_point.data(), per_point.data(),
                   field.data(), field.data(), 80, 80, 80);
    stderr = saved;
    std::fflush(capture);
    const long written = std::ftell(capture);
    std::string text(count(written), '\0');
    std::rewind(capture);
    if (written > 0 && std::fread(&text[0], 1, text.size(), capture) != text.size()) fail("cannot read capture");
    return text;
  }
};

// ---------------------------------------------------------------------------
// Decoding.

mortar::Parameters paper_set(int which) {
  switch (which % 4) {
    case 0: return mortar::testing::almeida_m15();
    case 1: return mortar::testing::almeida_m34();
    case 2: return mortar::testing::van_der_pluijm(-0.5);
    default: return mortar::testing::atkinson();
  }
}

double unit(Reader& r) { return r.u16() / 65535.0; }
double log_range(Reader& r, double lo, double hi) { return lo * std::pow(hi / lo, unit(r)); }
double lin_range(Reader& r, double lo, double hi) { return lo + (hi - lo) * unit(r); }

// A random valid set over wide ranges (beyond Table 1), from 2 bytes each.
std::vector<double> random_valid_set(Reader& r) {
  const double kn = log_range(r, 1e-2, 1e7);
  const double ks = kn * log_range(r, 1e-2, 2);
  const double ft0 = log_range(r, 1e-3, 1e2);
  const double phi0 = lin_range(r, 0.5, 89.5);
  const double phir = phi0 * lin_range(r, 0.01, 1);
  const double c0 = ft0 * std::tan(phi0 * 3.14159265358979323846 / 180) * lin_range(r, 1.000001, 10);
  const double GIC = log_range(r, 1e-6, 1);
  const double GIIC = log_range(r, 1e-6, 10);
  const double m = (r.u8() & 3) == 0 ? 0.0 : log_range(r, 1, 1e5);
  const double psi0 = lin_range(r, 0, 89);
  const double psir = psi0 * lin_range(r, 0, 1);
  const double n = (r.u8() & 3) == 0 ? 0.0 : log_range(r, 1, 1e5);
  const double bn = lin_range(r, 0, 50), bs = lin_range(r, 0, 20);
  return {kn, ks, ft0, c0, GIC, GIIC, phi0, phir, m, psi0, psir, n, bn, bs};
}

void decode_props(Reader& r, Block& b) {
  const int mode = r.u8() % 4;
  std::vector<double> p(count(b.n_props), 0.0);
  if (mode == 2) {
    for (double& x : p) x = r.f64();
  } else {
    std::vector<double> base(14);
    if (mode == 1) {
      base = random_valid_set(r);
    } else {
      const mortar::Parameters set = paper_set(r.u8());
      for (int i = 0; i < 14; ++i) base[i] = mortar::parameter_at(set, i);
      if (mode == 3)
        for (double& x : base) x *= std::pow(10.0, int8_t(r.u8()) / 16.0);
    }
    for (size_t i = 0; i < p.size(); ++i) p[i] = i < 14 ? base[i] : mj_fuzz::control_value(int(i), r.u8(), r);
  }
  const int overrides = r.u8() % 4;
  for (int o = 0; o < overrides; ++o) {
    const uint8_t index = r.u8();
    const double value = r.f64();
    if (!p.empty()) p[index % p.size()] = value;
  }
  // The substep budget, props(18), lowered to kFuzzMaxSubsteps where the
  // input leaves it at the default (0: 10^5) or sets a larger valid one
  // (fuzz_input.hpp, "props").
  if (p.size() > 17) {
    double& budget = p[17];
    if (budget == 0 || (budget == std::floor(budget) && budget > kFuzzMaxSubsteps && budget <= 1e9))
      budget = kFuzzMaxSubsteps;
  }
  for (size_t i = 0; i < p.size(); ++i) b.props[i] = Real(p[i]);
}

// ---------------------------------------------------------------------------
// Checks after one call.

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

void check_call(const Block& b, const Block& before, const std::string& text, int call) {
  char when_buf[64];
  std::snprintf(when_buf, sizeof when_buf, "call %d", call + 1);
  const std::string when = when_buf;
  check_outputs_finite(b, when);
  const bool args_ok = (b.n_dir == 2 || b.n_dir == 3) && b.n_node_states >= 1 && b.n_states >= kSlots &&
                       b.n_props >= 14;
  const bool valid = args_ok && props_valid(b.props, b.n_props);
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
    // precision): a whole number of the four bits (docs/model.md 9).
    const bool flagged = b.n_states >= mortar::kFlaggedStateCount;
    for (long i = slots; i < per_point; ++i) {
      if (flagged && i == mortar::flag_slot::integration_flags) continue;
      if (!same_bits(s0[i], s1[i])) fail("%s: point %d: state slot %ld (beyond SDV %d or node state 2) written", when.c_str(), k + 1, i + 1, slots);
    }
    if (flagged && !same_bits(s0[mortar::flag_slot::integration_flags], s1[mortar::flag_slot::integration_flags])) {
      const double f = double(s1[mortar::flag_slot::integration_flags]);
      if (!(f >= 0 && f <= 15 && f == std::floor(f))) fail("%s: point %d: SDV 35 = %g is not a set of flags", when.c_str(), k + 1, f);
    }
    const double pen = double(b.penetration[k]);
    if (pen <= -1e30) {  // no opposite surface: nothing happens, nothing carried
      ++stats.unpaired;
      for (int i = 0; i < slots; ++i)
        if (!same_bits(s0[i], s1[i])) fail("%s: unpaired point %d: state slot %d changed", when.c_str(), k + 1, i + 1);
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
    const char* corrupt = state_violation(s0, paired);
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
    if (const char* v = state_violation(s1, paired)) fail("%s: point %d accepted but its new state breaks a rule: %s", when.c_str(), k + 1, v);
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

void print_stats() {
  std::fprintf(real_stderr,
               "fuzz_vuinteraction: %ld inputs, %ld calls (%ld invalid), %ld point-increments integrated "
               "(SDV 21: 0: %ld, 1: %ld, 2: %ld, 3: %ld, 4: %ld, 5: %ld, 6: %ld, 7+: %ld), %ld unpaired, "
               "%ld corrupt incoming states reported\n",
               stats.inputs, stats.calls, stats.invalid_calls, stats.points, stats.status[0], stats.status[1],
               stats.status[2], stats.status[3], stats.status[4], stats.status[5], stats.status[6],
               stats.status[7] + stats.status[8] + stats.status[9], stats.unpaired, stats.corrupt_reported);
}

FILE* capture_file() {
  static FILE* capture = [] {
    real_stderr = stderr;
    const char* v = std::getenv("MJ_FUZZ_VERBOSE");
    verbose = v && *v && *v != '0';
    std::atexit(print_stats);
    FILE* f = std::tmpfile();
    if (!f) {
      std::perror("tmpfile");
      std::abort();
    }
    return f;
  }();
  return capture;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  FILE* capture = capture_file();
  ++stats.inputs;
  Reader r(data, size);
  Block b;
  b.n_dir = mj_fuzz::decode_n_dir(r.u8());
  b.n_states = mj_fuzz::decode_n_states(r.u8());
  b.n_node_states = mj_fuzz::decode_n_node_states(r.u8());
  b.n_block = mj_fuzz::decode_n_block(r.u8());
  b.n_props = mj_fuzz::decode_n_props(r.u8());
  b.n_nod_slv = mj_fuzz::decode_n_node_slv(r.u8());
  b.allocate();
  decode_props(r, b);
  if (r.u8() & 1) {
    for (Real& x : b.stress) x = Real(mj_fuzz::read_value(r));
    for (Real& x : b.sed) x = Real(mj_fuzz::read_value(r));
  }
  const int n_calls = 1 + r.u8() % 8;
  const long per_point = long(count(b.n_states)) * long(count(b.n_node_states));
  double substeps = 0;  // spent by this input so far (see fuzz_input.hpp)
  for (int call = 0; call < n_calls && substeps < kInputSubstepBudget; ++call) {
    const int corruptions = r.u8() % 4;
    for (int c = 0; c < corruptions; ++c) {
      const int k = r.u8(), i = r.u8();
      const double v = mj_fuzz::read_value(r);
      if (b.n_block > 0 && per_point > 0) b.state[(k % b.n_block) * per_point + (i % per_point)] = Real(v);
    }
    for (int k = 0; k < b.n_block; ++k) {
      b.penetration[k] = Real(mj_fuzz::read_value(r, true, double(b.penetration[k])));
      for (int i = 0; i < b.n_dir; ++i) b.dr_disp[k * b.n_dir + i] = Real(mj_fuzz::read_value(r));
    }
    const Block before = b;
    if (verbose) {
      std::fprintf(real_stderr, "call %d: nDir %d nStates %d nNodState %d nBlock %d nProps %d nNodSlv %d\n", call + 1,
                   b.n_dir, b.n_states, b.n_node_states, b.n_block, b.n_props, b.n_nod_slv);
      print_values("props", b.props);
      print_values("penetration", b.penetration);
      print_values("drDisp", b.dr_disp);
      print_values("state in", b.state);
    }
    const std::string text = b.call(capture);
    ++stats.calls;
    if (verbose) {
      print_values("state out", b.state);
      print_values("stress out", b.stress);
      print_values("sed out", b.sed);
      print_values("spd out", b.spd);
      std::fprintf(real_stderr, "  stderr: %s\n", text.c_str());
    }
    check_call(b, before, text, call);
    if (per_point >= kSlots)
      for (int k = 0; k < b.n_block; ++k) {
        const Real* st = b.state_of(k);
        const double spent = double(st[slot::substeps_accepted]) + double(st[slot::substeps_rejected]);
        if (spent > 0 && spent < 1e7) substeps += spent;
      }
  }
  return 0;
}
