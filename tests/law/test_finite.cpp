// mortar/finite.hpp: the finite tests of the adapters' stores, here the
// twelve-value test of the single-precision elastic store
// (StateStorage::store_elastic_pairs).
#include <catch2/catch.hpp>

#include <algorithm>
#include <limits>

#include "mortar/finite.hpp"

using mortar::all_finite_values;

TEST_CASE("Finite test: all_finite_values finds a non-finite value in any of its twelve places", "[finite]") {
  const float bad[] = {std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity(),
                       std::numeric_limits<float>::quiet_NaN()};
  float v[12];
  for (int i = 0; i < 12; ++i) v[i] = float(i) - 5.5f;
  v[3] = -0.0f;
  v[7] = std::numeric_limits<float>::max();
  v[9] = std::numeric_limits<float>::denorm_min();
  CHECK(all_finite_values(v));
  for (int i = 0; i < 12; ++i)
    for (float b : bad) {
      float w[12];
      std::copy(v, v + 12, w);
      w[i] = b;
      CHECK_FALSE(all_finite_values(w));
    }
}
