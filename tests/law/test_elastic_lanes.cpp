// The elastic shortcut's lanes (mortar/batch.hpp) against the
// scalar shortcut they stand in for (mortar/elastic.hpp): every lane makes
// elastic_increment()'s decision and, when it books, the same end
// separation, traction and energy to the last bit (docs/model.md 10: the
// answer must not depend on how points are grouped into a call).
#include <catch2/catch.hpp>

#include <cstring>
#include <random>

#include "mortar/batch.hpp"
#include "mortar/integrator.hpp"
#include "mortar/state_layout.hpp"
#include "random_parameters.hpp"

#if MORTAR_ELASTIC_LANES
namespace {

using mortar::State;
using mortar::Vec3;
using mj_test::log_uniform;
using mj_test::uniform;

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// A valid unworn state (w_III = 0) anywhere in its range: open or closed, on
// either side of the regime boundary, damaged or not, softened or not; its
// elastic separation a random fraction of what reaches ft0, so that the
// tractions fall inside, near and beyond the surface.
State random_state(std::mt19937& rng, const mortar::Model& M) {
  const double scale = M.p.ft0 / M.p.kn;
  State s;
  s.open = uniform(rng, 0, 1) < 0.5;
  s.dn = uniform(rng, 0, 1) < 0.3 ? 0.0 : uniform(rng, 0, 1);
  s.ds = uniform(rng, 0, 1) < 0.3 ? 0.0 : uniform(rng, 0, 1);
  s.wI = uniform(rng, 0, 1) < 0.3 ? 0.0 : uniform(rng, 0, 1.2) * M.p.GIC;
  s.wII = uniform(rng, 0, 1) < 0.5 ? 0.0 : uniform(rng, 0, 0.5) * M.p.GIIC;
  for (int i = 0; i < 3; ++i) {
    s.plastic[i] = uniform(rng, -3, 3) * scale;
    s.separation[i] = s.plastic[i] + uniform(rng, -1.5, 1.5) * scale * (i == 0 ? 1.0 : M.p.kn / M.p.ks);
  }
  return s;
}

Vec3 random_increment(std::mt19937& rng, const mortar::Model& M) {
  const double size = log_uniform(rng, 1e-9, 1.0) * M.p.ft0 / M.p.kn;
  return Vec3(uniform(rng, -1, 1) * size, uniform(rng, -1, 1) * size, uniform(rng, -1, 1) * size);
}

void put_lane(mortar::lanes::ElasticLanes& y, int l, const State& s, const Vec3& d) {
  for (int i = 0; i < 3; ++i) {
    y.plastic[i][l] = s.plastic[i];
    y.separation[i][l] = s.separation[i];
    y.d[i][l] = d[i];
  }
  y.wI[l] = s.wI;
  y.wII[l] = s.wII;
  y.dn[l] = s.dn;
  y.ds[l] = s.ds;
  y.h[l] = s.open ? 1.0 : 0.0;
  y.candidate[l] = -1;
}

}  // namespace

TEST_CASE("elastic lanes: each lane decides and books as elastic_increment, bit for bit", "[elastic][lanes]") {
  using mortar::lanes::kWidth;
  std::mt19937 rng(20261203);
  int booked = 0, declined = 0, differences = 0;
  for (int set = 0; set < 200; ++set) {
    const mortar::Model M = mortar::make_model_checked(mj_test::random_parameters(rng));
    for (int trial = 0; trial < 200; ++trial) {
      mortar::lanes::ElasticLanes y;
      State start[kWidth];
      Vec3 d[kWidth];
      for (int l = 0; l < kWidth; ++l) {
        start[l] = random_state(rng, M);
        d[l] = random_increment(rng, M);
        put_lane(y, l, start[l], d[l]);
      }
      const mortar::lanes::ElasticLaneResult r = mortar::lanes::elastic_increment_lanes(M, y);
      for (int l = 0; l < kWidth; ++l) {
        State s = start[l];
        mortar::IncrementResult res;
        const bool elastic = mortar::elastic_increment(M, s, d[l], res);
        (elastic ? booked : declined) += 1;
        differences += elastic != (r.elastic[l] != 0);
        if (!elastic || !r.elastic[l]) continue;
        for (int i = 0; i < 3; ++i) {
          differences += !same_bits(s.separation[i], r.separation[i][l]);
          differences += !same_bits(res.traction[i], r.traction[i][l]);
        }
        differences += !same_bits(res.elastic_energy, r.energy[l]);
      }
    }
  }
  INFO(booked << " booked, " << declined << " declined");
  CHECK(differences == 0);
  // Both outcomes are exercised in earnest.
  CHECK(booked > 10000);
  CHECK(declined > 10000);
}

TEST_CASE("elastic lanes: a lane the caller did not find valid is never booked", "[elastic][lanes]") {
  using mortar::lanes::kWidth;
  std::mt19937 rng(7);
  const mortar::Model M = mortar::make_model_checked(mj_test::random_parameters(rng));
  mortar::lanes::ElasticLanes y;
  const Vec3 pressed(-1e-9, 1e-9, 0);  // elastic from the reference state
  State s;
  mortar::IncrementResult res;
  REQUIRE(mortar::elastic_increment(M, s, pressed, res));
  for (int l = 0; l < kWidth; ++l) put_lane(y, l, State{}, pressed);
  y.candidate[1] = 0;
  const mortar::lanes::ElasticLaneResult r = mortar::lanes::elastic_increment_lanes(M, y);
  CHECK(r.elastic[0] != 0);
  CHECK(r.elastic[1] == 0);
}
#endif
