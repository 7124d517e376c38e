// The fuzz target's parts (fuzz_vuinteraction.cpp): the block of points and
// its call, the decoding of an input, the independent oracles and the checks
// after a call, with the reporting they share.
#pragma once

#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "fuzz_input.hpp"
#include "mortar/state_layout.hpp"
#include "vuinteraction.h"

namespace mj_fuzz {

using Real = mj_real;
namespace slot = mortar::slot;
constexpr int kSlots = mortar::kStateCount;  // 23
constexpr const char* kName = "FUZZ-JOINT";
// The largest substep budget per increment (props(18)) an input gets. The
// libFuzzer build's default budget, for nProps < 18, is the same
// (FUZZING_BUILD_MODE_UNSAFE_FOR_PRODUCTION, src/mortar/parameters.hpp); the
// plain build's replay of the seeds keeps the law's 10^5 there.
constexpr double kFuzzMaxSubsteps = 1e3;

inline size_t count(long n) { return n > 0 ? size_t(n) : 0; }
inline bool finite(double x) { return std::isfinite(x); }
inline bool same_bits(Real a, Real b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// Statistics, printed at exit.
struct Stats {
  long inputs = 0, calls = 0, invalid_calls = 0, unpaired = 0, points = 0, corrupt_reported = 0;
  long status[16] = {};  // by SDV 21 after the call
};
extern Stats stats;
// Where reports go while the routine's stderr is captured.
extern FILE* real_stderr;

// Prints what was violated and aborts, so libFuzzer keeps the input as a crash.
[[noreturn]] void fail(const char* format, ...);

// The block and its arguments, sized as declared (fuzz_block.cpp).
struct Block {
  int n_dir = 3, n_states = kSlots, n_node_states = 1, n_block = 1, n_props = 14, n_nod_slv = 1;
  std::vector<Real> stress, flux_slv, flux_mst, state, sed, sfd, scd, spd, svd, props, penetration, dr_disp;
  std::vector<int> slave_nodes, master_nodes;
  // The rotation increment (read in 3D: here the unit matrix) and the
  // arguments the adapter does not read, sized as declared all the same.
  std::vector<Real> d_rot, dircos, per_point, dircos_sl, shape_slv, shape_mst, coord_slv, coord_mst, field;

  void allocate();
  Real* state_of(int k) { return state.data() + long(k) * n_states * n_node_states; }
  // Calls vuinteraction_ with stderr redirected into `capture`; returns what
  // was written there.
  std::string call(FILE* capture);
};

// The props of an input (fuzz_block.cpp).
void decode_props(Reader& r, Block& b);

// The independent oracles (fuzz_oracles.cpp).
bool props_valid(const std::vector<Real>& props, int n_props);
// Whether valid props switch the compression cap on (props(21) = fc > 0), and
// the state count such a call needs in this precision (36 double, 37 single).
bool props_capped(const std::vector<Real>& props, int n_props);
constexpr int kCappedSlots = sizeof(Real) == 4 ? mortar::kCappedStateCountSingle : mortar::kCappedStateCountDouble;
int owned_slots(int n_states);
double value(const Real* s, int i, bool paired);
// kappa_c (SDV 36, with SDV 37 its low part where `paired`) as the routine
// reads it, where `capped`.
double kappa_c_value(const Real* s, bool paired);
const char* state_violation(const Real* s, bool paired, bool flagged, bool capped = false);

// The checks after one call (fuzz_checks.cpp).
void check_call(const Block& b, const Block& before, const std::string& text, int call);

}  // namespace mj_fuzz
