// The elastic lanes (adapter/explicit_block_lanes.hpp) through the routine:
// points integrated two at a time in a block write what each writes alone
// (nBlock = 1, where no point has a partner), bit for bit, whatever its
// partner is doing: elastic or plastic, worn or not, turned by dRot or not,
// unpaired, or past the block's end; in 2D and 3D, with the plain layout and
// (single precision) with float pairs (docs/model.md 10, block invariance).
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <type_traits>
#include <vector>

#include <catch2/catch.hpp>

#include "explicit_calls.hpp"
#include "mortar/failure.hpp"
#include "paper_sets.hpp"
#include "stderr_capture.hpp"

namespace {

using mj_abi_test::GeneralContact;
using Real = mj_real;

// Point k's inputs at step i: pressed at 0.5 MPa, then increments of 1e-7 mm
// back and forth (elastic) with, on some points at some steps, a slip of
// 2e-3 mm (plastic, wearing the joint for later steps), an opening, a turn
// of the tangents or no opposite surface.
struct Step {
  double penetration, slip1, slip2, angle;
};
Step step_of(int k, int i, double pressed, std::mt19937& rng) {
  const double back_and_forth = (i % 2 ? 1e-7 : -1e-7) * (1 + k % 3);
  Step s{pressed + back_and_forth, back_and_forth, -0.5 * back_and_forth, 0.0};
  const double u = std::uniform_real_distribution<double>(0, 1)(rng);
  if (u < 0.08) s.slip1 = 2e-3;
  else if (u < 0.12) s.penetration = -1e-3;   // open
  else if (u < 0.16) s.angle = 0.02;          // the tangents turn
  else if (u < 0.18) s.penetration = -1e36;   // no opposite surface
  return s;
}

void check_block_against_singles(int n_dir, int n_states) {
  const std::vector<Real> props = mj_abi_test::props_of<Real>(mortar::testing::almeida_m15(), 14);
  const double pressed = 0.5 / mortar::testing::almeida_m15().kn;
  const int n_points = 37;  // odd: the last point has no partner
  GeneralContact block(n_points, n_dir, props, n_states);
  std::vector<GeneralContact> singles(n_points, GeneralContact(1, n_dir, props, n_states));
  std::mt19937 rng(41);
  int differences = 0;
  for (int i = 0; i < 60; ++i) {
    for (int k = 0; k < n_points; ++k) {
      const Step s = i == 0 ? Step{0, 0, 0, 0} : step_of(k, i, pressed, rng);
      block.penetration[k] = Real(s.penetration);
      Real* dd = &block.dr_disp[k * n_dir];
      dd[1] = Real(s.slip1);
      if (n_dir == 3) dd[2] = Real(s.slip2);
      Real* rot = &block.d_rot[4 * k];
      rot[0] = rot[3] = Real(std::cos(s.angle));
      rot[1] = Real(-std::sin(s.angle));
      rot[2] = Real(std::sin(s.angle));
      GeneralContact& one = singles[k];
      one.penetration[0] = block.penetration[k];
      std::copy_n(dd, n_dir, one.dr_disp.begin());
      std::copy_n(rot, 4, one.d_rot.begin());
      one.call();
    }
    block.call();
    for (int k = 0; k < n_points; ++k) {
      const GeneralContact& one = singles[k];
      differences += !std::equal(one.state.begin(), one.state.end(), block.state_of(k));
      differences += !std::equal(one.stress.begin(), one.stress.end(), block.stress_of(k));
      differences += one.sed[0] != block.sed[k] || one.spd[0] != block.spd[k];
    }
  }
  CHECK(differences == 0);
}

}  // namespace

TEST_CASE("elastic lanes: points in pairs write what each writes alone, bit for bit", "[abi][blocks][lanes]") {
  for (int n_dir : {2, 3}) {
    for (int n_states : {mortar::kStateCount, mortar::kPairedStateCount}) {
      INFO("nDir = " << n_dir << ", state variables = " << n_states);
      check_block_against_singles(n_dir, n_states);
    }
  }
}

