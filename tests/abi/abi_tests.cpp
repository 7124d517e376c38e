// Tests of the Abaqus/Explicit adapters through their C ABI, compiled once per
// precision (mj_real from vuinteraction.h): the mapping of the law's signs and
// state (docs/model.md 1 and 3) onto Abaqus's arguments (docs/abaqus.md), the
// error reports, concurrency and block invariance (docs/model.md 10).
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
using mj_test::StderrCapture;

using Real = mj_real;
namespace slot = mortar::slot;
constexpr int kStates = mortar::kStateCount;
constexpr bool kDouble = sizeof(Real) == sizeof(double);
// Relative agreement expected between the adapter and the law itself.
constexpr double kRtol = kDouble ? 1e-12 : 1e-6;

// Almeida M15 as props(1..14), then optionally controls and the shear sign.
std::vector<Real> paper_props(int n_props = 14) {
  return mj_abi_test::props_of<Real>(mortar::testing::almeida_m15(), n_props);
}

bool all_finite(const std::vector<Real>& v) {
  return std::all_of(v.begin(), v.end(), [](Real x) { return std::isfinite(double(x)); });
}

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

namespace {

// A rejected block: the message names the routine, the interaction, the
// argument and the rule; every point carries `code` in SDV 21; the outputs
// are finite and the stress is what came in.
void check_rejected(const std::string& message, const std::vector<std::string>& parts, GeneralContact& gc,
                    int code, const std::vector<Real>& stress_in) {
  INFO("stderr: " << message);
  for (const std::string& part : parts) CHECK(message.find(part) != std::string::npos);
  for (int k = 0; k < gc.n_block; ++k) CHECK(gc.state_of(k)[slot::status] == Real(code));
  CHECK(gc.stress == stress_in);
  CHECK(all_finite(gc.sed));
  CHECK(all_finite(gc.spd));
  CHECK(std::all_of(gc.spd.begin(), gc.spd.end(), [](Real x) { return x == Real(0); }));
}

GeneralContact initialised_block(std::vector<Real> props, int states = kStates) {
  GeneralContact gc(3, 3, std::move(props), states);
  std::fill(gc.stress.begin(), gc.stress.end(), Real(0.25));
  return gc;
}

}  // namespace

TEST_CASE("bad arguments are reported and leave finite outputs", "[abi][errors]") {
  SECTION("nDir") {
    GeneralContact gc = initialised_block(paper_props());
    gc.n_dir = 1;  // fewer rows than allocated: still within the arrays
    const std::vector<Real> stress_in = gc.stress;
    StderrCapture err;
    gc.call();
    check_rejected(err.text(), {"VUINTERACTION", "interaction 'JOINT-A'", "nDir = 1", "2 (2D) or 3 (3D)"}, gc, -1,
                   stress_in);
  }
  SECTION("nStates below the layout") {
    GeneralContact gc(3, 3, paper_props(), 22);
    std::fill(gc.stress.begin(), gc.stress.end(), Real(0.25));
    const std::vector<Real> stress_in = gc.stress;
    StderrCapture err;
    gc.call();
    check_rejected(err.text(), {"nStates = 22", "at least 23 state variables"}, gc, -2, stress_in);
  }
  SECTION("nStates too small to hold the status: nothing outside the array is touched") {
    GeneralContact gc(3, 3, paper_props(), 10, 8);
    std::fill(gc.state.begin(), gc.state.end(), Real(-3));
    StderrCapture err;
    gc.call();
    const std::string message = err.text();
    CHECK(message.find("nStates = 10") != std::string::npos);
    CHECK(std::all_of(gc.state.begin(), gc.state.end(), [](Real x) { return x == Real(-3); }));
    CHECK(all_finite(gc.stress));
  }
  SECTION("nProps") {
    GeneralContact gc = initialised_block(paper_props(13));
    const std::vector<Real> stress_in = gc.stress;
    StderrCapture err;
    gc.call();
    check_rejected(err.text(), {"nProps = 13", "14 parameters"}, gc, -3, stress_in);
  }
  SECTION("nNodState") {
    GeneralContact gc = initialised_block(paper_props());
    gc.n_node_states = 0;
    StderrCapture err;
    gc.call();
    CHECK(err.text().find("nNodState = 0") != std::string::npos);
    CHECK(all_finite(gc.stress));
  }
  SECTION("non-finite incoming stress is not passed back") {
    GeneralContact gc = initialised_block(paper_props(13));
    gc.stress[1] = std::numeric_limits<Real>::quiet_NaN();
    gc.sed[2] = std::numeric_limits<Real>::infinity();
    StderrCapture err;
    gc.call();
    CHECK(all_finite(gc.stress));
    CHECK(all_finite(gc.sed));
  }
}

