// Writes the seed corpus of the vuinteraction_ fuzz target (tests/fuzz/corpus):
// one file per interesting case, in the format of fuzz_input.hpp. The corpus
// is committed; rerun this after changing the format:
//   build/tests/fuzz/fuzz_make_seeds tests/fuzz/corpus
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "seed_format.hpp"

namespace {

using mj_fuzz::Case;
using mj_fuzz::Corruption;
using mj_fuzz::Seed;
using mj_fuzz::small;
using mj_fuzz::value;
using mj_fuzz::Writer;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

std::string out_dir;
int written = 0;

void save(const std::string& name, const Seed& s) {
  const std::vector<uint8_t> b = s.bytes();
  std::ofstream(out_dir + "/" + name, std::ios::binary).write(reinterpret_cast<const char*>(b.data()), b.size());
  ++written;
}

// A whole path for one point, from (penetration delta, slip1, slip2) per call.
struct Step {
  double dpen, s1, s2;
};
void path_seed(const std::string& name, const Case& c, const std::vector<Step>& steps,
               std::vector<std::vector<Corruption>> corruptions = {}) {
  Seed s(c);
  for (size_t i = 0; i < steps.size(); ++i) {
    const Step st = steps[i];
    s.call(i < corruptions.size() ? corruptions[i] : std::vector<Corruption>{}, [&](Writer& w, int k) {
      const double scale = 1.0 + 0.25 * k;
      small(w, st.dpen * scale);
      w.u8(mj_fuzz::kZero);  // drDisp(1) is not read
      for (int i = 1; i < c.n_dir; ++i) small(w, (i == 1 ? st.s1 : st.s2) * scale);
    });
  }
  save(name, s);
}

std::vector<Step> opening(int n, double step) {
  std::vector<Step> v{{0, 0, 0}};
  for (int i = 1; i < n; ++i) v.push_back({-step, 0, 0});
  return v;
}
std::vector<Step> pressed_shear(int n, double press, double slip) {
  std::vector<Step> v{{0, 0, 0}, {press, 0, 0}};
  for (int i = 2; i < n; ++i) v.push_back({0, slip, 0.3 * slip});
  return v;
}
std::vector<Step> open_close(int n, double amp) {
  std::vector<Step> v{{0, 0, 0}};
  for (int i = 1; i < n; ++i) v.push_back({(i % 4 < 2 ? -amp : amp) * (i % 2 ? 1.0 : 0.5), 0.2 * amp, 0});
  return v;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: fuzz_make_seeds <corpus-directory>\n");
    return 2;
  }
  out_dir = argv[1];