// The lanes take a point only when its values fit in the routine's Real, a
// test made in double (|x| <= FLT_MAX) that must leave the outputs as the
// floats' own test (store_elastic) leaves them. Pressed joints of M15 whose
// elastic energy, 0.5 (kn e_n^2 + ks e_s^2), steps in 2^101 from below
// FLT_MAX, through the band above it that float() still rounds to FLT_MAX
// (up to half a spacing, 2^103, above it), to beyond: point by point, the
// block writes what each point writes alone, and (single precision) the
// three kinds come out as they must, stored or rejected.
TEST_CASE("elastic lanes: points whose energy nears float's largest write what each writes alone", "[abi][blocks][lanes]") {
  const mortar::Parameters m15 = mortar::testing::almeida_m15();
  const std::vector<Real> props = mj_abi_test::props_of<Real>(m15, 14);
  const double most = std::numeric_limits<float>::max(), step = std::ldexp(1.0, 101);
  // A pressed normal separation with an energy about 2^110 below FLT_MAX
  // (its float input moves that by about 2^105), then slips that add 2^101
  // a point.
  const float pressed = float(std::sqrt(2 * (most - std::ldexp(1.0, 110)) / m15.kn));
  const double normal_energy = 0.5 * (m15.kn * double(pressed)) * double(pressed);
  const int n_points = 24;
  GeneralContact block(n_points, 3, props, mortar::kPairedStateCount);
  std::vector<GeneralContact> singles(n_points, GeneralContact(1, 3, props, mortar::kPairedStateCount));
  std::vector<double> energy(n_points);
  int differences = 0;
  mj_test::StderrCapture err;  // the rejected points are reported
  for (int i = 0; i < 2; ++i) {  // a first call at rest, then the increment
    for (int k = 0; k < n_points; ++k) {
      const double target = most - 8 * step + k * step;
      const float slip = float(std::sqrt(2 * (target - normal_energy) / m15.ks));
      energy[k] = normal_energy + 0.5 * (m15.ks * double(slip)) * double(slip);
      block.penetration[k] = i == 0 ? Real(0) : Real(pressed);
      block.dr_disp[k * 3 + 1] = i == 0 ? Real(0) : Real(slip);
      GeneralContact& one = singles[k];
      one.penetration[0] = block.penetration[k];
      one.dr_disp[1] = block.dr_disp[k * 3 + 1];
      one.call();
    }
    block.call();
  }
  int below = 0, band = 0, beyond = 0;
  for (int k = 0; k < n_points; ++k) {
    const GeneralContact& one = singles[k];
    differences += !std::equal(one.state.begin(), one.state.end(), block.state_of(k));
    differences += !std::equal(one.stress.begin(), one.stress.end(), block.stress_of(k));
    differences += one.sed[0] != block.sed[k] || one.spd[0] != block.spd[k];
    if (!std::is_same_v<Real, float>) continue;
    // The kinds by this test's own sum, 2^80 clear of their edges (its
    // rounding differs from the law's by far less).
    const double margin = std::ldexp(1.0, 80), half_spacing = std::ldexp(1.0, 103);
    const int status = int(one.state[mortar::slot::status]);
    if (energy[k] < most - margin) {
      below += status == 0 && std::isfinite(one.sed[0]);
    } else if (energy[k] > most + margin && energy[k] < most + half_spacing - margin) {
      band += status == 0 && one.sed[0] == Real(most);
    } else if (energy[k] > most + half_spacing + margin) {
      beyond += status == int(mortar::Failure::non_finite_result);
    }
  }
  CHECK(differences == 0);
  if (std::is_same_v<Real, float>) {
    CHECK(below >= 2);
    CHECK(band >= 2);
    CHECK(beyond >= 2);
  }
}
