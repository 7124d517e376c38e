// Tests of the Abaqus/Explicit adapters through their C ABI, compiled once per
// precision (mj_real from vuinteraction.h): the mapping of the law's signs and
// state (docs/model.md 1 and 3) onto Abaqus's arguments (docs/abaqus.md),
// concurrency and block invariance (docs/model.md 10); the error reports are
// error_tests.cpp.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>
#include <thread>
#include <vector>

#include <catch2/catch.hpp>

#include "abi_support.hpp"
#include "explicit_calls.hpp"
#include "adapter/arguments.hpp"
#include "adapter/report.hpp"
#include "adapter/status_codes.hpp"
#include "mortar/integrator.hpp"
#include "mortar/state_layout.hpp"
#include "mortar/state_pairs.hpp"
#include "paper_sets.hpp"
#include "stderr_capture.hpp"
#include "vuinteraction.h"

namespace {

using mj_abi_test::ContactPair;
using mj_abi_test::GeneralContact;
using mj_abi_test::Name80;
using mj_abi_test::paper_props;
using mj_test::StderrCapture;

using Real = mj_real;
namespace slot = mortar::slot;
constexpr int kStates = mortar::kStateCount;
constexpr bool kDouble = sizeof(Real) == sizeof(double);
// Relative agreement expected between the adapter and the law itself.
constexpr double kRtol = kDouble ? 1e-12 : 1e-6;


using mj_abi_test::all_finite;

// A family of loading paths (penetration, two slips) for point k at step i of
// n: opening to separation, opening and closing, shear under pressure, cyclic
// shear, mixed opening and shear.
struct PathInput {
  double penetration, slip1, slip2;
};
PathInput path(int k, int i, int n) {
  const double t = double(i) / n, amp = 1 + 0.1 * (k % 7), p0 = 1e-4 * (k % 5);
  const double ramp = std::min(1.0, 10 * t), pi = 3.14159265358979;
  switch (k % 5) {
    case 0: return {p0 - 0.03 * amp * t, 0, 0};
    case 1: return {p0 - 0.008 * amp * std::sin(2 * pi * t), 0, 0};
    case 2: return {p0 + 7e-4 * amp * ramp, 0.03 * amp * std::max(0.0, t - 0.1), 0.01 * amp * t};
    case 3: return {p0 + 5e-4 * amp * ramp, 0.01 * amp * std::sin(4 * pi * t), -0.004 * amp * t};
    default: return {p0 - 4e-3 * amp * t, 6e-3 * amp * t, -4e-3 * amp * t};
  }
}

// Sets penetration and drDisp of every point of `gc` for step i of n.
void set_inputs(GeneralContact& gc, int i, int n) {
  for (int k = 0; k < gc.n_block; ++k) {
    const PathInput now = path(k, i, n), before = path(k, std::max(i - 1, 0), n);
    gc.penetration[k] = Real(now.penetration);
    Real* dd = &gc.dr_disp[k * gc.n_dir];
    dd[0] = Real(before.penetration - now.penetration);
    dd[1] = Real(now.slip1 - before.slip1);
    if (gc.n_dir == 3) dd[2] = Real(now.slip2 - before.slip2);
  }
}

mortar::Model paper_model() { return mortar::make_model_checked(mortar::testing::almeida_m15()); }

}  // namespace

TEST_CASE("the first call stores the reference and defines the zero", "[abi][mapping]") {
  GeneralContact gc(3, 3, paper_props());
  gc.penetration = {Real(0.1), Real(-0.05), Real(0)};
  std::fill(gc.dr_disp.begin(), gc.dr_disp.end(), Real(1e3));  // ignored at the first call
  gc.call();
  for (int k = 0; k < 3; ++k) {
    const Real* s = gc.state_of(k);
    CHECK(s[slot::reference_penetration] == gc.penetration[k]);
    CHECK(s[slot::initialised] == Real(1));
    for (int i = 0; i < slot::reference_penetration; ++i) CHECK(s[i] == Real(0));
    for (int i = 0; i < 3; ++i) CHECK(gc.stress_of(k)[i] == Real(0));
    CHECK(gc.sed[k] == Real(0));
    CHECK(gc.spd[k] == Real(0));
  }
}

