// Restart and corruption, through vuinteraction_ (double; docs/robustness.md).
//   - a state array saved mid-path and restored (binary, or as text with 17
//     significant digits; into a block of another size and order, as after a
//     restart) continues exactly as the uninterrupted run;
//   - a state array with impossible values (damage outside [0, 1], negative
//     work, non-finite values, flags that are neither 0 nor 1) is reported
//     (SDV 21, a message naming the point) and not propagated (the point
//     keeps its start state, its outputs are finite, the other points of the
//     block are untouched, and the next call reports it again);
//   - garbage in the slots the routine only writes (SDV 19-21: substep
//     counts and status of the last increment) is harmless;
//   - finite but absurd inputs (1e-300 to 1e300) give finite outputs or a
//     reported failure.
#include <catch2/catch.hpp>

#include <cstdio>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "abi_block.hpp"
#include "paper_sets.hpp"
#include "formatted.hpp"

using namespace mj_property;

// Double precision only: the corruption cases write values beyond a float's
// range, and the restart file keeps 17 digits (property_tests).
static_assert(!kSingle, "the restart and corruption tests drive the double-precision routine");

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

bool same_bits(const double* a, const double* b, size_t n) { return std::memcmp(a, b, n * sizeof(double)) == 0; }

// The restart file: what Abaqus keeps of a point between analyses (state,
// stress, sed), written as binary or as text.
std::vector<double> save_and_load(const std::vector<double>& values, bool text) {
  std::FILE* f = std::tmpfile();
  REQUIRE(f);
  if (text) {
    for (double v : values) std::fprintf(f, "%.17g\n", v);
  } else {
    REQUIRE(std::fwrite(values.data(), sizeof(double), values.size(), f) == values.size());
  }
  std::rewind(f);
  std::vector<double> back(values.size());
  for (double& v : back) {
    if (text) {
      REQUIRE(std::fscanf(f, "%lf", &v) == 1);
    } else {
      REQUIRE(std::fread(&v, sizeof(double), 1, f) == 1);
    }
  }
  std::fclose(f);
  return back;
}

// A point with history: M15, pressed and sheared past the peak, or opened
// past the peak (so every slot holds something).
struct History {
  Block block;
  std::vector<Step> next;  // the increments that follow
};
History with_history(int points, bool shear) {
  const mortar::Parameters p = mortar::testing::almeida_m15();
  History h{Block(points, 3, props_of(p)), {}};
  h.block.call();
  for (int i = 0; i < 30; ++i) {
    for (int k = 0; k < points; ++k)
      apply(h.block, k, shear ? Step{i < 3 ? 3e-4 : 0.0, 6e-4, 1e-4} : Step{-3e-4, 1e-5, 0});
    h.block.call();
  }
  for (int i = 0; i < 3; ++i) h.next.push_back(shear ? Step{-1e-4, 6e-4, 1e-4} : Step{-3e-4, 2e-5, 0});
  return h;
}

}  // namespace