  // --- Valid paths: the law's regimes through the ABI.
  {
    Case c;
    path_seed("valid-m15-3d-opening-to-separation", c, opening(8, 0.004));
    c.paper = 1;
    path_seed("valid-m34-3d-pressed-shear", c, pressed_shear(8, 0.0007, 0.004));
    c.paper = 2;
    c.n_dir = 2;
    c.n_block = 4;
    path_seed("valid-vdp-2d-open-close-4-points", c, open_close(8, 0.003));
    c.paper = 3;
    c.n_dir = 3;
    c.n_block = 8;
    path_seed("valid-atkinson-8-points-open-close-shear", c, open_close(8, 0.001));
  }
  {
    Case c;  // a random valid set from 2-byte payloads, snap-back likely (large ft0, small GIC)
    c.props_mode = 1;
    // kn ks ft0 c0 GIC GIIC phi0 phir m psi0 psir n bn bs (fractions of 65535)
    c.payload = {30000, 30000, 60000, 20000, 1000, 30000, 30000, 40000, 100, 30000, 100, 100, 30000, 30000};
    c.n_block = 3;
    path_seed("valid-random-set-snapback", c, open_close(8, 0.01));
    c.payload = {10000, 50000, 10000, 65000, 50000, 60000, 65535, 65535, 1, 65000, 65535, 1, 0, 65535};
    path_seed("valid-random-set-steep-angles", c, pressed_shear(8, 0.01, 0.01));
  }
  {
    Case c;  // scaled paper set
    c.props_mode = 3;
    c.payload = {16, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
    path_seed("valid-scaled-stiff-joint", c, pressed_shear(6, 0.0001, 0.001));
  }
  {
    Case c;  // controls: forward Euler, STOL 1e-3, shear sign +1
    c.n_props = 20;
    c.control_bytes = {2, 4, 0, 0, 0, 1};
    path_seed("valid-controls-forward-euler-sign-plus", c, pressed_shear(8, 0.0007, 0.004));
    c.control_bytes = {1, 1, 1, 0, 2, 2};  // STOL 1e-12, FTOL 1e-12, min substep 1e-12
    path_seed("valid-controls-tight-tolerances", c, opening(3, 0.003));
    c.control_bytes = {1, 3, 3, 1, 5, 0};  // one substep at most, min substep 1
    path_seed("valid-controls-one-substep", c, pressed_shear(6, 0.0007, 0.004));
    c.control_bytes = {1, 3, 3, 4, 0, 0};  // max substeps 1e9 (the largest allowed)
    path_seed("valid-controls-max-substeps-1e9", c, pressed_shear(6, 0.0007, 0.004));
    c.n_props = 30;  // entries beyond props(20) are ignored
    c.control_bytes = {0, 0, 0, 0, 0, 0, 3, 3, 2, 0x80};
    path_seed("valid-30-props-extra-entries-ignored", c, opening(4, 0.002));
  }
  {
    Case c;  // wider arrays: 30 state variables, 2 node states: only state(1:23,1,k) may change
    c.n_states = 30;
    c.n_node_states = 2;
    c.n_block = 3;
    path_seed("valid-30-states-2-node-states", c, open_close(6, 0.003));
    c.n_nod_slv = 0;
    path_seed("valid-no-slave-node-numbers", c, opening(3, 0.003));
  }
  {
    Case c;  // 34 state variables: the single-precision routine keeps float pairs, their low parts in SDV 24-34
    c.n_states = 34;
    c.n_block = 2;
    path_seed("valid-34-states-float-pairs", c, pressed_shear(8, -0.001, 0.004));
    // SDV 32, the low part of delta_n, far beyond its high part's float
    // spacing: a broken rule in single precision, a slot the double-precision
    // routine does not read.
    std::vector<std::vector<Corruption>> corr(8);
    corr[5] = {{0, 31, 0.5}};
    path_seed("corrupt-pair-low-part", c, pressed_shear(8, -0.001, 0.004), corr);
  }

  // --- The compression cap (docs/model.md 12): props(21..24) as raw doubles
  // (props mode 2) on Almeida M15, DEPVAR 37 (the single-precision float
  // pair; the double routine keeps SDV 36). Cs = 1, fc = 4 sqrt(ft0^2 + Cs
  // c0^2) = 12.8 MPa (its cap fc/3 at 0.0058 mm of closure), Gfc twice its
  // snap-back bound, kappa_p = fc/kn: pressed onto the cap, crushed while
  // sliding, opened and reclosed.
  {
    const double m15[14] = {741.1, 308.8, 1.78, 2.67, 0.01209, 0.121, 40, 32, 511.9, 8, 0, 856.1, 10, 3};
    const double fc = 4 * std::sqrt(1.78 * 1.78 + 2.67 * 2.67), Gfc = 2 * 481 * fc * fc / (588 * 308.8);
    auto capped = [&](double fc_, double Cs, double Gfc_, double kappa_p, int states, int block) {
      Case c;
      c.props_mode = 2;
      c.n_props = 24;
      c.n_states = states;
      c.n_block = block;
      c.raw_props.assign(m15, m15 + 14);
      c.raw_props.resize(20, 0.0);
      for (double v : {fc_, Cs, Gfc_, kappa_p}) c.raw_props.push_back(v);
      return c;
    };
    const std::vector<Step> crush = {{0, 0, 0},       {0.008, 0, 0},   {0.008, 0.002, 0}, {0.006, 0.004, 0.002},
                                     {0, 0.004, 0},   {-0.01, 0, 0},   {0.01, -0.004, 0}, {0.01, 0.002, 0}};
    path_seed("valid-cap-37-states-crush", capped(fc, 1, Gfc, fc / 741.1, 37, 1), crush);
    path_seed("valid-cap-37-states-4-points-crush", capped(fc, 1, Gfc, 0, 37, 4), crush);
    path_seed("valid-cap-36-states-crush", capped(fc, 1, Gfc, fc / 741.1, 36, 2), crush);  // single: too few
    path_seed("valid-cap-fc-0-no-cap", capped(0, 0, 0, 0, 37, 1), crush);
    path_seed("invalid-cap-fc-below-rule", capped(0.5 * fc, 1, Gfc, 0, 37, 1), crush);      // fc/3 too small
    path_seed("invalid-cap-gfc-snap-back", capped(fc, 1, 0.1 * Gfc, 0, 37, 1), crush);
  }

  // --- Invalid arguments: reported, outputs finite.
  for (int d : {1, 4, 0, -1, -4, 11}) {
    Case c;
    c.n_dir = d;
    c.start_values = true;
    c.start_stress = kNaN;
    c.start_sed = kInf;
    path_seed("invalid-nDir-" + std::to_string(d), c, opening(2, 0.001));
  }
  for (int n : {22, 21, 20, 10, 0, -2}) {
    Case c;
    c.n_states = n;
    path_seed("invalid-nStates-" + std::to_string(n), c, opening(2, 0.001));
  }
  for (int n : {13, 0, -1}) {
    Case c;
    c.n_props = n;
    path_seed("invalid-nProps-" + std::to_string(n), c, opening(2, 0.001));
  }
  for (int n : {0, -1}) {
    Case c;
    c.n_node_states = n;
    path_seed("invalid-nNodState-" + std::to_string(n), c, opening(2, 0.001));
  }
  for (int n : {0, -1}) {
    Case c;
    c.n_block = n;
    path_seed("edge-nBlock-" + std::to_string(n), c, opening(2, 0.001));
  }

  // --- Invalid properties and controls.
  struct Bad {
    const char* name;
    int index;
    double value;
  };
  const Bad bad[] = {
      {"kn-nan", 0, kNaN},           {"kn-zero", 0, 0},           {"ks-negative", 1, -1},
      {"ft0-inf", 2, kInf},          {"c0-below-hyperbola", 3, 0.5}, {"GIC-zero", 4, 0},
      {"phi0-90", 6, 90},            {"phir-above-phi0", 7, 45},  {"phir-zero", 7, 0},
      {"m-negative", 8, -1},         {"psir-above-psi0", 10, 9},  {"bn-negative", 12, -1e-300},
      {"scheme-3", 14, 3},           {"stol-2", 15, 2},           {"ftol-negative", 16, -1e-8},
      {"max-substeps-fraction", 17, 1.5}, {"max-substeps-2e9", 17, 2e9},
      {"max-substeps-minus-1e300", 17, -1e300}, {"min-substep-1.5", 18, 1.5},
      {"shear-sign-half", 19, 0.5},  {"control-nan", 16, kNaN},
  };
  for (const Bad& b : bad) {
    Case c;
    c.n_props = 20;
    c.overrides = {{b.index, b.value}};
    c.start_values = true;
    c.start_stress = 0.25;
    c.start_sed = kNaN;
    path_seed(std::string("invalid-prop-") + b.name, c, opening(2, 0.001));
  }
  {
    Case c;  // raw props: whatever bits
    c.props_mode = 2;
    c.n_props = 16;
    c.raw_props = {741.1, 308.8, 1.78, 2.67, 0.01209, 0.121, 40, 32, 511.9, 8, 0, 856.1, 10, 3, 1, 1e-6};
    path_seed("valid-raw-props", c, pressed_shear(4, 0.0005, 0.002));
    c.raw_props[5] = -0.0;
    path_seed("invalid-raw-props-negative-zero", c, opening(2, 0.001));
    c.raw_props = {1e308, 1e308, 1e-308, 1e308, 1e-308, 1e308, 89.999999, 1e-300, 1e308, 89.99, 0, 1e308, 1e308, 0};
    path_seed("valid-raw-props-extreme", c, pressed_shear(4, 0.0005, 0.002));
  }

  // --- Increments: tiny, huge, non-finite, unpaired.
  {
    Case c;
    c.n_block = 2;
    auto special = [&](const std::string& name, double pen_later, double slip_later) {
      Seed s(c);
      s.call({}, [&](Writer& w, int) {
        w.u8(mj_fuzz::kZero);
        for (int i = 0; i < 3; ++i) w.u8(mj_fuzz::kZero);
      });
      for (int n = 0; n < 3; ++n)
        s.call({}, [&](Writer& w, int k) {
          value(w, k == 0 ? pen_later : 1e-4);
          w.u8(mj_fuzz::kZero);
          value(w, k == 0 ? slip_later : 1e-4);
          value(w, 0.0);
        });
      save(name, s);
    };
    special("increment-tiny-1e-300", 1e-300, 1e-300);
    special("increment-denormal", 4.9e-324, -4.9e-324);
    special("increment-huge-opening-1e300", -1e300, 0);
    special("increment-huge-pressure-1e155", 1e155, 0);
    special("increment-huge-pressure-1e100", 1e100, 1e100);
    special("increment-huge-shear-1e200", 1e-4, 1e200);
    special("increment-large-opening-1e3", -1e3, 1e3);
    special("increment-nan-penetration", kNaN, 0);
    special("increment-inf-penetration", kInf, 0);
    special("increment-minus-inf-penetration", -kInf, 0);
    special("increment-nan-slip", 1e-4, kNaN);
    special("increment-inf-slip", 1e-4, -kInf);
    special("increment-unpaired", -1e36, 0);
  }
  {
    Case c;  // NaN penetration at the very first call, then a good one
    Seed s(c);
    s.call({}, [](Writer& w, int) {
      w.u8(mj_fuzz::kNaN);
      for (int i = 0; i < 3; ++i) w.u8(mj_fuzz::kZero);
    });
    s.call({}, [](Writer& w, int) {
      small(w, 0.001);
      for (int i = 0; i < 3; ++i) w.u8(mj_fuzz::kZero);
    });
    save("increment-nan-first-call", s);
  }

  // --- Corrupted state (restart garbage) on a point with history.
  struct Garbage {
    const char* name;
    int slot;  // 0-based
    double value;
  };
  const Garbage garbage[] = {
      {"damage-n-1.5", 9, 1.5},          {"damage-s-negative", 10, -0.1},   {"wI-negative", 6, -1},
      {"wII-negative", 7, -1},           {"wIII-negative", 8, -1e-3},       {"plastic-nan", 0, kNaN},
      {"crack-inf", 4, kInf},            {"separation-nan", 12, kNaN},      {"separation-huge", 11, 1e300},
      {"dissipation-plastic-nan", 15, kNaN}, {"dissipation-damage-negative", 16, -1},
      {"unilateral-inf", 17, -kInf},     {"substeps-nan", 18, kNaN},        {"substeps-1e300", 19, 1e300},
      {"status-nan", 20, kNaN},          {"status-minus-1e20", 20, -1e20},  {"open-nan", 14, kNaN},
      {"open-half", 14, 0.5},            {"open-2", 14, 2},                 {"reference-nan", 21, kNaN},
      {"reference-inf", 21, kInf},       {"initialised-nan", 22, kNaN},     {"initialised-half", 22, 0.5},
      {"initialised-0-on-used-state", 22, 0},
  };
  for (const Garbage& g : garbage) {
    Case c;
    c.n_block = 2;
    std::vector<std::vector<Corruption>> corr(8);
    corr[5] = {{0, g.slot, g.value}};
    path_seed(std::string("corrupt-") + g.name, c, pressed_shear(8, -0.001, 0.004), corr);
  }
  // SDV 35 (DEPVAR 35) that no set of integration flags can be: rejected on
  // every path, as the other slots' garbage is.
  const Garbage flag_garbage[] = {
      {"flags-2.5", 34, 2.5}, {"flags-16", 34, 16}, {"flags-minus-1", 34, -1}, {"flags-nan", 34, kNaN}};
  for (const Garbage& g : flag_garbage) {
    Case c;
    c.n_block = 2;
    c.n_states = 35;
    std::vector<std::vector<Corruption>> corr(8);
    corr[5] = {{0, g.slot, g.value}};
    path_seed(std::string("corrupt-") + g.name, c, pressed_shear(8, -0.001, 0.004), corr);
  }
  {
    Case c;  // a whole restart of garbage on a fresh point
    std::vector<std::vector<Corruption>> corr(3);
    for (int i = 0; i < 23; ++i) corr[0].push_back({0, i, i % 3 == 0 ? kNaN : -1e10 * (i + 1)});
    corr[0].resize(3);
    path_seed("corrupt-fresh-point-garbage", c, opening(3, 0.001), corr);
  }

  std::printf("fuzz_make_seeds: wrote %d seeds to %s\n", written, out_dir.c_str());
  return 0;
}
