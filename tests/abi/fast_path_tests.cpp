// The fast paths as a switch: vuinteraction_ built with the elastic shortcut
// and the lanes (and the path counters, adapter/path_counters.hpp) gives, on
// the random-path corpus, the outputs of the build without them, bit for bit
// (their hashes: MJ_CORPUS_REFERENCE, written by path_corpus_reference); and
// an elastic block actually goes through the lanes.
#include <catch2/catch.hpp>

#include <cstring>
#include <vector>

#include "adapter/path_counters.hpp"
#include "mortar/parameters.hpp"
#include "mortar/state_layout.hpp"
#include "path_corpus.hpp"
#include "vuinteraction.h"

namespace {

using Real = mj_real;
constexpr bool kSingle = sizeof(Real) == sizeof(float);

// A block of n points, all at one penetration, calling vuinteraction_.
struct Block {
  int n, n_dir, n_states;
  std::vector<Real> stress, state, sed, spd, other, props, penetration, dr_disp, d_rot, wide;
  std::vector<int> nodes;
  Block(int points, int dir, int states)
      : n(points), n_dir(dir), n_states(states), stress(size_t(dir) * points), state(size_t(states) * points),
        sed(points), spd(points), other(points), penetration(points), dr_disp(size_t(dir) * points),
        d_rot(4 * size_t(points)), wide(16 * size_t(points)), nodes(4 * size_t(points)) {
    const double table1[14] = {741.1, 308.8, 1.78, 2.67, 0.01209, 0.121, 40, 32, 511.9, 8, 0, 856.1, 10, 3};
    for (double v : table1) props.push_back(Real(v));
    turn(0);
  }
  void turn(double angle) {
    for (int k = 0; k < n; ++k) {
      d_rot[4 * k] = d_rot[4 * k + 3] = Real(std::cos(angle));
      d_rot[4 * k + 1] = Real(std::sin(angle));
      d_rot[4 * k + 2] = Real(-std::sin(angle));
    }
  }
  // Every point opened by dn and slid by ds (mm) in this call.
  mj_adapter::PathCounts call(double dn, double ds) {
    for (int k = 0; k < n; ++k) {
      penetration[k] = Real(double(penetration[k]) - dn);
      dr_disp[size_t(n_dir) * k] = Real(dn);
      dr_disp[size_t(n_dir) * k + 1] = Real(ds);
    }
    const mj_adapter::PathCounts before = mj_adapter::path_counts();
    const int one = 1, four = 4, zero = 0, n_props = int(props.size()), flags[3] = {1, 1, 0};
    const Real r_data[4] = {0, 0, Real(1e-6), 0};
    char name[80];
    std::memset(name, ' ', sizeof name);
    vuinteraction_(stress.data(), other.data(), other.data(), state.data(), sed.data(), other.data(),
                   other.data(), spd.data(), other.data(), &n, &n, &n, &one, &one, &four, &n_dir, &n_states,
                   &n_props, &zero, &one, flags, r_data, name, name, name, nodes.data(), nodes.data(),
                   props.data(), penetration.data(), dr_disp.data(), d_rot.data(), wide.data(), wide.data(), wide.data(), wide.data(), wide.data(), wide.data(), wide.data(), wide.data(), wide.data(), wide.data(), wide.data(), wide.data(), wide.data(), wide.data(), wide.data(),
                   80, 80, 80);
    const mj_adapter::PathCounts after = mj_adapter::path_counts();
    return {after.lanes - before.lanes, after.shortcut - before.shortcut, after.full - before.full,
            after.unpaired - before.unpaired};
  }
};

}  // namespace

TEST_CASE("fast paths: the random-path corpus is bit for bit the build without them", "[fast_paths]") {
  const mj_adapter::PathCounts before = mj_adapter::path_counts();
  const std::vector<mj_corpus::CaseHash> hashes = mj_corpus::run_corpus();
  const std::vector<std::string> differ = mj_corpus::compare_hashes(hashes, MJ_CORPUS_REFERENCE);
  INFO("cases: " << hashes.size() << ", first that differs: " << (differ.empty() ? "none" : differ.front()));
  CHECK(differ.empty());
  // Every path takes a share of the corpus's point-updates.
  const mj_adapter::PathCounts c = mj_adapter::path_counts();
  const double total = double(c.total() - before.total());
  INFO("lanes " << (c.lanes - before.lanes) / total << ", shortcut " << (c.shortcut - before.shortcut) / total
                << ", full " << (c.full - before.full) / total << ", unpaired "
                << (c.unpaired - before.unpaired) / total);
  CHECK((c.lanes - before.lanes) / total > 0.1);
  CHECK((c.shortcut - before.shortcut) / total > 0.01);
  CHECK((c.full - before.full) / total > 0.1);
  CHECK(c.unpaired - before.unpaired > 0);
}

TEST_CASE("fast paths: an elastic block goes through the lanes", "[fast_paths]") {
  const int n_dir = GENERATE(2, 3);
  const int n_states = GENERATE(mortar::kStateCount, mortar::kPairedStateCount, mortar::kFlaggedStateCount);
  if (kSingle && n_states < mortar::kPairedStateCount) return;  // plain floats: no lanes (covered below)
  CAPTURE(n_dir, n_states);
  Block b(17, n_dir, n_states);
  // The first call sets each point's reference: one point at a time.
  const mj_adapter::PathCounts first = b.call(0, 0);
  CHECK(first.lanes == 0);
  CHECK(first.shortcut == 17);
  // Small closing increments from rest: elastic, sixteen points in pairs, one alone.
  for (int i = 0; i < 3; ++i) {
    const mj_adapter::PathCounts c = b.call(-1e-5, 2e-5);
    CHECK(c.lanes == 16);
    CHECK(c.shortcut == 1);
    CHECK(c.full == 0);
  }
  if (n_dir == 3) {  // a turning dRot: the per-point shortcut turns the state
    b.turn(0.01);
    const mj_adapter::PathCounts c = b.call(-1e-5, 2e-5);
    CHECK(c.lanes == 0);
    CHECK(c.shortcut == 17);
  }
  // Far over the surface: plastic, the full path; then (SDV 19 > 0) again.
  const mj_adapter::PathCounts plastic = b.call(1e-3, 0.05);
  CHECK(plastic.full == 17);
}

TEST_CASE("fast paths: plain floats take the per-point shortcut, not the lanes", "[fast_paths]") {
  if (!kSingle) return;
  Block b(8, 2, mortar::kStateCount);
  b.call(0, 0);
  const mj_adapter::PathCounts c = b.call(-1e-5, 2e-5);
  CHECK(c.lanes == 0);
  CHECK(c.shortcut == 8);
}