TEST_CASE("Restart: a state array saved and restored mid-path continues exactly (400 random paths)", "[restart]") {
  std::mt19937 rng(20261206);
  long paths = 0, differences = 0;
  const int sets = scaled(25);
  for (int set = 0; set < sets; ++set) {
    const mortar::Parameters p = random_parameters(rng);
    const int n = 16, increments = 60, restart_at = 1 + int(rng() % (increments - 1));
    const bool text = set % 2 == 1;
    CAPTURE(set, restart_at, text);
    std::vector<int> family(n);
    for (int& f : family) f = int(rng() % 5);
    std::vector<std::vector<Step>> steps(increments, std::vector<Step>(n));
    for (auto& row : steps)
      for (int k = 0; k < n; ++k) row[k] = random_step(rng, p, family[k], set % 3 == 0);

    Block whole(n, 3, props_of(p));  // uninterrupted
    Block first(n, 3, props_of(p));  // up to the restart
    whole.call();
    first.call();
    for (int i = 0; i < restart_at; ++i) {
      for (int k = 0; k < n; ++k) {
        apply(whole, k, steps[i][k]);
        apply(first, k, steps[i][k]);
      }
      whole.call();
      first.call();
    }
    // Save, end the first analysis, restore into a new block in reverse order.
    const std::vector<double> state = save_and_load(first.state, text), stress = save_and_load(first.stress, text),
                              sed = save_and_load(first.sed, text);
    const std::vector<double> penetration = first.penetration;
    first = Block(0, 3, props_of(p));
    Block restarted(n, 3, props_of(p));
    auto at = [&](int k) { return n - 1 - k; };  // position of point k after the restart
    for (int k = 0; k < n; ++k) {
      std::copy_n(&state[size_t(k) * kStates], kStates, restarted.state_of(at(k)));
      std::copy_n(&stress[size_t(k) * 3], 3, restarted.stress_of(at(k)));
      restarted.sed[at(k)] = sed[k];
      restarted.penetration[at(k)] = penetration[k];
    }
    for (int i = restart_at; i < increments; ++i) {
      for (int k = 0; k < n; ++k) {
        apply(whole, k, steps[i][k]);
        apply(restarted, at(k), steps[i][k]);
      }
      whole.call();
      restarted.call();
      for (int k = 0; k < n; ++k) {
        const bool same = same_bits(whole.state_of(k), restarted.state_of(at(k)), kStates) &&
                          same_bits(whole.stress_of(k), restarted.stress_of(at(k)), 3) &&
                          same_bits(&whole.sed[k], &restarted.sed[at(k)], 1) &&
                          same_bits(&whole.spd[k], &restarted.spd[at(k)], 1);
        if (!same) ++differences;
      }
    }
    for (int k = 0; k < n; ++k) CHECK(whole.state_of(k)[slot::status] == 0);
    paths += n;
  }
  INFO(mj_test::formatted("restart: %ld paths saved and restored mid-path, %ld differences", paths, differences));
  CHECK(paths == 16L * sets);
  CHECK(differences == 0);
}

TEST_CASE("Corruption: a state array with impossible values is reported, not propagated", "[corruption]") {
  struct Case {
    int slot;  // 0-based
    double value;
    int expected;  // SDV 21 the point must carry
  };
  constexpr int kInvalidState = int(mortar::Failure::invalid_state);
  constexpr int kNonFiniteIncrement = int(mortar::Failure::non_finite_increment);
  std::vector<Case> cases;
  for (int s = 0; s <= slot::energy_unilateral; ++s)  // SDV 1-18: finite
    for (double v : {kNaN, kInf, -kInf}) cases.push_back({s, v, kInvalidState});
  for (double v : {1.5, 1.0000001, -0.1, -1e-300}) {  // damage in [0, 1]
    cases.push_back({slot::damage_n, v, kInvalidState});
    cases.push_back({slot::damage_s, v, kInvalidState});
  }
  for (int s : {int(slot::work_I), int(slot::work_II), int(slot::work_III), int(slot::dissipation_damage)})
    for (double v : {-1.0, -1e-3}) cases.push_back({s, v, kInvalidState});  // works, damage dissipation >= 0
  for (double v : {0.5, 2.0, -1.0, kNaN}) {  // flags are 0 or 1
    cases.push_back({slot::open, v, kInvalidState});
    cases.push_back({slot::initialised, v, kInvalidState});
  }
  for (double v : {kNaN, kInf}) cases.push_back({slot::reference_penetration, v, kNonFiniteIncrement});

  int reported = 0;
  for (const bool shear : {true, false}) {
    for (const Case& c : cases) {
      CAPTURE(shear, c.slot + 1, c.value);
      History clean = with_history(3, shear), bad = with_history(3, shear);
      bad.block.state_of(1)[c.slot] = c.value;
      std::vector<double> corrupt_state(bad.block.state_of(1), bad.block.state_of(1) + kStates);
      for (int call = 0; call < 2; ++call) {  // reported again on the next call: never propagated
        for (int k = 0; k < 3; ++k) {
          apply(clean.block, k, clean.next[call]);
          apply(bad.block, k, bad.next[call]);
        }
        clean.block.call();
        std::string message;
        {
          StderrCapture err;
          bad.block.call();
          message = err.text();
        }
        INFO("stderr: " << message);
        const double* st = bad.block.state_of(1);
        CHECK(st[slot::status] == c.expected);
        CHECK(message.find("VUINTERACTION, interaction 'PROPERTY': point 2 of 3 (slave node 1002)") != std::string::npos);
        for (int i = 0; i < kStates; ++i) {
          if (i == slot::substeps_accepted || i == slot::substeps_rejected || i == slot::status) continue;
          CHECK(same_bits(&st[i], &corrupt_state[i], 1));  // start state kept, nothing propagated
        }
        CHECK(all_finite(bad.block.stress.data(), bad.block.stress.size()));
        CHECK(all_finite(bad.block.sed.data(), 3));
        CHECK(bad.block.spd[1] == 0);
        for (int k : {0, 2}) {  // the other points are untouched by their neighbour's garbage
          CHECK(same_bits(bad.block.state_of(k), clean.block.state_of(k), kStates));
          CHECK(same_bits(bad.block.stress_of(k), clean.block.stress_of(k), 3));
        }
        reported += st[slot::status] == c.expected;
      }
    }
  }
}

