// Blocks: a run of many points in blocks of any size gives every point
// exactly the result it gets alone (invariant 8 of docs/model.md 10, through the ABI).
#include <catch2/catch.hpp>

#include "support.hpp"

using namespace mortar;
using namespace mortar::harness;
using namespace mortar::harness::testing;

namespace {
// Exact equality: the same arithmetic must run whatever the blocking.
bool same(const Sample& a, const Sample& b) {
  return a.increment == b.increment && a.separation == b.separation && a.traction == b.traction &&
         a.state == b.state && a.elastic_energy == b.elastic_energy && a.dissipation == b.dissipation &&
         a.external_work == b.external_work;
}

// Counts the samples that differ and remembers the first (one assertion per
// run rather than per sample keeps the test fast in Debug builds).
struct Mismatches {
  long count = 0, compared = 0;
  int first_point = -1;
  long first_increment = -1;
  void check(int point, const Sample& got, const Sample& expected) {
    ++compared;
    if (same(got, expected)) return;
    if (count++ == 0) {
      first_point = point;
      first_increment = got.increment;
    }
  }
};
}  // namespace

TEST_CASE("1000 identical points in blocks of 97 match the single-point run point by point", "[blocks]") {
  // Arrange
  const ParameterSet params = read_parameter_file(data_file("vdp_sn0.5.toml"));
  const Protocol protocol = read_protocol_file(data_file("block_shear.toml"));
  const std::vector<Sample> single = run_one_point(params.values, protocol, RunSettings{});
  RunSettings many;
  many.points = 1000;
  many.block = 97;  // ten full blocks and one of 30
  Mismatches m;
  // Act: compare as the samples arrive (1000 x 91 samples need not be kept)
  const RunStatistics stats = run_protocol(params.values, protocol, many, [&](int point, const Sample& s) {
    m.check(point, s, single.at(static_cast<size_t>(s.increment)));
  });
  // Assert
  CHECK(stats.blocks == 11);
  CHECK(m.compared == 1000L * static_cast<long>(single.size()));
  CAPTURE(m.first_point, m.first_increment);
  CHECK(m.count == 0);
}

TEST_CASE("28 points with 7 different histories keep their own results in blocks of 1, 5, 64", "[blocks]") {
  // Arrange: point k's targets are scaled by one of 7 factors, so neighbours
  // in a block follow different paths (some beyond the peak, some not).
  const ParameterSet params = read_parameter_file(data_file("vdp_sn0.5.toml"));
  const Protocol protocol = read_protocol_file(data_file("three_components.toml"));
  auto scale = [](int k) { return 0.4 + 0.2 * (k % 7); };
  std::vector<std::vector<Sample>> alone;
  for (int f = 0; f < 7; ++f) {
    RunSettings one;
    one.target_scale = [&](int) { return scale(f); };
    alone.push_back(run_one_point(params.values, protocol, one));
  }
  const int block = GENERATE(1, 5, 64);
  CAPTURE(block);
  RunSettings many;
  many.points = 28;
  many.block = block;
  many.target_scale = scale;
  Mismatches m;
  // Act
  run_protocol(params.values, protocol, many, [&](int k, const Sample& s) {
    m.check(k, s, alone[k % 7].at(static_cast<size_t>(s.increment)));
  });
  // Assert
  CHECK(m.compared == 28L * static_cast<long>(alone[0].size()));
  CAPTURE(m.first_point, m.first_increment);
  CHECK(m.count == 0);
}