TEST_CASE("invalid properties and controls are reported with name, value and rule", "[abi][errors]") {
  struct Case {
    int index;
    double value;
    std::vector<std::string> parts;
  };
  const std::vector<Case> cases = {
      {3, 0.5, {"'c0' (props(4))", "= 0.5", "c0 > ft0*tan(phi0)"}},
      {0, -1.0, {"'kn' (props(1))", "0.01 <= kn <= 1e6 N/mm^3"}},
      {0, 1e30, {"'kn' (props(1))", "= 1e+30", "kn <= 1e6 N/mm^3"}},
      {7, 45.0, {"'phir' (props(8))", "phir <= phi0"}},
      {14, 4.0, {"props(15)", "scheme is 1"}},
      {15, 2.0, {"props(16)", "STOL"}},
      {19, 0.5, {"props(20)", "0 (default, = -1), -1 or +1"}},
  };
  for (const Case& c : cases) {
    std::vector<Real> props = paper_props(20);
    props[c.index] = Real(c.value);
    GeneralContact gc = initialised_block(props);
    const std::vector<Real> stress_in = gc.stress;
    StderrCapture err;
    gc.call();
    std::vector<std::string> parts = c.parts;
    parts.push_back("interaction 'JOINT-A'");
    check_rejected(err.text(), parts, gc, -4, stress_in);
  }
}

TEST_CASE("SDV 21 reads back: the law's names for its codes, the adapter's for its own", "[abi][errors]") {
  using namespace mj_adapter;
  // The numbers docs/abaqus.md documents and the harness reads.
  CHECK(kBadDirections == -1);
  CHECK(kBadStateCount == -2);
  CHECK(kBadPropCount == -3);
  CHECK(kBadProperty == -4);
  CHECK(kBadNodeStates == -5);
  CHECK(kBadRotation == -6);
  CHECK(kInternalError == -9);
  for (int code = 0; code <= int(mortar::Failure::local_solve_failed); ++code)
    CHECK(std::string(status_meaning(code)) == mortar::failure_name(static_cast<mortar::Failure>(code)));
  CHECK(std::string(status_meaning(kBadDirections)) == "nDir is not 2 or 3");
  CHECK(std::string(status_meaning(kBadStateCount)) == "fewer than 23 state variables");
  CHECK(std::string(status_meaning(kBadPropCount)) == "fewer than 14 properties");
  CHECK(std::string(status_meaning(kBadProperty)).find("a property breaks its rule") == 0);
  CHECK(std::string(status_meaning(kBadNodeStates)) == "nNodState < 1");
  CHECK(std::string(status_meaning(kBadRotation)).find("dRot of a point is not a rotation") == 0);
  CHECK(std::string(status_meaning(kInternalError)) == "the routine's internal error");
}