TEST_CASE("normal: separation is reference minus penetration, stress is a pressure", "[abi][mapping]") {
  const mortar::Parameters p = mortar::testing::almeida_m15();
  GeneralContact gc(2, 3, paper_props());
  gc.penetration = {Real(0.01), Real(0.01)};
  gc.call();
  // Point 1 opens by 1e-3 mm (elastic, below ft0/kn = 2.4e-3 mm); point 2
  // is pressed by 2e-3 mm. drDisp(1) must not matter: NaN.
  gc.penetration = {Real(0.009), Real(0.012)};
  std::fill(gc.dr_disp.begin(), gc.dr_disp.end(), Real(0));
  gc.dr_disp[0] = gc.dr_disp[3] = std::numeric_limits<Real>::quiet_NaN();
  gc.call();
  const double open = 0.01 - double(Real(0.009)), shut = 0.01 - double(Real(0.012));
  CHECK(double(gc.stress_of(0)[0]) == Approx(-p.kn * open).epsilon(kRtol * 10));  // tension: negative pressure
  CHECK(double(gc.stress_of(1)[0]) == Approx(-p.kn * shut).epsilon(kRtol * 10));  // compression: positive
  CHECK(double(gc.state_of(0)[slot::separation_n]) == Approx(open).epsilon(kRtol * 10));
  CHECK(double(gc.sed[0]) == Approx(0.5 * p.kn * open * open).epsilon(kRtol * 10));
  CHECK(all_finite(gc.stress));
  CHECK(gc.state_of(0)[slot::status] == Real(0));
}

TEST_CASE("shear: slips sum drDisp(2..nDir), stress(2..) = -tau unless props(20) = +1", "[abi][mapping]") {
  const mortar::Parameters p = mortar::testing::almeida_m15();
  for (const int n_dir : {2, 3}) {
    for (const double sign : {0.0, -1.0, 1.0}) {
      std::vector<Real> props = paper_props(20);
      props[19] = Real(sign);
      GeneralContact gc(1, n_dir, props);
      gc.call();  // reference: penetration 0
      for (int step = 0; step < 2; ++step) {  // two elastic increments of 2e-4 mm (ks slip < c0/ks)
        gc.dr_disp[1] = Real(2e-4);
        if (n_dir == 3) gc.dr_disp[2] = Real(-1e-4);
        gc.call();
      }
      const double expected_sign = sign == 0 ? -1.0 : sign;
      const double s1 = 2 * double(Real(2e-4)), s2 = n_dir == 3 ? 2 * double(Real(-1e-4)) : 0.0;
      CHECK(double(gc.state_of(0)[slot::separation_s1]) == Approx(s1).epsilon(kRtol * 10));
      CHECK(double(gc.state_of(0)[slot::separation_s2]) == Approx(s2).epsilon(kRtol * 10).margin(1e-30));
      CHECK(double(gc.stress_of(0)[1]) == Approx(expected_sign * p.ks * s1).epsilon(kRtol * 10));
      if (n_dir == 3) CHECK(double(gc.stress_of(0)[2]) == Approx(expected_sign * p.ks * s2).epsilon(kRtol * 10));
      CHECK(double(gc.sed[0]) == Approx(0.5 * p.ks * (s1 * s1 + s2 * s2)).epsilon(kRtol * 10));
    }
  }
}

TEST_CASE("energies: sed elastic, spd all inelastic increments, the rest zero", "[abi][mapping]") {
  GeneralContact gc(10, 3, paper_props());
  const int n = 60;
  std::vector<double> spd_sum(10, 0.0);
  for (int i = 0; i <= n; ++i) {
    set_inputs(gc, i, n);
    std::fill(gc.sfd.begin(), gc.sfd.end(), Real(7));  // write-only outputs must be overwritten
    std::fill(gc.flux_slv.begin(), gc.flux_slv.end(), Real(7));
    gc.call();
    for (int k = 0; k < 10; ++k) {
      spd_sum[k] += double(gc.spd[k]);
      CHECK(gc.sfd[k] == Real(0));
      CHECK(gc.scd[k] == Real(0));
      CHECK(gc.svd[k] == Real(0));
      CHECK(gc.flux_slv[k] == Real(0));
      CHECK(gc.flux_mst[k] == Real(0));
    }
  }
  const mortar::Model model = paper_model();
  for (int k = 0; k < 10; ++k) {
    const Real* s = gc.state_of(k);
    const double booked =
        double(s[slot::dissipation_plastic]) + double(s[slot::dissipation_damage]) + double(s[slot::energy_unilateral]);
    CHECK(spd_sum[k] == Approx(booked).epsilon(kDouble ? 1e-9 : 1e-4).margin(1e-12));
    // In single precision the stored state is rounded, and the elastic part
    // delta - delta_p loses digits to cancellation: a looser check there.
    mortar::State state;
    mortar::load_state(s, state);
    CHECK(double(gc.sed[k]) == Approx(mortar::elastic_energy(model, state)).epsilon(kDouble ? 1e-12 : 1e-3).margin(1e-15));
  }
  CHECK(*std::max_element(spd_sum.begin(), spd_sum.end()) > 0);  // the paths are inelastic
}

