// The block function over the solver's flat arrays (src/mortar/integrator.hpp,
// integrate_block): the point-by-point results in the solver layout.
#include <catch2/catch.hpp>

#include <random>
#include <vector>

#include "paper_sets.hpp"
#include "mortar/integrator.hpp"

using namespace mortar;
using namespace mortar::testing;

TEST_CASE("Decision: the block function gives the point-by-point results in the solver layout",
          "[decision][block]") {
  const Model M = model_with(van_der_pluijm(-0.5), Scheme::modified_euler);
  const int n = 7, n_dir = 3, n_states = kStateCount;
  std::vector<double> state(n * n_states, 0.0), traction(n * n_dir), dsep(n * n_dir), energy(n);
  std::vector<State> points(n);
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(-2e-3, 2e-3);
  for (int step = 0; step < 50; ++step) {
    for (double& x : dsep) x = u(rng);
    const int failures = integrate_block(M, n, n_dir, n_states, dsep.data(), state.data(), traction.data(),
                                         BlockOutputs{energy.data(), nullptr});
    CHECK(failures == 0);
    for (int k = 0; k < n; ++k) {
      const IncrementResult r =
          integrate_increment(M, points[k], Vec3(dsep[k * 3], dsep[k * 3 + 1], dsep[k * 3 + 2]));
      for (int i = 0; i < n_dir; ++i) CHECK(traction[k * n_dir + i] == r.traction[i]);
      CHECK(energy[k] == r.elastic_energy);
      std::vector<double> flat(n_states);
      store_state(points[k], flat.data());
      for (int j = 0; j < n_states; ++j) CHECK(state[k * n_states + j] == flat[j]);
    }
  }
}
