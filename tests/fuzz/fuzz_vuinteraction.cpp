// Fuzz target of the VUINTERACTION entry point vuinteraction_ (docs/robustness.md).
//
// One input (format: fuzz_input.hpp) is a block of points with arbitrary
// dimensions (nDir, nStates, nNodState, nBlock, nProps, valid and not),
// arbitrary props (paper sets, random valid sets, scaled sets, raw doubles,
// controls), and a sequence of up to 8 calls with arbitrary penetrations and
// relative-displacement increments (tiny, huge, NaN, infinite, "unpaired")
// and state corruptions between calls (garbage a corrupted restart could
// hold). Arrays are sized as declared, as Abaqus sizes them.
//
// Pass condition, checked after every call (a violation prints what was
// wrong and aborts, so libFuzzer keeps the input as a crash):
//   - no crash and no sanitizer report (the build adds ASan + UBSan);
//   - every output (stress, sed, spd, sfd, scd, svd, fluxes) is finite,
//     whatever came in;
//   - invalid arguments or properties (judged here by an independent reading
//     of docs/model.md section 2 and docs/abaqus.md) are reported: a message
//     naming the routine and the interaction, the negative code in SDV 21 of
//     every point, no other state slot changed, stress and sed as they came
//     in (made finite), spd = 0;
//   - a point whose incoming state breaks the documented rules (non-finite
//     SDV 1-18, damage outside [0, 1], negative work w_I, w_II, w_III or
//     damage dissipation (which only grows from 0), open flag or
//     initialised flag not 0/1, non-finite reference) is reported and not
//     propagated: SDV 21 > 0, every other slot it holds unchanged, a message;
//   - a point the law rejects keeps its start state and is reported;
//   - a point that succeeds (SDV 21 = 0) has every state variable finite,
//     damage in [0, 1] and not decreased, w_I and w_III not decreased (w_II
//     may: docs/robustness.md), the flags 0/1,
//     the reference stored; no message at all when every point succeeds;
//   - nothing outside state(1:23, 1, k) is written (other node states,
//     slots beyond 23); state(1:34, 1, k) in single precision with
//     nStates >= 34, where SDV 24-34 hold the low parts of the float pairs
//     and each paired variable is the sum of its two parts (docs/model.md 3),
//     a low part larger than its high part's float spacing a broken rule.
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "fuzz_target.hpp"

namespace mj_fuzz {

Stats stats;
FILE* real_stderr = nullptr;

[[noreturn]] void fail(const char* format, ...) {
  std::va_list args;
  va_start(args, format);
  std::fputs("fuzz_vuinteraction: PROPERTY VIOLATED: ", real_stderr);
  std::vfprintf(real_stderr, format, args);
  std::fputs("\n", real_stderr);
  va_end(args);
  std::fflush(real_stderr);
  std::abort();
}

}  // namespace mj_fuzz

namespace {

using namespace mj_fuzz;

// Substeps (SDV 19 + 20) an input's points may spend before its remaining
// calls are skipped (fuzz_input.hpp, "calls").
constexpr double kInputSubstepBudget = 2e3;

// MJ_FUZZ_VERBOSE=1: print every call (arguments, props, per-point inputs and
// results), to turn a failing input into a reproducer.
bool verbose = false;

template <class Vec>
void print_values(const char* name, const Vec& v) {
  std::fprintf(real_stderr, "  %s =", name);
  for (const auto& x : v) std::fprintf(real_stderr, " %.17g", double(x));
  std::fputs("\n", real_stderr);
}

void print_stats() {
  std::fprintf(real_stderr,
               "fuzz_vuinteraction: %ld inputs, %ld calls (%ld invalid), %ld point-increments integrated "
               "(SDV 21: 0: %ld, 1: %ld, 2: %ld, 3: %ld, 4: %ld, 5: %ld, 6: %ld, 7+: %ld), %ld unpaired, "
               "%ld corrupt incoming states reported\n",
               stats.inputs, stats.calls, stats.invalid_calls, stats.points, stats.status[0], stats.status[1],
               stats.status[2], stats.status[3], stats.status[4], stats.status[5], stats.status[6],
               stats.status[7] + stats.status[8] + stats.status[9], stats.unpaired, stats.corrupt_reported);
}

FILE* capture_file() {
  static FILE* capture = [] {
    real_stderr = stderr;
    const char* v = std::getenv("MJ_FUZZ_VERBOSE");
    verbose = v && *v && *v != '0';
    std::atexit(print_stats);
    FILE* f = std::tmpfile();
    if (!f) {
      std::perror("tmpfile");
      std::abort();
    }
    return f;
  }();
  return capture;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  FILE* capture = capture_file();
  ++stats.inputs;
  Reader r(data, size);
  Block b;
  b.n_dir = mj_fuzz::decode_n_dir(r.u8());
  b.n_states = mj_fuzz::decode_n_states(r.u8());
  b.n_node_states = mj_fuzz::decode_n_node_states(r.u8());
  b.n_block = mj_fuzz::decode_n_block(r.u8());
  b.n_props = mj_fuzz::decode_n_props(r.u8());
  b.n_nod_slv = mj_fuzz::decode_n_node_slv(r.u8());
  b.allocate();
  decode_props(r, b);
  if (r.u8() & 1) {
    for (Real& x : b.stress) x = Real(mj_fuzz::read_value(r));
    for (Real& x : b.sed) x = Real(mj_fuzz::read_value(r));
  }
  const int n_calls = 1 + r.u8() % 8;
  const long per_point = long(count(b.n_states)) * long(count(b.n_node_states));
  double substeps = 0;  // spent by this input so far (see fuzz_input.hpp)
  for (int call = 0; call < n_calls && substeps < kInputSubstepBudget; ++call) {
    const int corruptions = r.u8() % 4;
    for (int c = 0; c < corruptions; ++c) {
      const int k = r.u8(), i = r.u8();
      const double v = mj_fuzz::read_value(r);
      if (b.n_block > 0 && per_point > 0) b.state[(k % b.n_block) * per_point + (i % per_point)] = Real(v);
    }
    for (int k = 0; k < b.n_block; ++k) {
      b.penetration[k] = Real(mj_fuzz::read_value(r, true, double(b.penetration[k])));
      for (int i = 0; i < b.n_dir; ++i) b.dr_disp[k * b.n_dir + i] = Real(mj_fuzz::read_value(r));
    }
    const Block before = b;
    if (verbose) {
      std::fprintf(real_stderr, "call %d: nDir %d nStates %d nNodState %d nBlock %d nProps %d nNodSlv %d\n", call + 1,
                   b.n_dir, b.n_states, b.n_node_states, b.n_block, b.n_props, b.n_nod_slv);
      print_values("props", b.props);
      print_values("penetration", b.penetration);
      print_values("drDisp", b.dr_disp);
      print_values("state in", b.state);
    }
    const std::string text = b.call(capture);
    ++stats.calls;
    if (verbose) {
      print_values("state out", b.state);
      print_values("stress out", b.stress);
      print_values("sed out", b.sed);
      print_values("spd out", b.spd);
      std::fprintf(real_stderr, "  stderr: %s\n", text.c_str());
    }
    check_call(b, before, text, call);
    if (per_point >= kSlots)
      for (int k = 0; k < b.n_block; ++k) {
        const Real* st = b.state_of(k);
        const double spent = double(st[slot::substeps_accepted]) + double(st[slot::substeps_rejected]);
        if (spent > 0 && spent < 1e7) substeps += spent;
      }
  }
  return 0;
}