TEST_CASE("VUINTER: rdisp(1) is the penetration, unpaired nodes carry nothing", "[abi][mapping]") {
  const mortar::Parameters p = mortar::testing::almeida_m15();
  ContactPair cp(2, 2, paper_props());
  cp.rdisp = {Real(0.02), Real(0), Real(-1e36), Real(0)};  // node 2 has no master yet
  cp.call();
  CHECK(cp.statev[slot::initialised] == Real(1));
  CHECK(cp.statev[kStates + slot::initialised] == Real(0));
  cp.rdisp = {Real(0.021), Real(3e-4), Real(-1e36), Real(0)};
  cp.drdisp = {Real(1e-3), Real(3e-4), Real(5), Real(5)};
  cp.call();
  const double shut = double(Real(0.021)) - double(Real(0.02));
  CHECK(double(cp.stress[0]) == Approx(p.kn * shut).epsilon(kRtol * 100));
  CHECK(double(cp.stress[1]) == Approx(-p.ks * double(Real(3e-4))).epsilon(kRtol * 10));
  CHECK(cp.stress[2] == Real(0));
  CHECK(cp.stress[3] == Real(0));
  CHECK(cp.statev[kStates + slot::initialised] == Real(0));
  // Paired at last: the node's first call defines its zero.
  cp.rdisp[2] = Real(0.005);
  cp.call();
  CHECK(cp.statev[kStates + slot::reference_penetration] == Real(0.005));
  CHECK(cp.stress[2] == Real(0));
}

TEST_CASE("VUINTER: nStateVar >= 34 keeps single precision's float pairs and double leaves SDV 24 on alone",
          "[abi][state]") {
  ContactPair cp(1, 2, paper_props(), mortar::kPairedStateCount);
  // Double: whatever SDV 24-34 hold stays there; single: a fresh (zero) array.
  if (kDouble) std::fill(cp.statev.begin() + kStates, cp.statev.end(), Real(0.25));
  cp.call();
  cp.rdisp = {Real(-0.01), Real(0)};  // opened past the peak: every paired variable moves
  cp.call();
  CHECK(cp.statev[slot::status] == Real(0));
  CHECK(cp.statev[slot::plastic_n] > Real(0));
  int low_parts = 0;
  for (const mortar::SlotPair& p : mortar::kPairedSlots) {
    if (kDouble) {
      CHECK(cp.statev[p.low] == Real(0.25));
    } else {
      CHECK(mortar::pair_consistent(float(cp.statev[p.high]), float(cp.statev[p.low])));
      low_parts += cp.statev[p.low] != Real(0);
    }
  }
  if (!kDouble) CHECK(low_parts > 0);
}

TEST_CASE("agreement with the law along mixed paths, point by point", "[abi][mapping]") {
  const mortar::Model model = paper_model();
  GeneralContact gc(5, 3, paper_props());
  std::vector<mortar::State> law(5);
  const int n = 80;
  for (int i = 0; i <= n; ++i) {
    set_inputs(gc, i, n);
    gc.call();
    if (i == 0) continue;
    for (int k = 0; k < 5; ++k) {
      const PathInput now = path(k, i, n), before = path(k, i - 1, n);
      const mortar::Vec3 d(before.penetration - now.penetration, now.slip1 - before.slip1, now.slip2 - before.slip2);
      const mortar::IncrementResult r = mortar::integrate_increment(model, law[k], d);
      const double scale = model.p.ft0;
      CHECK(double(gc.stress_of(k)[0]) == Approx(-r.traction[0]).margin(kDouble ? 1e-9 * scale : 1e-3 * scale));
      CHECK(double(gc.stress_of(k)[1]) == Approx(-r.traction[1]).margin(kDouble ? 1e-9 * scale : 1e-3 * scale));
      CHECK(double(gc.stress_of(k)[2]) == Approx(-r.traction[2]).margin(kDouble ? 1e-9 * scale : 1e-3 * scale));
    }
  }
}

