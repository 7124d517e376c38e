// The fuzz target's block of points: its arrays sized as declared, its call
// of vuinteraction_, and the decoding of an input's props (fuzz_input.hpp).
#include <cmath>
#include <cstdint>

#include "fuzz_target.hpp"
#include "paper_sets.hpp"

namespace mj_fuzz {

void Block::allocate() {
  const size_t nb = count(n_block), nd = count(n_dir);
  stress.assign(nd * nb, Real(0));
  for (auto* v : {&flux_slv, &flux_mst, &sed, &sfd, &scd, &spd, &svd, &penetration, &per_point, &field})
    v->assign(nb, Real(0));
  state.assign(count(n_states) * count(n_node_states) * nb, Real(0));
  props.assign(count(n_props), Real(0));
  dr_disp.assign(nd * nb, Real(0));
  slave_nodes.resize(count(n_nod_slv) * nb);
  for (size_t i = 0; i < slave_nodes.size(); ++i) slave_nodes[i] = int(1000 + i);
  master_nodes.assign(4 * nb, 0);
  d_rot.assign(4 * nb, Real(0));  // the unit matrix: the tangent directions do not turn
  for (size_t k = 0; k < nb; ++k) d_rot[4 * k] = d_rot[4 * k + 3] = Real(1);
  dircos.assign(nd * nd * nb, Real(0));
  dircos_sl.assign(nd * nb, Real(0));
  shape_slv.assign(count(n_nod_slv) * nb, Real(0));
  shape_mst.assign(4 * nb, Real(0));
  coord_slv.assign(nd * count(n_nod_slv) * nb, Real(0));
  coord_mst.assign(nd * 4 * nb, Real(0));
}

std::string Block::call(FILE* capture) {
  const int n_nod_mst = 4, n_temp = 0, n_fields = 1;
  const int flags[3] = {1, 1, 0};
  const Real r_data[4] = {0, 0, Real(1e-6), 0};
  char name[80], blank[80];
  std::memset(name, ' ', sizeof name);
  std::memset(blank, ' ', sizeof blank);
  std::memcpy(name, kName, std::strlen(kName));
  std::rewind(capture);
  FILE* saved = stderr;
  stderr = capture;  // glibc: stderr is an assignable variable; sanitizers write to fd 2 directly
  vuinteraction_(stress.data(), flux_slv.data(), flux_mst.data(), state.data(), sed.data(), sfd.data(),
                 scd.data(), spd.data(), svd.data(), &n_block, &n_block, &n_block, &n_node_states, &n_nod_slv,
                 &n_nod_mst, &n_dir, &n_states, &n_props, &n_temp, &n_fields, flags, r_data, name, blank,
                 blank, slave_nodes.data(), master_nodes.data(), props.data(), penetration.data(),
                 dr_disp.data(), d_rot.data(), dircos.data(), per_point.data(), per_point.data(),
                 per_point.data(), dircos_sl.data(), shape_slv.data(), shape_mst.data(), coord_slv.data(),
                 coord_mst.data(), coord_slv.data(), coord_mst.data(), per_point.data(), per_point.data(),
                 field.data(), field.data(), 80, 80, 80);
  stderr = saved;
  std::fflush(capture);
  const long written = std::ftell(capture);
  std::string text(count(written), '\0');
  std::rewind(capture);
  if (written > 0 && std::fread(&text[0], 1, text.size(), capture) != text.size()) fail("cannot read capture");
  return text;
}

namespace {

mortar::Parameters paper_set(int which) {
  switch (which % 4) {
    case 0: return mortar::testing::almeida_m15();
    case 1: return mortar::testing::almeida_m34();
    case 2: return mortar::testing::van_der_pluijm(-0.5);
    default: return mortar::testing::atkinson();
  }
}

double unit(Reader& r) { return r.u16() / 65535.0; }
double log_range(Reader& r, double lo, double hi) { return lo * std::pow(hi / lo, unit(r)); }
double lin_range(Reader& r, double lo, double hi) { return lo + (hi - lo) * unit(r); }

// A random valid set over wide ranges (beyond Table 1), from 2 bytes each.
std::vector<double> random_valid_set(Reader& r) {
  const double kn = log_range(r, 1e-2, 1e7);
  const double ks = kn * log_range(r, 1e-2, 2);
  const double ft0 = log_range(r, 1e-3, 1e2);
  const double phi0 = lin_range(r, 0.5, 89.5);
  const double phir = phi0 * lin_range(r, 0.01, 1);
  const double c0 = ft0 * std::tan(phi0 * 3.14159265358979323846 / 180) * lin_range(r, 1.000001, 10);
  const double GIC = log_range(r, 1e-6, 1);
  const double GIIC = log_range(r, 1e-6, 10);
  const double m = (r.u8() & 3) == 0 ? 0.0 : log_range(r, 1, 1e5);
  const double psi0 = lin_range(r, 0, 89);
  const double psir = psi0 * lin_range(r, 0, 1);
  const double n = (r.u8() & 3) == 0 ? 0.0 : log_range(r, 1, 1e5);
  const double bn = lin_range(r, 0, 50), bs = lin_range(r, 0, 20);
  return {kn, ks, ft0, c0, GIC, GIIC, phi0, phir, m, psi0, psir, n, bn, bs};
}

}  // namespace

void decode_props(Reader& r, Block& b) {
  const int mode = r.u8() % 4;
  std::vector<double> p(count(b.n_props), 0.0);
  if (mode == 2) {
    for (double& x : p) x = r.f64();
  } else {
    std::vector<double> base(14);
    if (mode == 1) {
      base = random_valid_set(r);
    } else {
      const mortar::Parameters set = paper_set(r.u8());
      for (int i = 0; i < 14; ++i) base[i] = mortar::parameter_at(set, i);
      if (mode == 3)
        for (double& x : base) x *= std::pow(10.0, int8_t(r.u8()) / 16.0);
    }
    for (size_t i = 0; i < p.size(); ++i) p[i] = i < 14 ? base[i] : mj_fuzz::control_value(int(i), r.u8(), r);
  }
  const int overrides = r.u8() % 4;
  for (int o = 0; o < overrides; ++o) {
    const uint8_t index = r.u8();
    const double value = r.f64();
    if (!p.empty()) p[index % p.size()] = value;
  }
  // The substep budget, props(18), lowered to kFuzzMaxSubsteps where the
  // input leaves it at the default (0: 10^5) or sets a larger valid one
  // (fuzz_input.hpp, "props").
  if (p.size() > 17) {
    double& budget = p[17];
    if (budget == 0 || (budget == std::floor(budget) && budget > kFuzzMaxSubsteps && budget <= 1e9))
      budget = kFuzzMaxSubsteps;
  }
  for (size_t i = 0; i < p.size(); ++i) b.props[i] = Real(p[i]);
}

}  // namespace mj_fuzz
