// Results identical for any grouping of points into blocks (docs/robustness.md).
//
// Abaqus/Explicit hands the routine blocks of points whose size, order and
// membership change from call to call (and between threads). Every point here
// is integrated twice: alone (nBlock = 1, its own arrays) and inside blocks
// drawn afresh at every call (a random permutation cut into blocks of random
// sizes, arrays gathered and scattered as a solver does). State, stress, sed
// and spd must agree bit for bit after every call.
//
// tests/abi has the fixed-path version (512 points: one block, single blocks,
// one shuffle); this one randomises parameters, paths, block sizes and order.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstring>
#include <numeric>
#include <vector>

#include "abi_block.hpp"
#include "formatted.hpp"

using namespace mj_property;

namespace {

// Per-point storage of everything that persists between calls.
struct PointStore {
  std::vector<Real> state = std::vector<Real>(kStates, Real(0));
  std::vector<Real> stress;
  Real sed = 0, spd = 0;
  Real penetration = 0;
  std::vector<Real> dr_disp;
};

bool same_bits(const Real* a, const Real* b, size_t n) { return std::memcmp(a, b, n * sizeof(Real)) == 0; }

}  // namespace

TEST_CASE("Property: identical results for any grouping of points into blocks (1600 random paths, blocks "
          "redrawn at every call)",
          "[property][blocks]") {
  const int n_sets = scaled(40), n_points = 40, n_increments = 40;
  std::mt19937 rng(20261205);
  long compared = 0, differences = 0, paths = 0, calls = 0;
  for (int set = 0; set < n_sets; ++set) {
    const mortar::Parameters p = random_parameters(rng);
    const mortar::Scheme scheme = set % 3 == 2 ? mortar::Scheme::forward_euler : mortar::Scheme::modified_euler;
    const int n_dir = set % 4 == 3 ? 2 : 3;
    const std::vector<Real> props = props_of(p, scheme);
    CAPTURE(set, n_dir, int(scheme));

    std::vector<Block> alone(n_points, Block(1, n_dir, props));
    std::vector<PointStore> grouped(n_points);
    std::vector<int> family(n_points);
    for (int k = 0; k < n_points; ++k) {
      family[k] = int(rng() % 5);
      const Real reference = Real(uniform(rng, -1e-3, 1e-3));
      alone[k].penetration[0] = reference;
      grouped[k].penetration = reference;
      grouped[k].stress.assign(n_dir, Real(0));
      grouped[k].dr_disp.assign(n_dir, Real(0));
    }
    std::vector<int> order(n_points);
    std::iota(order.begin(), order.end(), 0);
    for (int i = 0; i <= n_increments; ++i) {
      // Inputs of this call (the first call: the reference, no increment).
      for (int k = 0; k < n_points && i > 0; ++k) {
        Step s = random_step(rng, p, family[k], false);
        if (n_dir == 2) s.slip2 = 0;
        apply(alone[k], 0, s);
        grouped[k].penetration = alone[k].penetration[0];
        grouped[k].dr_disp.assign(alone[k].dr_disp.begin(), alone[k].dr_disp.end());
      }
      for (Block& b : alone) b.call();

      // The same points in freshly drawn blocks.
      std::shuffle(order.begin(), order.end(), rng);
      for (int first = 0; first < n_points;) {
        const int size = std::min(n_points - first, 1 + int(rng() % n_points));
        Block b(size, n_dir, props);
        for (int j = 0; j < size; ++j) {
          const PointStore& ps = grouped[order[first + j]];
          std::copy(ps.state.begin(), ps.state.end(), b.state_of(j));
          std::copy(ps.stress.begin(), ps.stress.end(), b.stress_of(j));
          std::copy(ps.dr_disp.begin(), ps.dr_disp.end(), &b.dr_disp[size_t(j) * n_dir]);
          b.sed[j] = ps.sed;
          b.penetration[j] = ps.penetration;
        }
        b.call();
        ++calls;
        for (int j = 0; j < size; ++j) {
          PointStore& ps = grouped[order[first + j]];
          std::copy(b.state_of(j), b.state_of(j) + kStates, ps.state.begin());
          std::copy(b.stress_of(j), b.stress_of(j) + n_dir, ps.stress.begin());
          ps.sed = b.sed[j];
          ps.spd = b.spd[j];
        }
        first += size;
      }

      for (int k = 0; k < n_points; ++k) {
        const Block& a = alone[k];
        const PointStore& g = grouped[k];
        ++compared;
        const bool same = same_bits(a.state.data(), g.state.data(), kStates) &&
                          same_bits(a.stress.data(), g.stress.data(), size_t(n_dir)) && same_bits(&a.sed[0], &g.sed, 1) &&
                          same_bits(&a.spd[0], &g.spd, 1);
        if (!same) {
          ++differences;
          UNSCOPED_INFO("set " << set << " point " << k << " call " << i << " differs");
        }
      }
    }
    paths += n_points;
  }
  INFO(mj_test::formatted(
      "blocks: %ld paths, %ld point-calls compared bit for bit over %ld regrouped block calls, %ld differences", paths,
      compared, calls, differences));
  CHECK(paths == long(n_sets) * n_points);
  CHECK(differences == 0);
}