TEST_CASE("Corruption: garbage in the slots the routine only writes (SDV 19-21) is harmless", "[corruption]") {
  for (int s : {int(slot::substeps_accepted), int(slot::substeps_rejected), int(slot::status)}) {
    for (double v : {kNaN, kInf, 1e300, -1e300, 3e9, 0.5, -7.0}) {
      CAPTURE(s + 1, v);
      History clean = with_history(2, true), bad = with_history(2, true);
      bad.block.state_of(0)[s] = v;
      for (int k = 0; k < 2; ++k) {
        apply(clean.block, k, clean.next[0]);
        apply(bad.block, k, bad.next[0]);
      }
      clean.block.call();
      bad.block.call();
      CHECK(bad.block.state_of(0)[slot::status] == 0);
      CHECK(same_bits(bad.block.state.data(), clean.block.state.data(), bad.block.state.size()));
      CHECK(same_bits(bad.block.stress.data(), clean.block.stress.data(), bad.block.stress.size()));
      CHECK(same_bits(bad.block.sed.data(), clean.block.sed.data(), 2));
    }
  }
}

TEST_CASE("Corruption: negative SDV 16 (plastic dissipation) and SDV 18 (unilateral energy) are legal", "[corruption]") {
  // Both can be negative on a valid path: SDV 18 on every closing, SDV 16
  // where the dilatancy exceeds the friction angle (psi > phi, which the
  // parameter rules allow). So they are not rejected.
  for (int s : {int(slot::dissipation_plastic), int(slot::energy_unilateral)}) {
    History h = with_history(1, true);
    h.block.state_of(0)[s] = -1.0;
    apply(h.block, 0, h.next[0]);
    h.block.call();
    CHECK(h.block.state_of(0)[slot::status] == 0);
  }
}

TEST_CASE("Bad input: finite but absurd increments give finite outputs or a reported failure", "[corruption]") {
  const std::vector<double> sizes = {1e-300, 4.9e-324, 1e-12, 1e3, 1e100, 1e155, 1e200, 1e300, 1.7e308};
  int accepted = 0, rejected = 0;
  for (const bool shear : {true, false}) {
    for (double size : sizes) {
      for (int component = 0; component < 3; ++component) {
        for (double sign : {1.0, -1.0}) {
          CAPTURE(shear, size, component, sign);
          History h = with_history(1, shear);
          const std::vector<double> before = h.block.state;
          Step s{0, 0, 0};
          if (component == 0) s.d_penetration = sign * size;
          if (component == 1) s.slip1 = sign * size;
          if (component == 2) s.slip2 = sign * size;
          apply(h.block, 0, s);
          std::string message;
          {
            StderrCapture err;
            h.block.call();
            message = err.text();
          }
          CHECK(all_finite(h.block.stress.data(), 3));
          CHECK(std::isfinite(h.block.sed[0]));
          CHECK(std::isfinite(h.block.spd[0]));
          const double status = h.block.state_of(0)[slot::status];
          if (status == 0) {
            ++accepted;
            CHECK(all_finite(h.block.state.data(), kStates));
            CHECK(message.empty());
          } else {
            ++rejected;
            CHECK(message.find("point 1 of 1") != std::string::npos);
            for (int i = 0; i < slot::substeps_accepted; ++i) CHECK(same_bits(&h.block.state[i], &before[i], 1));
          }
        }
      }
    }
  }
}