TEST_CASE("concurrent calls on disjoint blocks give the single-thread results", "[abi][threads]") {
  const int n_points = 2048, n_threads = 8, block = n_points / n_threads, n = 60;
  auto run = [&](bool threaded) {
    std::vector<GeneralContact> blocks;
    for (int b = 0; b < n_threads; ++b) blocks.emplace_back(block, 3, paper_props(20));
    auto drive = [&](int b) {
      GeneralContact& gc = blocks[b];
      for (int i = 0; i <= n; ++i) {
        for (int k = 0; k < block; ++k) {  // point identity: b * block + k
          const PathInput now = path(b * block + k, i, n), before = path(b * block + k, std::max(i - 1, 0), n);
          gc.penetration[k] = Real(now.penetration);
          gc.dr_disp[3 * k + 1] = Real(now.slip1 - before.slip1);
          gc.dr_disp[3 * k + 2] = Real(now.slip2 - before.slip2);
        }
        gc.call();
      }
    };
    if (threaded) {
      std::vector<std::thread> threads;
      for (int b = 0; b < n_threads; ++b) threads.emplace_back(drive, b);
      for (std::thread& t : threads) t.join();
    } else {
      for (int b = 0; b < n_threads; ++b) drive(b);
    }
    return blocks;
  };
  const std::vector<GeneralContact> serial = run(false), parallel = run(true);
  for (int b = 0; b < n_threads; ++b) {
    CHECK(serial[b].state == parallel[b].state);
    CHECK(serial[b].stress == parallel[b].stress);
    CHECK(serial[b].sed == parallel[b].sed);
    CHECK(serial[b].spd == parallel[b].spd);
  }
}

TEST_CASE("block invariance: nBlock = 512, nBlock = 1 and shuffled give identical results", "[abi][blocks]") {
  const int n_points = 512, n = 50;
  GeneralContact whole(n_points, 3, paper_props());
  std::vector<GeneralContact> singles(n_points, GeneralContact(1, 3, paper_props()));
  GeneralContact shuffled(n_points, 3, paper_props());
  std::vector<int> order(n_points);  // position j of `shuffled` holds point order[j]
  for (int j = 0; j < n_points; ++j) order[j] = (263 * j) % n_points;
  int differences = 0;
  for (int i = 0; i <= n; ++i) {
    set_inputs(whole, i, n);
    whole.call();
    for (int k = 0; k < n_points; ++k) {
      singles[k].penetration[0] = whole.penetration[k];
      std::copy_n(&whole.dr_disp[3 * k], 3, singles[k].dr_disp.begin());
      singles[k].call();
    }
    for (int j = 0; j < n_points; ++j) {
      shuffled.penetration[j] = whole.penetration[order[j]];
      std::copy_n(&whole.dr_disp[3 * order[j]], 3, &shuffled.dr_disp[3 * j]);
    }
    shuffled.call();
    for (int j = 0; j < n_points; ++j) {
      const int k = order[j];
      const GeneralContact& one = singles[k];
      differences += !std::equal(one.state.begin(), one.state.end(), whole.state_of(k));
      differences += !std::equal(one.state.begin(), one.state.end(), shuffled.state_of(j));
      differences += !std::equal(one.stress.begin(), one.stress.end(), whole.stress_of(k));
      differences += !std::equal(one.stress.begin(), one.stress.end(), shuffled.stress_of(j));
      differences += one.sed[0] != whole.sed[k] || one.sed[0] != shuffled.sed[j];
      differences += one.spd[0] != whole.spd[k] || one.spd[0] != shuffled.spd[j];
    }
  }
  CHECK(differences == 0);
}
