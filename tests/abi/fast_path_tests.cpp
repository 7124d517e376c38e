// The fast paths as a switch: vuinteraction_ built with the elastic shortcut
// and the lanes (and the path counters, adapter/path_counters.hpp) gives, on
// the random-path corpus, the outputs of the build without them, bit for bit
// (their hashes: MJ_CORPUS_REFERENCE, written by path_corpus_reference); and
// an elastic block actually goes through the lanes (a deck with a compression
// cap never does).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstring>
#include <initializer_list>
#include <limits>
#include <vector>

#include "adapter/path_counters.hpp"
#include "mortar/failure.hpp"
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

TEST_CASE("fast paths: a deck with a compression cap takes no lanes, with fc = 0 it takes them as before",
          "[fast_paths][cap]") {
  const double fc = GENERATE(0.0, 30.0);
  CAPTURE(fc);
  Block b(17, 3, kSingle ? mortar::kCappedStateCountSingle : mortar::kCappedStateCountDouble);
  // props(15..20) at their defaults, then a cap that keeps its rules on M15.
  b.props.resize(mortar::kCapFirstProp, Real(0));
  for (double v : {fc, 1.0, 5.0, 0.01}) b.props.push_back(Real(v));
  b.call(0, 0);
  for (int i = 0; i < 3; ++i) {
    const mj_adapter::PathCounts c = b.call(-1e-5, 2e-5);
    CHECK(c.lanes == (fc > 0 ? 0 : 16));
    CHECK(c.total() == 17);
    CHECK(b.state[mortar::slot::status] == Real(0));
  }
}

TEST_CASE("fast paths: plain floats take the per-point shortcut, not the lanes", "[fast_paths]") {
  if (!kSingle) return;
  Block b(8, 2, mortar::kStateCount);
  b.call(0, 0);
  const mj_adapter::PathCounts c = b.call(-1e-5, 2e-5);
  CHECK(c.lanes == 0);
  CHECK(c.shortcut == 8);
}

TEST_CASE("fast paths: a corrupted SDV 35 is rejected on every path, the other points integrated",
          "[fast_paths][flags]") {
  // SDV 35 holds integration flags, a whole number from 0 to 15 (docs/model.md
  // 3): each value below is rejected (SDV 21 = invalid_state, the state kept)
  // on a point of a lane pair, on the tail point (the per-point shortcut) and,
  // after a plastic call, on the full path.
  namespace slot = mortar::slot;
  const int n_dir = GENERATE(2, 3);
  const Real bad = GENERATE(Real(2.5), Real(16), Real(-1), std::numeric_limits<Real>::quiet_NaN(), Real(1e9));
  CAPTURE(n_dir, bad);
  Block b(17, n_dir, mortar::kFlaggedStateCount);
  b.call(0, 0);
  b.call(-1e-5, 2e-5);
  const int code = int(mortar::Failure::invalid_state), flags = mortar::flag_slot::integration_flags;
  auto corrupt_and_call = [&](std::initializer_list<int> points, double dn, double ds) {
    std::vector<Real> start = b.state;
    for (int k : points) b.state[size_t(b.n_states) * k + flags] = start[size_t(b.n_states) * k + flags] = bad;
    const mj_adapter::PathCounts c = b.call(dn, ds);
    for (int k = 0; k < b.n; ++k) {
      const Real* st = b.state.data() + size_t(b.n_states) * k;
      const bool corrupted = std::find(points.begin(), points.end(), k) != points.end();
      CAPTURE(k);
      CHECK(st[slot::status] == Real(corrupted ? code : 0));
      if (corrupted) {  // the start state kept, but for the status
        const Real* s0 = start.data() + size_t(b.n_states) * k;
        int changed = 0;
        for (int i = 0; i < b.n_states; ++i) changed += i != slot::status && std::memcmp(st + i, s0 + i, sizeof(Real));
        CHECK(changed == 0);
      }
    }
    for (int k : points) b.state[size_t(b.n_states) * k + flags] = Real(0);
    return c;
  };
  // Point 0 in a pair of lanes and the tail point 16: the lanes take the
  // other fifteen, the rejected two count as the full path's.
  const mj_adapter::PathCounts elastic = corrupt_and_call({0, 16}, -1e-5, 2e-5);
  CHECK(elastic.lanes == 15);
  CHECK(elastic.full == 2);
  corrupt_and_call({}, 1e-3, 0.05);  // plastic: SDV 19 > 0 from here on
  const mj_adapter::PathCounts full = corrupt_and_call({5}, 1e-5, 1e-4);
  CHECK(full.full == 17);
}