TEST_CASE("messages name the interaction: trailing blanks cut, a hidden length beyond 1..80 read as 80", "[abi][errors]") {
  using mj_adapter::make_caller;
  const Name80 name("JOINT-A");
  auto named = [](const mj_adapter::Caller& c) { return std::string(c.name, c.name_length); };
  CHECK(named(make_caller("VUINTER", name.text, 80)) == "JOINT-A");
  CHECK(named(make_caller("VUINTER", name.text, 0)) == "JOINT-A");
  CHECK(named(make_caller("VUINTER", name.text, 1 << 20)) == "JOINT-A");
  CHECK(named(make_caller("VUINTER", name.text, 3)) == "JOI");
  CHECK(named(make_caller("VUINTER", Name80("").text, 80)).empty());
  CHECK(named(make_caller("VUINTER", nullptr, 80)) == "?");
}

TEST_CASE("the first array size that breaks its rule is the one reported", "[abi][errors]") {
  const mj_adapter::ArgumentNames names = {"nDir", "nDir is 2 (2D) or 3 (3D)", "nStates", "nProps", "dRot"};
  using mj_adapter::check_counts;
  CHECK(check_counts({1, 0, 0, 0}, names).code == mj_adapter::kBadDirections);
  CHECK(check_counts({3, 0, 0, 0}, names).code == mj_adapter::kBadNodeStates);
  CHECK(check_counts({3, 1, 22, 0}, names).code == mj_adapter::kBadStateCount);
  CHECK(std::string(check_counts({3, 1, 22, 0}, names).argument) == "nStates");
  CHECK(check_counts({2, 1, 23, 13}, names).code == mj_adapter::kBadPropCount);
  CHECK(check_counts({2, 1, 23, 14}, names).code == 0);
}

TEST_CASE("VUINTER reports bad arguments too", "[abi][errors]") {
  ContactPair cp(2, 3, paper_props(), 22);
  StderrCapture err;
  cp.call();
  const std::string message = err.text();
  CHECK(message.find("VUINTER, interaction 'PAIR-B'") != std::string::npos);
  CHECK(message.find("nStateVar = 22") != std::string::npos);
  CHECK(cp.statev[slot::status] == Real(-2));
  CHECK(cp.statev[22 + slot::status] == Real(-2));
}

TEST_CASE("a point the law rejects keeps its start state and is reported", "[abi][errors]") {
  GeneralContact gc(3, 3, paper_props());
  gc.call();
  gc.dr_disp[3 * 1 + 1] = std::numeric_limits<Real>::infinity();  // point 2: slip increment not finite
  gc.penetration = {Real(-1e-4), Real(-1e-4), Real(-1e-4)};
  StderrCapture err;
  gc.call();
  const std::string message = err.text();
  INFO("stderr: " << message);
  CHECK(message.find("point 2 of 3 (slave node 1002)") != std::string::npos);
  CHECK(message.find("separation increment is not finite") != std::string::npos);
  CHECK(gc.state_of(0)[slot::status] == Real(0));
  CHECK(gc.state_of(1)[slot::status] == Real(int(mortar::Failure::non_finite_increment)));
  CHECK(gc.state_of(2)[slot::status] == Real(0));
  CHECK(gc.state_of(1)[slot::separation_n] == Real(0));  // start state kept
  CHECK(gc.state_of(0)[slot::separation_n] != Real(0));
  CHECK(all_finite(gc.stress));
  CHECK(all_finite(gc.sed));
}

TEST_CASE("a non-finite penetration at the first call does not become the reference", "[abi][errors]") {
  GeneralContact gc(2, 2, paper_props());
  gc.penetration = {std::numeric_limits<Real>::quiet_NaN(), Real(0)};
  StderrCapture err;
  gc.call();
  CHECK(err.text().find("point 1 of 2") != std::string::npos);
  CHECK(gc.state_of(0)[slot::initialised] == Real(0));
  CHECK(gc.state_of(0)[slot::status] == Real(int(mortar::Failure::non_finite_increment)));
  CHECK(gc.state_of(1)[slot::initialised] == Real(1));
  CHECK(all_finite(gc.stress));
}
